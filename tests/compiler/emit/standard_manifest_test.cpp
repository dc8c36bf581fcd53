// The standard-library manifest (vm/stdlib/manifest.hpp) against what implements it: every
// function row is typed by the typing stage, emitted by code generation (a native row as a
// CallNative of its binding) and bound in the VM's standard library with the same signature;
// every FB row is ST of the built-in library with the row's interface, and the built-in library
// has no FB without a row; every runtime helper is called and bound by its binding.

#include "codegen_harness.hpp"
#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "stdlib/standard_library_source.hpp"
#include "typing_helpers.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

using vm::stdlib::Family;
using vm::stdlib::StandardFunction;

const char* const kDeclarations =
    "r : REAL; d : DINT; i : INT; w : WORD; x : BOOL; s : STRING; arr : ARRAY[1..3] OF INT; "
    "p : POINTER TO DINT; t : TIME; tod1 : TOD; dt1 : DT; date1 : DATE; ltime1 : LTIME; "
    "ltod1 : LTOD; ldt1 : LDT; ldate1 : LDATE;";

/// A variable of the manifest's time type.
std::string time_variable(vm::NativeType type) {
    switch (type) {
    case vm::NativeType::TimeOfDay:
        return "tod1";
    case vm::NativeType::DateAndTime:
        return "dt1";
    case vm::NativeType::Date:
        return "date1";
    case vm::NativeType::Ltime:
        return "ltime1";
    case vm::NativeType::Ltod:
        return "ltod1";
    case vm::NativeType::Ldt:
        return "ldt1";
    case vm::NativeType::Ldate:
        return "ldate1";
    default:
        return "t";
    }
}

/// `target := call` for the row, with inputs its family takes: REAL, DINT, WORD, STRING.
std::string assignment(const StandardFunction& f) {
    const std::string name(f.name);
    switch (f.family) {
    case Family::Real:
    case Family::Power:
        return "r := " + name + (f.max_inputs == 2 ? "(r, r)" : "(r)");
    case Family::Absolute:
    case Family::Move:
    case Family::Size:
        return "d := " + name + "(d)";
    case Family::Truncate:
        return "d := " + name + "(r)";
    case Family::Arithmetic:
    case Family::Extreme:
        return "d := " + name + "(d, d)";
    case Family::Logic:
        return "w := " + name + (f.min_inputs == 1 ? "(w)" : "(w, w)");
    case Family::Comparison:
        return "x := " + name + "(d, d)";
    case Family::Shift:
        return "w := " + name + "(w, 1)";
    case Family::Select:
        return "d := " + name + "(x, d, 1)";
    case Family::Limit:
    case Family::Multiplex:
        return "d := " + name + "(1, d, 2)";
    case Family::Bound:
        return "d := " + name + "(arr, 1)";
    case Family::Address:
        return "p := " + name + "(d)";
    case Family::Text: {
        std::string call = name + "(s";
        const std::size_t texts = f.max_inputs == vm::stdlib::kExtensible ? 2 : f.texts;
        for (std::size_t i = 1; i < std::max<std::size_t>(f.min_inputs, texts); ++i) {
            call += i < texts ? ", s" : ", 1";
        }
        const bool count = f.text_result == vm::stdlib::TextResult::Count;
        return (count ? "i := " : "s := ") + call + ")";
    }
    case Family::Time:
        return time_variable(f.time.result) + " := " + name + "(" + time_variable(f.time.first) +
               ", " + (f.time.scaled ? "2" : time_variable(f.time.second)) + ")";
    }
    return "";
}

TEST(StandardManifest, EveryFunctionIsTypedEmittedAndBound) {
    vm::NativeRegistry registry;
    vm::stdlib::register_standard_library(registry);
    for (const StandardFunction& f : vm::stdlib::standard_functions()) {
        SCOPED_TRACE(std::string(f.name));
        const std::string body = assignment(f) + ";";
        const auto typed = type_body(kDeclarations, body);
        ASSERT_TRUE(typed->front_end->program) << typed->errors();
        EXPECT_EQ(typed->errors(), "");
        const types::CallTarget* target = typed->program().call_target(typed->value(0));
        // TRUNC is typed as the conversion it is, `NOT(w)` parsed as the operator.
        if (f.family != Family::Truncate && f.operation != vm::stdlib::Operation::Not) {
            ASSERT_NE(target, nullptr);
            EXPECT_EQ(target->name, f.name);
        }
        const StProgram program("PROGRAM Main\nVAR " + std::string(kDeclarations) + " END_VAR\n" +
                                body + "\nEND_PROGRAM\n");
        ASSERT_TRUE(program.ok()) << program.errors();
        if (vm::stdlib::implementation(f) != vm::stdlib::Implementation::Native) {
            continue;
        }
        const auto native = vm::stdlib::native_binding(f);
        const auto& imports = program.image().imports;
        EXPECT_TRUE(std::any_of(imports.begin(), imports.end(), [&](const vm::NativeImport& i) {
            return i.name == native.name && i.signature == native.signature;
        })) << native.name;
    }
    // Every variant of every native row, as the VM's standard library registers it.
    for (const vm::stdlib::NativeBinding& native : vm::stdlib::standard_function_natives()) {
        const vm::NativeRegistry::Entry* entry = registry.find(native.name);
        ASSERT_NE(entry, nullptr) << native.name;
        EXPECT_EQ(entry->signature, native.signature) << native.name;
    }
}

/// The runtime helpers and the CHAR and WCHAR conversions: natives for what is no call of a
/// standard function row.
std::vector<vm::stdlib::NativeBinding> helpers_and_character_conversions() {
    using vm::stdlib::CharWidth;
    std::vector<vm::stdlib::NativeBinding> natives = vm::stdlib::helper_natives();
    for (const auto& [character, width] : {std::pair{vm::NativeType::Char, CharWidth::Narrow},
                                           std::pair{vm::NativeType::Wchar, CharWidth::Wide}}) {
        natives.push_back(vm::stdlib::to_text_binding(character, width));
        natives.push_back(vm::stdlib::from_text_binding(character, width));
    }
    return natives;
}

TEST(StandardManifest, EveryHelperIsCalledAndBoundByItsBinding) {
    vm::NativeRegistry registry;
    vm::stdlib::register_standard_library(registry);
    vm::stdlib::register_clock(registry, [] { return std::int64_t{0}; });
    const auto natives = helpers_and_character_conversions();
    for (const vm::stdlib::NativeBinding& native : natives) {
        const vm::NativeRegistry::Entry* entry = registry.find(native.name);
        ASSERT_NE(entry, nullptr) << native.name;
        EXPECT_EQ(entry->signature, native.signature) << native.name;
    }
    std::string body;
    for (const std::string text : {"s", "w"}) {
        body += text + "10 := " + text + "; "; // an assignment between capacities
        for (const char* op : {"=", "<>", "<", "<=", ">", ">="}) {
            body += "x := " + text + " " + op + " " + text + "10; ";
        }
    }
    const StProgram program(
        "PROGRAM Main\nVAR s : STRING; s10 : STRING[10]; w : WSTRING; w10 : WSTRING[10]; c : CHAR; "
        "wc : WCHAR; "
        "x : BOOL; timer : TON; END_VAR\n" +
        body +
        "s := CHAR_TO_STRING(c); c := STRING_TO_CHAR(s); w := WCHAR_TO_WSTRING(wc); "
        "wc := WSTRING_TO_WCHAR(w); timer(IN := x, PT := T#1s);\nEND_PROGRAM\n");
    ASSERT_TRUE(program.ok()) << program.errors();
    const auto& imports = program.image().imports;
    for (const vm::stdlib::NativeBinding& native : natives) {
        EXPECT_TRUE(std::any_of(imports.begin(), imports.end(), [&](const vm::NativeImport& i) {
            return i.name == native.name && i.signature == native.signature;
        })) << native.name;
    }
}

std::string parameter(bool output, const std::string& name, ast::ElementaryType type) {
    return (output ? "out " : "in ") + name + " : " + std::string(ast::name_of(type));
}

/// The FUNCTION_BLOCKs of the built-in library, by name, with their inputs and outputs.
std::map<std::string, std::vector<std::string>> library_blocks() {
    SourceManager sources;
    Diagnostics diagnostics;
    const FileId file =
        sources.add("standard_library.st", std::string(stdlib::standard_library_source()));
    const ast::CompilationUnit unit = parse(sources, file, diagnostics);
    std::map<std::string, std::vector<std::string>> blocks;
    for (const ast::Pou& pou : unit.pous) {
        if (pou.kind != ast::PouKind::FunctionBlock) {
            continue;
        }
        auto& parameters = blocks[pou.name.name];
        for (const ast::DeclarationSection& declared : pou.sections) {
            const auto* section_of = std::get_if<ast::VarSection>(&declared);
            if (section_of == nullptr) {
                continue;
            }
            const ast::VarSection& section = *section_of;
            const bool output = section.kind == ast::VarSectionKind::Output;
            if (!output && section.kind != ast::VarSectionKind::Input) {
                continue;
            }
            for (const ast::VariableDeclaration& declaration : section.variables) {
                const auto* type = std::get_if<ast::ElementaryTypeRef>(&declaration.type.node);
                for (const ast::Identifier& name : declaration.names) {
                    parameters.push_back(parameter(output, name.name, type->type));
                }
            }
        }
    }
    return blocks;
}

TEST(StandardManifest, EveryFunctionBlockIsTheStOfItsRowAndNoOther) {
    std::map<std::string, std::vector<std::string>> rows;
    for (const vm::stdlib::StandardBlockVariant& variant : vm::stdlib::standard_block_variants()) {
        auto& parameters = rows[variant.name];
        for (const vm::stdlib::StandardParameter& p : variant.block->parameters) {
            if (!p.name.empty()) {
                const auto type = ast::elementary_type_from_name(variant.type_of(p));
                parameters.push_back(parameter(p.output, std::string(p.name), *type));
            }
        }
    }
    EXPECT_EQ(library_blocks(), rows);
}

} // namespace
} // namespace eposp::compiler::test
