// Declarations of IEC 61131-3 ed. 3: data types (6.4), variables (6.5), POUs (6.6) and
// configurations (6.8).
#include "eposp/compiler/ast/ast_printer.hpp"
#include "parse_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using test::parse_text;

std::string unit_sexpr(const std::string& text) {
    const test::Parsed parsed = parse_text(text);
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    return ast::to_sexpr(parsed.unit);
}

// The type of the only variable of the only POU.
std::string variable_type(const std::string& declaration) {
    const test::Parsed parsed =
        parse_text("FUNCTION_BLOCK F\nVAR\n" + declaration + "\nEND_VAR\nEND_FUNCTION_BLOCK\n");
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    if (parsed.unit.pous.empty()) {
        return "<none>";
    }
    const auto& section = std::get<ast::VarSection>(parsed.unit.pous.front().sections.front());
    return ast::to_sexpr(section.variables.front().type);
}

TEST(TypeDeclaration, NestedStructWithInitialValues) {
    EXPECT_EQ(unit_sexpr("TYPE\n  Point : STRUCT x, y : REAL := 1.5; END_STRUCT;\n"
                         "  Segment : STRUCT a : Point; b : Point := (x := 2.0); n : INT; "
                         "END_STRUCT;\nEND_TYPE\n"),
              "(type Point (struct (var x y REAL (real 1.5))))\n"
              "(type Segment (struct (var a Point) (var b Point ( x=(real 2) )) (var n INT)))\n");
}

TEST(TypeDeclaration, EnumerationsPlainTypedAndWithDefault) {
    EXPECT_EQ(unit_sexpr("TYPE Color : (Red, Green, Blue) := Green; Mask : DWORD (A := 16#1, B "
                         ":= 16#2); Single : INT (Only); END_TYPE"),
              "(type Color (enum Red Green Blue))\n(type Mask (enum DWORD A=(int 1) B=(int 2)))\n"
              "(type Single (enum INT Only))\n");
}

// A base type after the values is TwinCAT's spelling of `UDINT (a, b, c)`.
TEST(TypeDeclaration, EnumerationWithItsBaseTypeAfterTheValues) {
    EXPECT_EQ(unit_sexpr("TYPE E : (a, b, c) UDINT; F : (p := 1, q := 2) DINT := q;\n"
                         "  G : (u, v) H : INT; END_TYPE"),
              "(type E (enum UDINT a b c))\n(type F (enum DINT p=(int 1) q=(int 2)))\n"
              "(type G (enum u v))\n(type H INT)\n");
}

TEST(TypeDeclaration, SubrangeAliasReferencesAndStrings) {
    EXPECT_EQ(unit_sexpr("TYPE Percent : INT(0..100); Speed : LREAL; R : REF_TO INT; P : "
                         "POINTER TO Speed; Name : STRING[20]; WName : WSTRING(10); END_TYPE"),
              "(type Percent (subrange INT (int 0) (int 100)))\n(type Speed LREAL)\n"
              "(type R (ref_to INT))\n(type P (pointer_to Speed))\n"
              "(type Name (STRING (int 20)))\n(type WName (WSTRING (int 10)))\n");
}

TEST(TypeDeclaration, KeepsTheDefaultOfTheType) {
    const test::Parsed parsed = parse_text("TYPE Color : (Red, Green) := Green; END_TYPE");
    ASSERT_EQ(parsed.unit.types.size(), 1u);
    ASSERT_TRUE(parsed.unit.types.front().initial_value);
}

// CODESYS writes `END_STRUCT` and `END_TYPE` with nothing between them.
TEST(TypeDeclaration, SemicolonAfterADeclarationIsOptional) {
    EXPECT_EQ(unit_sexpr("TYPE Axis :\nSTRUCT\n  pos : LREAL;\nEND_STRUCT\nEND_TYPE\n"
                         "TYPE Color : (Red, Green) := Green Level : INT(0..5) END_TYPE\n"),
              "(type Axis (struct (var pos LREAL)))\n(type Color (enum Red Green))\n"
              "(type Level (subrange INT (int 0) (int 5)))\n");
}

TEST(TypeDeclaration, StructMembersStillEndWithASemicolon) {
    EXPECT_EQ(parse_text("TYPE Axis :\nSTRUCT\n  pos : LREAL\nEND_STRUCT\nEND_TYPE\n").rendered(),
              "test.st:4:1: error: expected ':=' or ';', found 'END_STRUCT' [E0101]\n"
              "END_STRUCT\n"
              "^~~~~~~~~~\n");
}

TEST(VariableType, MultiDimensionalArrayWithRepetitionInitializer) {
    const test::Parsed parsed = parse_text(
        "PROGRAM P\nVAR m : ARRAY[1..2, 0..2] OF INT := [1, 2, 3(0), 2()]; END_VAR\nEND_PROGRAM");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& declaration =
        std::get<ast::VarSection>(parsed.unit.pous.front().sections.front()).variables.front();
    EXPECT_EQ(ast::to_sexpr(declaration.type), "(array (int 1)..(int 2) (int 0)..(int 2) INT)");
    const auto& elements =
        std::get<std::vector<ast::ArrayInitElement>>(declaration.initial_value->value);
    ASSERT_EQ(elements.size(), 4u);
    EXPECT_FALSE(elements[0].repeat_count);
    EXPECT_TRUE(elements[2].repeat_count);
    EXPECT_TRUE(elements[2].value);
    EXPECT_FALSE(elements[3].value); // 2() keeps the defaults
}

TEST(VariableType, ArraysOfStructsAndFbInstancesAndVariableLength) {
    EXPECT_EQ(variable_type("a : ARRAY[0..9] OF Item;"), "(array (int 0)..(int 9) Item)");
    EXPECT_EQ(variable_type("t : ARRAY[1..4] OF TON;"), "(array (int 1)..(int 4) TON)");
    EXPECT_EQ(variable_type("v : ARRAY[*, *] OF REAL;"), "(array * * REAL)");
    EXPECT_EQ(variable_type("s : STRING;"), "(STRING)");
    EXPECT_EQ(variable_type("e : (Open, Closed);"), "(enum Open Closed)");
}

TEST(VariableType, LengthOnANonStringTypeIsAnError) {
    EXPECT_EQ(parse_text("PROGRAM P VAR x : INT[3]; END_VAR END_PROGRAM").first_message(),
              "only STRING and WSTRING take a length; 'INT' does not");
}

TEST(VarSection, KindsAndQualifiers) {
    const test::Parsed parsed = parse_text(
        "FUNCTION_BLOCK F\nVAR_INPUT a : BOOL; END_VAR\nVAR_OUTPUT b : INT; END_VAR\n"
        "VAR_IN_OUT c : REAL; END_VAR\nVAR_TEMP d : INT; END_VAR\nVAR_EXTERNAL e : DINT; END_VAR\n"
        "VAR CONSTANT f : INT := 3; END_VAR\nVAR RETAIN g : INT; END_VAR\n"
        "VAR NON_RETAIN h : INT; END_VAR\nEND_FUNCTION_BLOCK\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& sections = parsed.unit.pous.front().sections;
    ASSERT_EQ(sections.size(), 8u);
    const auto section = [&](std::size_t i) -> const ast::VarSection& {
        return std::get<ast::VarSection>(sections[i]);
    };
    EXPECT_EQ(section(0).kind, ast::VarSectionKind::Input);
    EXPECT_EQ(section(1).kind, ast::VarSectionKind::Output);
    EXPECT_EQ(section(2).kind, ast::VarSectionKind::InOut);
    EXPECT_EQ(section(3).kind, ast::VarSectionKind::Temp);
    EXPECT_EQ(section(4).kind, ast::VarSectionKind::External);
    EXPECT_TRUE(section(5).constant);
    EXPECT_EQ(section(6).retention, ast::Retention::Retain);
    EXPECT_EQ(section(7).retention, ast::Retention::NonRetain);
}

TEST(VarSection, LocatedVariables) {
    const test::Parsed parsed = parse_text("PROGRAM P\nVAR\n  i AT %IX0.7 : BOOL;\n"
                                           "  q AT %QW4 : WORD;\n  m AT %MD10 : DINT;\n"
                                           "  any AT %I* : BYTE;\nEND_VAR\nEND_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& variables =
        std::get<ast::VarSection>(parsed.unit.pous.front().sections.front()).variables;
    ASSERT_EQ(variables.size(), 4u);
    using Address = ast::DirectAddress;
    EXPECT_EQ(variables[0].address->area, Address::Area::Input);
    EXPECT_EQ(variables[0].address->size, Address::Size::Bit);
    EXPECT_EQ(variables[0].address->path, (std::vector<std::uint32_t>{0, 7}));
    EXPECT_EQ(variables[1].address->area, Address::Area::Output);
    EXPECT_EQ(variables[1].address->size, Address::Size::Word);
    EXPECT_EQ(variables[1].address->path, (std::vector<std::uint32_t>{4}));
    EXPECT_EQ(variables[2].address->area, Address::Area::Memory);
    EXPECT_EQ(variables[2].address->size, Address::Size::DoubleWord);
    EXPECT_TRUE(variables[3].address->path.empty());
    EXPECT_EQ(ast::to_sexpr(parsed.unit),
              "(program P (var i (at %IX0.7) BOOL) (var q (at %QW4) WORD) "
              "(var m (at %MD10) DINT) (var any (at %I*) BYTE) (body))\n");
}

TEST(VarSection, AtWithSeveralNamesIsAnError) {
    EXPECT_EQ(
        parse_text("PROGRAM P VAR a, b AT %IX0.0 : BOOL; END_VAR END_PROGRAM").first_message(),
        "AT locates a single variable; declare 'b' separately");
}

TEST(VarSection, FbInstanceWithInitialInputs) {
    EXPECT_EQ(unit_sexpr("PROGRAM P VAR t : TON := (PT := T#1s); END_VAR END_PROGRAM"),
              "(program P (var t TON ( PT=(TIME 1000000000ns) )) (body))\n");
}

TEST(Pou, FunctionFunctionBlockAndProgram) {
    EXPECT_EQ(unit_sexpr("FUNCTION Twice : INT VAR_INPUT x : INT; END_VAR Twice := 2 * x; "
                         "END_FUNCTION\nFUNCTION_BLOCK Fb END_FUNCTION_BLOCK\nPROGRAM Main VAR "
                         "fb1 : Fb; END_VAR fb1(); END_PROGRAM"),
              "(function Twice (var x INT) (body (assign (name Twice) (* (int 2) (name x)))))\n"
              "(function_block Fb (body))\n(program Main (var fb1 Fb) (body (call (name fb1))))\n");
}

TEST(Pou, FunctionKeepsItsReturnType) {
    const test::Parsed parsed = parse_text("FUNCTION F : LREAL F := 1.0; END_FUNCTION");
    ASSERT_TRUE(parsed.unit.pous.front().return_type);
    EXPECT_EQ(ast::to_sexpr(*parsed.unit.pous.front().return_type), "LREAL");
}

TEST(Pou, FunctionBlockExtendsAndImplements) {
    const test::Parsed parsed =
        parse_text("FUNCTION_BLOCK Motor EXTENDS Device IMPLEMENTS IRun, IStop END_FUNCTION_BLOCK");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const ast::Pou& pou = parsed.unit.pous.front();
    EXPECT_EQ(pou.extends->name, "Device");
    ASSERT_EQ(pou.implements.size(), 2u);
    EXPECT_EQ(pou.implements[1].name, "IStop");
}

TEST(Configuration, ResourcesTasksProgramsGlobalsAndAccessPaths) {
    const test::Parsed parsed = parse_text(R"(
CONFIGURATION Cell
  VAR_GLOBAL speed : INT; END_VAR
  VAR_GLOBAL CONSTANT limit : INT := 10; END_VAR
  VAR_ACCESS
    speed_in : Cpu1.Main1.speed : INT READ_WRITE;
    led : %QX1.0 : BOOL;
  END_VAR
  RESOURCE Cpu1 ON PLC
    VAR_GLOBAL local : BOOL; END_VAR
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    TASK OnEvent(SINGLE := trigger, PRIORITY := 2);
    PROGRAM RETAIN Main1 WITH Fast : Main (go := start, done => finished);
    PROGRAM Background : Idle;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const ast::Configuration& configuration = parsed.unit.configurations.front();
    ASSERT_EQ(configuration.sections.size(), 3u);
    const auto& access = std::get<ast::AccessSection>(configuration.sections[2]);
    ASSERT_EQ(access.paths.size(), 2u);
    EXPECT_TRUE(access.paths[0].writable);
    EXPECT_EQ(std::get<std::vector<ast::Identifier>>(access.paths[0].path).size(), 3u);
    EXPECT_FALSE(access.paths[1].writable);
    EXPECT_TRUE(std::holds_alternative<ast::DirectAddress>(access.paths[1].path));

    const ast::Resource& resource = configuration.resources.front();
    EXPECT_EQ(resource.processor->name, "PLC");
    ASSERT_EQ(resource.tasks.size(), 2u);
    EXPECT_TRUE(resource.tasks[0].interval);
    EXPECT_FALSE(resource.tasks[0].single);
    EXPECT_TRUE(resource.tasks[1].single);
    ASSERT_EQ(resource.programs.size(), 2u);
    EXPECT_EQ(resource.programs[0].retention, ast::Retention::Retain);
    EXPECT_EQ(resource.programs[0].task->name, "Fast");
    EXPECT_EQ(resource.programs[0].type.name, "Main");
    ASSERT_EQ(resource.programs[0].connections.size(), 2u);
    EXPECT_EQ(resource.programs[0].connections[1].kind, ast::Argument::Kind::Output);
    EXPECT_FALSE(resource.programs[1].task);
}

TEST(Configuration, WithoutResourceHasOneImplicitResource) {
    const test::Parsed parsed = parse_text(
        "CONFIGURATION C TASK T(INTERVAL := T#10ms, PRIORITY := 1); PROGRAM I WITH T : P; "
        "END_CONFIGURATION");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const ast::Resource& resource = parsed.unit.configurations.front().resources.front();
    EXPECT_FALSE(resource.processor);
    EXPECT_EQ(resource.programs.size(), 1u);
}

TEST(Configuration, TaskPropertiesAreChecked) {
    EXPECT_EQ(parse_text("CONFIGURATION C TASK T(CYCLE := T#1ms, PRIORITY := 1); "
                         "END_CONFIGURATION")
                  .first_message(),
              "unknown task property 'CYCLE'; a task has SINGLE, INTERVAL and PRIORITY");
    EXPECT_EQ(
        parse_text("CONFIGURATION C TASK T(INTERVAL := T#1ms); END_CONFIGURATION").first_message(),
        "task 'T' needs a PRIORITY");
    EXPECT_EQ(parse_text("CONFIGURATION C TASK T(PRIORITY := 1, priority := 2); END_CONFIGURATION")
                  .first_message(),
              "task property 'priority' is given twice");
}

TEST(Declaration, EveryNodeKnowsWhereItIs) {
    const test::Parsed parsed = parse_text("PROGRAM Main\n  VAR x : INT; END_VAR\n  x := 1;\n"
                                           "END_PROGRAM\n",
                                           "main.st");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const ast::Pou& pou = parsed.unit.pous.front();
    EXPECT_EQ(pou.range.begin, (SourcePosition{1, 1}));
    EXPECT_EQ(pou.range.end, (SourcePosition{4, 11}));
    EXPECT_EQ(pou.name.range.begin, (SourcePosition{1, 9}));
    const auto& variable = std::get<ast::VarSection>(pou.sections.front()).variables.front();
    EXPECT_EQ(variable.names.front().range.begin, (SourcePosition{2, 7}));
    EXPECT_EQ(variable.type.range.begin, (SourcePosition{2, 11}));
    EXPECT_EQ(pou.body.front().range.begin, (SourcePosition{3, 3}));
}

} // namespace
} // namespace eposp::compiler
