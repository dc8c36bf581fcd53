// The hand-written parser (compiler/src/parse/descent_*.cpp) against its oracle, the generated
// parser's tree turned into the AST by AstBuilder, as parsing was before: the same AST (every
// node, with the source range of each expression, statement, declaration and type) and the same
// diagnostics in the same order wherever the generated parser accepts the input, and where it
// does not, the hand-written parser gives up and the same syntax errors are reported. On every ST
// file of the repository and of the benchmarks, their truncations and mutations, generated
// programs and a large generated file, and a case for every rule and alternative of the grammar.
#include "eposp/compiler/ast/ast_printer.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/differential/program_tree.hpp"
#include "eposp/differential/st_generator.hpp"
#include "parse/ast_builder.hpp"
#include "parse/input_stream.hpp"
#include "parse/lexer.hpp"
#include "parse/parse_tokens.hpp"
#include "st_corpus.hpp"

#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>
#include <variant>

namespace eposp::compiler {
namespace {

std::string where(const SourceRange& range) {
    std::ostringstream text;
    text << range.begin.line << ':' << range.begin.column << '-' << range.end.line << ':'
         << range.end.column;
    return text.str();
}

// The source ranges the S-expression dump leaves out, a line each, in the order of the tree.
class RangeDump {
public:
    std::string unit(const ast::CompilationUnit& unit) {
        for (const auto& type : unit.types) {
            line("type", type.range);
            name(type.name);
            type_spec(type.type);
            initializer(type.initial_value.get());
        }
        for (const auto& pou : unit.pous) {
            line("pou", pou.range);
            name(pou.name);
            if (pou.return_type) {
                type_spec(*pou.return_type);
            }
            if (pou.extends) {
                name(*pou.extends);
            }
            for (const auto& base : pou.implements) {
                name(base);
            }
            sections(pou.sections);
            statements(pou.body);
        }
        for (const auto& configuration : unit.configurations) {
            line("configuration", configuration.range);
            name(configuration.name);
            sections(configuration.sections);
            for (const auto& resource : configuration.resources) {
                line("resource", resource.range);
                name(resource.name);
                if (resource.processor) {
                    name(*resource.processor);
                }
                sections(resource.sections);
                for (const auto& task : resource.tasks) {
                    line("task", task.range);
                    name(task.name);
                    for (const auto& attribute : task.attributes) {
                        line("attribute " + attribute.name, attribute.range);
                    }
                }
                for (const auto& program : resource.programs) {
                    line("program", program.range);
                    name(program.name);
                    name(program.type);
                    if (program.task) {
                        name(*program.task);
                    }
                }
            }
        }
        sections(unit.global_variable_lists);
        return out_.str();
    }

private:
    void line(const std::string& what, const SourceRange& range) {
        out_ << what << ' ' << where(range) << '\n';
    }
    void name(const ast::Identifier& id) { line("name " + id.name, id.range); }

    void sections(const std::vector<ast::DeclarationSection>& all) {
        for (const auto& section : all) {
            if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
                line("access section", access->range);
                for (const auto& path : access->paths) {
                    line("access", path.range);
                    name(path.name);
                    type_spec(path.type);
                    if (const auto* parts = std::get_if<std::vector<ast::Identifier>>(&path.path)) {
                        for (const auto& part : *parts) {
                            name(part);
                        }
                    }
                }
                continue;
            }
            const auto& variables = std::get<ast::VarSection>(section);
            line("section", variables.range);
            for (const auto& variable : variables.variables) {
                declaration(variable);
            }
        }
    }
    void declaration(const ast::VariableDeclaration& variable) {
        line("variable", variable.range);
        for (const auto& id : variable.names) {
            name(id);
        }
        if (variable.address) {
            line("address", variable.address->range);
        }
        type_spec(variable.type);
        initializer(variable.initial_value.get());
    }
    void initializer(const ast::Initializer* value) {
        if (value == nullptr) {
            return;
        }
        line("initializer", value->range);
        if (const auto* elements = std::get_if<std::vector<ast::ArrayInitElement>>(&value->value)) {
            for (const auto& element : *elements) {
                initializer(element.value.get());
            }
        } else if (const auto* members =
                       std::get_if<std::vector<ast::StructInitElement>>(&value->value)) {
            for (const auto& member : *members) {
                name(member.member);
                initializer(member.value.get());
            }
        }
    }
    void type_spec(const ast::TypeSpec& type) {
        line("type spec", type.range);
        if (const auto* structure = std::get_if<ast::StructType>(&type.node)) {
            for (const auto& member : structure->members) {
                declaration(member);
            }
        } else if (const auto* array = std::get_if<ast::ArrayType>(&type.node)) {
            type_spec(*array->element);
        } else if (const auto* reference = std::get_if<ast::ReferenceType>(&type.node)) {
            type_spec(*reference->target);
        } else if (const auto* enumeration = std::get_if<ast::EnumType>(&type.node)) {
            if (enumeration->base) {
                type_spec(*enumeration->base);
            }
            for (const auto& value : enumeration->values) {
                name(value.name);
            }
        } else if (const auto* subrange = std::get_if<ast::SubrangeType>(&type.node)) {
            type_spec(*subrange->base);
        }
    }
    void statements(const ast::StatementList& list) {
        for (const auto& statement : list) {
            line("statement", statement.range);
            std::visit(
                [&](const auto& node) {
                    using Node = std::decay_t<decltype(node)>;
                    if constexpr (std::is_same_v<Node, ast::IfStatement>) {
                        for (const auto& branch : node.branches) {
                            statements(branch.body);
                        }
                        statements(node.else_body);
                    } else if constexpr (std::is_same_v<Node, ast::CaseStatement>) {
                        for (const auto& branch : node.branches) {
                            for (const auto& label : branch.labels) {
                                line("label", label.range);
                            }
                            statements(branch.body);
                        }
                        statements(node.else_body);
                    } else if constexpr (std::is_same_v<Node, ast::ForStatement>) {
                        name(node.control_variable);
                        statements(node.body);
                    } else if constexpr (std::is_same_v<Node, ast::WhileStatement> ||
                                         std::is_same_v<Node, ast::RepeatStatement>) {
                        statements(node.body);
                    }
                },
                statement.node);
        }
    }

    std::ostringstream out_;
};

// The AST (each expression with its range) and every diagnostic of `text` parsed by `parse`.
template <typename Parse>
std::string parsed_with(const std::string& text, Parse parse) {
    SourceManager sources;
    const FileId file = sources.add("input.st", text);
    Diagnostics diagnostics;
    InputStream input(text);
    Lexer lexer(input);
    const ast::CompilationUnit unit = parse(lexer, file, diagnostics);
    const ast::DumpLayout ranges{
        [](const ast::Expression& expression) { return where(expression.range); }};
    return ast::to_sexpr(unit, ranges) + "\n" + RangeDump().unit(unit) + "\n" +
           render(diagnostics, sources);
}

// Whether the oracle accepts `text` or not, the parser must agree with it exactly.
void expect_same(const std::string& bytes, const std::string& name) {
    if (::testing::Test::HasFailure()) {
        return; // the first difference of a test says enough
    }
    SCOPED_TRACE(name);
    const std::string text = corpus::as_text(bytes);
    const std::string expected = parsed_with(text, parse_tokens_with_tree);
    const std::string actual = parsed_with(text, parse_tokens);
    ASSERT_EQ(expected, actual) << "input: " << text;
    ASSERT_EQ(actual.find("[E0001]"), std::string::npos) << "input: " << text;
}

TEST(ParserEquivalence, EveryStFileOfTheRepositoryAndTheBenchmarks) {
    const auto files = corpus::st_files();
    ASSERT_GE(files.size(), 60U);
    for (const auto& file : files) {
        expect_same(corpus::read_file(file), file.string());
    }
}

TEST(ParserEquivalence, TruncatedAndMutatedFiles) {
    // Mutations of the tokens that decide between alternatives, as well as characters.
    constexpr std::string_view kPieces = "();:=,.[]^#-+*<>&0123456789 \nabxNOTANDORMOD";
    std::mt19937 random(1717);
    for (const auto& file : corpus::st_files()) {
        corpus::for_each_variant(corpus::read_file(file), file.string(), random, kPieces,
                                 expect_same);
    }
}

TEST(ParserEquivalence, GeneratedPrograms) {
    std::mt19937_64 random(61131);
    for (int i = 0; i < 200; ++i) {
        const std::string source = differential::render(differential::generate_program(random).block);
        expect_same(source, "generated program " + std::to_string(i));
    }
}

// Every rule and alternative of the grammar, the ambiguities it resolves by taking the first
// alternative, and forms close to them that it refuses.
TEST(ParserEquivalence, EveryRuleAndAlternative) {
    const std::string statements[] = {
        // precedence and associativity of every operator, prefix and postfix
        "x := a OR b XOR c AND d & e = f <> g < h > i <= j >= k + l - m * n / o MOD p ** q;",
        "x := a ** b ** c; x := a - b - c; x := a / b / c; x := -2 ** 2; x := NOT a = b;",
        "x := - - a; x := NOT NOT a; x := +a; x := -a.b[1]^(2); x := a ** -b; x := -5; x := -1.5;",
        "x := -(5); x := - 9223372036854775808; x := -INT#5; x := -REAL#1.5; x := -16#FF;",
        "x := (a + b) * c; x := ((a)); x := (a)(1); x := a(1)(2); x := a^^; x := a[1][2, 3];",
        "x := a.b.c; x := a.1; x := a.64; x := a.b.3; x := a.1_0; x := a[1].b^.c(d := 1);",
        // every literal form
        "x := 0; x := 1_000; x := 16#FF; x := 2#1010; x := 8#777; x := 1.5; x := 1.5E10;",
        "x := 1e5; x := 1.5e-3; x := INT#16#FF; x := INT#-5; x := REAL#1e3; x := BOOL#TRUE;",
        "x := STRING#'x'; x := WSTRING#\"x\"; x := Color#Red; x := T#5s; x := LTIME#5us;",
        "x := D#2020-01-01; x := TOD#12:00:00.5; x := DT#2020-01-01-12:00:00; x := TRUE;",
        "x := FALSE; x := NULL; x := 'a$'b'; x := \"w\"; x := 99999999999999999999999;",
        "x := 16#G; x := T#1x; x := D#2020-13-01; x := %IX1.2; x := %QW7; x := %MD3.4.5;",
        "x := %I*; %QX0.1 := TRUE; x := %IX99999999999.0;",
        // calls: formal, informal, output, negated output, operators as functions, REF
        "f(); f(1, 2); f(a := 1, b => c, NOT d => e); x := f(a := 1)(2); fb.q(1);",
        "x := MOD(7, 3); x := AND(a, b); x := OR(a); x := XOR(); x := REF(a); x := REF(a.b[1]);",
        "x := NOT(IN := a); x := NOT(IN := a, ENO => e); x := NOT(EN := c, IN := a, NOT ENO => e);",
        "x := f(a := b := 1);", "f(a => );", "x := AND a;", "x := REF a;",
        // statements that do nothing, assignments to what is not a variable
        "x = 1;", "x=1;", "x  =  1;", "a + b;", "1 := 2;", "f() := 1;", "-x := 1;", ";", ";;",
        // control statements, with and without the ';' after END_
        "IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ; ELSE x := 3; END_IF",
        "IF a THEN END_IF; IF a THEN ELSE END_IF;;", "IF a THEN x := 1; END_IF x := 2;",
        "CASE x OF 1: a := 1; 2, 3: b := 2; 4..5, 6: ; ELSE c := 3; END_CASE",
        "CASE x OF 1..2: END_CASE; CASE x OF END_CASE; CASE x OF ELSE END_CASE",
        "CASE x OF a.b: f(1); c: d := e; -1: ; Color#Red, INT#2..INT#3: x; END_CASE",
        "CASE x OF 1: a := 1; b; (c): d; f(1): ; END_CASE",
        "CASE x OF 1: a := 1 2: b := 2; END_CASE",
        "CASE x OF 99999999999999999999999..1E5: ; 1E5..99999999999999999999999: ; END_CASE",
        "CASE x OF ON..ON: ; END_CASE", "CASE x OF 1E5..ON: ; END_CASE",
        "FOR i := 1 TO 10 DO x := i; END_FOR FOR i := 1 TO 10 BY -1 DO END_FOR;",
        "WHILE a DO x := 1; EXIT; CONTINUE; END_WHILE REPEAT x := 1; UNTIL b END_REPEAT;",
        "RETURN; EXIT; CONTINUE;", "RETURN", "IF a THEN", "FOR i = 1 TO 2 DO END_FOR",
        "ON := ON; x := ON; ON();",
    };
    for (const std::string& body : statements) {
        expect_same("PROGRAM p\n" + body + "\nEND_PROGRAM\n", body);
    }
    const std::string declarations[] = {
        "VAR a : INT; b, c : REAL := 1.5; d AT %IX1.0 : BOOL; e, f AT %QX1.0 : BOOL; END_VAR",
        "VAR CONSTANT RETAIN a : INT := 1; END_VAR VAR RETAIN CONSTANT END_VAR",
        "VAR PERSISTENT CONSTANT a : INT; END_VAR VAR CONSTANT NON_RETAIN RETAIN END_VAR",
        "VAR_INPUT a : INT; END_VAR VAR_OUTPUT b : INT; END_VAR VAR_IN_OUT c : INT; END_VAR",
        "VAR_TEMP a : INT; END_VAR VAR_EXTERNAL b : INT; END_VAR VAR_GLOBAL c : INT; END_VAR",
        "VAR_ACCESS a : x.y.z : INT READ_WRITE; b : %IX1.0 : BOOL READ_ONLY; c : q : INT; END_VAR",
        "VAR_ACCESS a : %IX99999999999 : BOOL; END_VAR",
        "VAR a : ARRAY[1..2, 3..4] OF INT := [1, 2, 3(4)]; b : ARRAY[*] OF INT; END_VAR",
        "VAR a : ARRAY[1..3] OF INT := 1, 2, 3; b : ARRAY[1..3] OF INT := 3(0), 1; END_VAR",
        "VAR a : ARRAY[1..3] OF INT := [3(0)]; b : ARRAY[1..3] OF INT := [3()]; END_VAR",
        "VAR a : ARRAY[1..3] OF INT := [3(0) + 1]; b : ARRAY[1..3] OF INT := [3(1, 2)]; END_VAR",
        "VAR a : ARRAY[1..3] OF INT := [3(x := 1)]; b : ARRAY[1..3] OF S := [2((a := 1))]; END_VAR",
        "VAR a : INT := 3(0); b : ARRAY[1..2] OF INT := [3(0).x, 3(0)[1], 3(0)^]; END_VAR",
        "VAR a : S := (a := 1, b := (c := 2), d := [1, 2]); b : INT := (1); END_VAR",
        "VAR a : S := (a := 1, b); END_VAR",
        "VAR a : STRUCT x : INT; y : REAL; END_STRUCT; b : REF_TO INT; c : POINTER TO INT; END_VAR",
        "VAR a : (red, green := 2, blue); b : (x, y) UDINT; c : UDINT (x, y := 1); END_VAR",
        "VAR a : DWORD (red); b : INT (1..10); c : STRING[10]; d : WSTRING(20); e : INT[3]; END_VAR",
        "VAR a : STRING(n + 1); b : INT(a..b); c : INT(-1..1) := 0; d : X(ON); END_VAR",
        "VAR a : REF_TO ARRAY[1..2] OF REF_TO STRING[5]; END_VAR VAR END_VAR",
        "VAR ON : INT := 1E5; END_VAR", "VAR a, ON AT %IX1.0 : INT; END_VAR",
        "VAR a : (x) ON; END_VAR", "VAR a : STRUCT END_STRUCT; END_VAR", "VAR a INT; END_VAR",
    };
    for (const std::string& sections : declarations) {
        expect_same("FUNCTION_BLOCK fb\n" + sections + "\nEND_FUNCTION_BLOCK\n", sections);
    }
    const std::string files[] = {
        "TYPE a : INT; b : (x, y) c : STRUCT m : INT; END_STRUCT END_TYPE",
        "TYPE e : (x, y) f : INT; END_TYPE TYPE e : (x, y) f; END_TYPE",
        "TYPE e : (x, y) f := x; g : ARRAY[1..2] OF INT := 1, 2 h : INT := 3 END_TYPE",
        "TYPE r : INT (0..100) := 5; s : STRING[10] := 'x'; END_TYPE TYPE END_TYPE",
        "TYPE e : (ON := 1E5) ON; END_TYPE", "TYPE e : UDINT (a, b) := a; END_TYPE",
        "FUNCTION f : INT VAR_INPUT a : INT; END_VAR f := a; END_FUNCTION",
        // a result type's optional end, or the body's first statement
        "FUNCTION f : (a, b) x; END_FUNCTION", "FUNCTION f : (a, b) x := 1; END_FUNCTION",
        "FUNCTION f : (a, b) x.y := 1; END_FUNCTION", "FUNCTION f : (a, b) x * 2; END_FUNCTION",
        "FUNCTION f : (a, b) x + 2; END_FUNCTION", "FUNCTION f : (a, b) UDINT END_FUNCTION",
        "FUNCTION f : (a, b) x(a := 1); END_FUNCTION", "FUNCTION f : (a, b) x(1); END_FUNCTION",
        "FUNCTION f : (a, b) x AND b; END_FUNCTION", "FUNCTION f : (a, b) x AND (b); END_FUNCTION",
        "FUNCTION f : (a, b) x MOD 2; END_FUNCTION", "FUNCTION f : (a, b) x => 2; END_FUNCTION",
        "FUNCTION f : ARRAY[1..2] OF (a, b) x := 1; END_FUNCTION",
        "FUNCTION f : INT (x) := 1; END_FUNCTION", "FUNCTION f : INT (x); END_FUNCTION",
        "FUNCTION f : STRING (x) := 1E5; END_FUNCTION", "FUNCTION f : STRING[1] (x); END_FUNCTION",
        "FUNCTION ON : (ON := 1E5) ON := 1; END_FUNCTION",
        "FUNCTION f END_FUNCTION FUNCTION_BLOCK g END_FUNCTION_BLOCK PROGRAM h END_PROGRAM",
        "FUNCTION_BLOCK a EXTENDS b IMPLEMENTS c, d VAR x : INT; END_VAR x := 1; END_FUNCTION_BLOCK",
        "FUNCTION_BLOCK a IMPLEMENTS c END_FUNCTION_BLOCK FUNCTION_BLOCK a EXTENDS b END_FUNCTION_BLOCK",
        "VAR_GLOBAL g : INT; END_VAR VAR_GLOBAL CONSTANT k : INT := 1; END_VAR",
        "VAR x : INT; END_VAR", "VAR_ACCESS a : b : INT; END_VAR", "VAR_INPUT a : INT; END_VAR",
        "CONFIGURATION c VAR_GLOBAL g : INT; END_VAR RESOURCE r ON cpu "
        "VAR_GLOBAL h : INT; END_VAR {attribute 'event' := 'x'} TASK t (INTERVAL := T#10ms, "
        "PRIORITY := 1); TASK u (SINGLE := g, PRIORITY := 2); "
        "PROGRAM RETAIN i WITH t : p (a := g, b => h); PROGRAM j : q; END_RESOURCE "
        "RESOURCE r2 ON cpu2 END_RESOURCE END_CONFIGURATION",
        "CONFIGURATION c TASK t (PRIORITY := 1); PROGRAM NON_RETAIN i WITH t : p(); END_CONFIGURATION",
        "CONFIGURATION c END_CONFIGURATION CONFIGURATION d VAR_GLOBAL x : INT; END_VAR "
        "END_CONFIGURATION",
        "CONFIGURATION c TASK t (PRIORITY := 1, PRIORITY := 99999999999999999999999, "
        "COLOUR := 1E5, INTERVAL := ON); TASK u (INTERVAL := T#1s); PROGRAM i : p; "
        "END_CONFIGURATION",
        "CONFIGURATION c {attribute 'x'} {info 'y'} {attribute} {attribute 'a' := } "
        "TASK t (PRIORITY := 1); END_CONFIGURATION",
        "CONFIGURATION c RESOURCE ON ON ON END_RESOURCE END_CONFIGURATION",
        "CONFIGURATION c RESOURCE r ON ON END_RESOURCE END_CONFIGURATION",
        "CONFIGURATION c RESOURCE r END_RESOURCE END_CONFIGURATION",
        "CONFIGURATION c TASK t (); END_CONFIGURATION", "END_PROGRAM", "PROGRAM", "",
        "PROGRAM p END_PROGRAM garbage", "PROGRAM p x := 'open\nEND_PROGRAM",
        "PROGRAM p (* never closed", "PROGRAM p x := ((((1)))); END_PROGRAM",
    };
    for (const std::string& file : files) {
        expect_same(file, file);
    }
}

// Declarations and statements cut at every token: every place the parser may give up.
TEST(ParserEquivalence, EveryPrefixOfAFileOfManyForms) {
    const std::string text =
        "TYPE e : (x, y) UDINT; s : STRUCT a : ARRAY[1..2] OF INT := [2(1)]; END_STRUCT END_TYPE\n"
        "FUNCTION_BLOCK fb EXTENDS base VAR_INPUT i : INT := 1; END_VAR VAR_OUTPUT q : BOOL; "
        "END_VAR\n CASE i OF 1, 2..3: q := NOT q AND i.1; ELSE f(a := 1, b => q); END_CASE\n"
        "FOR i := 1 TO 3 BY 1 DO IF q THEN EXIT; ELSIF i > 2 THEN CONTINUE; END_IF END_FOR\n"
        "END_FUNCTION_BLOCK\nCONFIGURATION c TASK t (PRIORITY := 1); PROGRAM i WITH t : p; "
        "END_CONFIGURATION\n";
    for (std::size_t cut = 0; cut <= text.size(); ++cut) {
        expect_same(text.substr(0, cut), "cut at " + std::to_string(cut));
    }
}

} // namespace
} // namespace eposp::compiler
