// E0419: the interface of a native POU (a POU without statements in a linked library, whose body
// the host writes in C++) is what the native ABI can pass: a native function takes elementary
// inputs, STRING/WSTRING, ANY and VAR_IN_OUT ARRAY[*] of those and returns an elementary value or
// nothing; a native block's variables are elementary or VAR_IN_OUT (docs/runtime.md). Every
// native function is checked, called or not, so a library's author learns that the C++ side
// cannot be written; a native block when the program calls it.

#include "native_interfaces.hpp"

#include "pou_checks.hpp"

#include <fmt/format.h>
#include <unordered_set>

namespace eposp::compiler::checks {
namespace {

bool is_elementary_value(const sema::Type& type) {
    return type.kind == sema::TypeKind::Elementary || type.kind == sema::TypeKind::Enum;
}

constexpr std::string_view kSupported =
    "a native function takes VAR_INPUTs of elementary types, STRING, WSTRING or ANY, and "
    "VAR_IN_OUTs of ARRAY[*] OF an elementary type or a string";

void check_function(types::TypedProgram& program, const ast::Pou& pou, Diagnostics& diagnostics) {
    const sema::Type* frame = program.types().frame(pou);
    if (frame == nullptr) {
        return;
    }
    for (const sema::Field& field : frame->fields) {
        if (field.declaration == nullptr) { // the result
            if (!is_native_result(*field.type) && pou.return_type) {
                diagnostics.error(DiagnosticCode::E0419, pou.return_type->range,
                                  fmt::format("the native function '{}' returns a {}: a native "
                                              "function returns an elementary value or nothing",
                                              pou.name.name, field.type->name));
            }
        } else if (!native_parameter_kind(field)) {
            const bool in_out = field.section == ast::VarSectionKind::InOut;
            diagnostics.error(DiagnosticCode::E0419, field.declaration->range,
                              fmt::format("'{}' of the native function '{}' is {}{}: {}",
                                          field.name, pou.name.name,
                                          field.section == ast::VarSectionKind::Input || in_out
                                              ? (in_out ? "a VAR_IN_OUT of " : "a ")
                                              : "not a VAR_INPUT: ",
                                          in_out && field.type->element != nullptr
                                              ? field.type->element->name
                                              : field.type->name,
                                          kSupported));
        }
    }
}

void check_block(types::TypedProgram& program, const ast::Pou& pou, Diagnostics& diagnostics) {
    const sema::Type* instance = program.types().instance(pou);
    if (instance == nullptr) {
        return;
    }
    for (const sema::Field& field : instance->fields) {
        if (field.declaration != nullptr && !is_native_block_variable(field)) {
            diagnostics.error(DiagnosticCode::E0419, field.declaration->range,
                              fmt::format("'{}' of the native block '{}' is a {}: a native "
                                          "block's variables are elementary or VAR_IN_OUT",
                                          field.name, pou.name.name, field.type->name));
        }
    }
}

} // namespace

std::optional<NativeParameterKind> native_parameter_kind(const sema::Field& field) {
    const sema::Type& type = *field.type;
    if (field.section == ast::VarSectionKind::Input) {
        if (is_elementary_value(type)) {
            return NativeParameterKind::Value;
        }
        if (type.kind == sema::TypeKind::String) {
            return NativeParameterKind::String;
        }
        if (type.generic) {
            return NativeParameterKind::Any;
        }
    } else if (field.section == ast::VarSectionKind::InOut && type.conformant &&
               type.element->dimensions.size() == 1 &&
               is_native_any_value(*type.element->element)) {
        return NativeParameterKind::Array;
    }
    return std::nullopt;
}

bool is_native_any_value(const sema::Type& type) {
    return is_elementary_value(type) || type.kind == sema::TypeKind::String;
}

bool is_native_result(const sema::Type& type) {
    return sema::is_scalar(type) && type.kind != sema::TypeKind::Reference;
}

bool is_native_block_variable(const sema::Field& field) {
    return field.section == ast::VarSectionKind::InOut || sema::is_scalar(*field.type);
}

void check_native_interfaces(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> linked) {
    for (const ast::CompilationUnit& unit : linked) {
        for (const ast::Pou& pou : unit.pous) {
            if (pou.kind == ast::PouKind::Function && check.calls.is_native(pou)) {
                check_function(check.program, pou, check.diagnostics);
            }
        }
    }
    std::unordered_set<const ast::Pou*> blocks;
    for (const ast::Pou* caller : check.calls.pous()) {
        for (const ast::Pou* callee : check.calls.callees(*caller)) {
            if (callee->kind == ast::PouKind::FunctionBlock && check.calls.is_native(*callee) &&
                blocks.insert(callee).second) {
                check_block(check.program, *callee, check.diagnostics);
            }
        }
    }
}

} // namespace eposp::compiler::checks
