// ast::pous_calling: how `eposp test` finds its suites, the FBs and PROGRAMs whose body calls
// TEST(...).
#include "eposp/compiler/ast/calling_pous.hpp"
#include "parse_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

std::vector<std::string> names_calling(const std::string& text, std::string_view function) {
    const Parsed parsed = parse_text(text);
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    std::vector<std::string> names;
    for (const ast::CallingPou& pou : ast::pous_calling(parsed.unit, function)) {
        names.push_back(pou.name);
    }
    return names;
}

TEST(CallingPous, FindsFunctionBlocksAndProgramsWithTheirKindFileAndLine) {
    const Parsed parsed = parse_text(R"(FUNCTION_BLOCK SuiteA
TEST('first');
END_FUNCTION_BLOCK

PROGRAM SuiteB
TEST('second');
END_PROGRAM
)",
                                     "tests.st");
    const auto found = ast::pous_calling(parsed.unit, "TEST");
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].name, "SuiteA");
    EXPECT_EQ(found[0].kind, ast::PouKind::FunctionBlock);
    EXPECT_EQ(found[0].file, parsed.unit.file);
    EXPECT_EQ(found[0].range.begin.line, 1u);
    EXPECT_EQ(found[1].name, "SuiteB");
    EXPECT_EQ(found[1].kind, ast::PouKind::Program);
    EXPECT_EQ(found[1].range.begin.line, 5u);
    EXPECT_EQ(parsed.sources.path(found[1].file), "tests.st");
}

TEST(CallingPous, FindsCallsNestedInStatementsExpressionsAndArguments) {
    const std::string text = R"(
FUNCTION_BLOCK InIf VAR x : BOOL; END_VAR IF x THEN ; ELSIF x THEN TEST('a'); END_IF; END_FUNCTION_BLOCK
FUNCTION_BLOCK InCase VAR n : INT; END_VAR CASE n OF 1: ; ELSE Test('b'); END_CASE; END_FUNCTION_BLOCK
FUNCTION_BLOCK InFor VAR i : INT; END_VAR FOR i := 0 TO 3 DO WHILE FALSE DO REPEAT test('c'); UNTIL TRUE END_REPEAT; END_WHILE; END_FOR; END_FUNCTION_BLOCK
FUNCTION_BLOCK InCondition VAR x : BOOL; END_VAR IF TEST('d') AND x THEN ; END_IF; END_FUNCTION_BLOCK
FUNCTION_BLOCK InArgument VAR x : BOOL; END_VAR x := SEL(x, FALSE, NOT TEST(IN := 'e')); END_FUNCTION_BLOCK
FUNCTION_BLOCK InIndex VAR a : ARRAY[0..1] OF INT; END_VAR a[TEST('f')] := 1; END_FUNCTION_BLOCK
)";
    EXPECT_EQ(names_calling(text, "test"),
              (std::vector<std::string>{"InIf", "InCase", "InFor", "InCondition", "InArgument",
                                        "InIndex"}));
}

TEST(CallingPous, IgnoresFunctionsOtherCallsAndNamesThatAreNotCalled) {
    const std::string text = R"(
FUNCTION Helper : BOOL TEST('in a function'); END_FUNCTION
FUNCTION_BLOCK CallsOther VAR t : TON; END_VAR t(IN := TRUE); Helper(); END_FUNCTION_BLOCK
FUNCTION_BLOCK NamesOnly VAR TEST_x : BOOL; test : BOOL; END_VAR test := TEST_x; END_FUNCTION_BLOCK
FUNCTION_BLOCK InDeclarationOnly VAR b : BOOL := TEST('x'); END_VAR END_FUNCTION_BLOCK
PROGRAM Empty END_PROGRAM
)";
    EXPECT_TRUE(names_calling(text, "TEST").empty());
    EXPECT_EQ(names_calling(text, "Helper"), std::vector<std::string>{"CallsOther"});
}

} // namespace
} // namespace eposp::compiler::test
