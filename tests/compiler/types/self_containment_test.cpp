// A type or FB that contains itself has no size and is refused; a reference to itself is
// fine, since a reference does not contain its target (a linked list, common in CODESYS code).
#include "codegen_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;

TEST(SelfContainment, AnFbContainingAnInstanceOfItselfIsRefused) {
    const std::string user = "PROGRAM Main\nVAR a : A; END_VAR\nEND_PROGRAM\n";
    EXPECT_THAT(diagnostics_of("FUNCTION_BLOCK A\nVAR b : A; END_VAR\nEND_FUNCTION_BLOCK\n" + user),
                HasSubstr("test.st:1:16: error: 'A' contains an instance of itself"));
    EXPECT_THAT(diagnostics_of("FUNCTION_BLOCK A\nVAR b : ARRAY[0..1] OF A; END_VAR\n"
                               "END_FUNCTION_BLOCK\n" +
                               user),
                HasSubstr("test.st:1:16: error: 'A' contains an instance of itself"));
    EXPECT_THAT(diagnostics_of("FUNCTION_BLOCK A\nVAR b : B; END_VAR\nEND_FUNCTION_BLOCK\n"
                               "FUNCTION_BLOCK B\nVAR_OUTPUT a : A; END_VAR\nEND_FUNCTION_BLOCK\n" +
                               user),
                HasSubstr("test.st:1:16: error: 'A' contains an instance of itself"));
    // The cycle through a structure is found where the typing stage lays the structure out.
    EXPECT_THAT(diagnostics_of("TYPE S : STRUCT f : A; END_STRUCT; END_TYPE\n"
                               "FUNCTION_BLOCK A\nVAR s : S; END_VAR\nEND_FUNCTION_BLOCK\n" +
                               user),
                HasSubstr("test.st:1:10: error: this type contains itself [E0418]"));
}

TEST(SelfContainment, AStructureMayReferToItself) {
    StProgram run(R"(
TYPE Node : STRUCT value : DINT; next : REF_TO Node; END_STRUCT; END_TYPE
TYPE Cell : STRUCT value : DINT; next : POINTER TO Cell; END_STRUCT; END_TYPE
PROGRAM Main
VAR n1, n2, n3 : Node; p : REF_TO Node; sum : DINT; c : Cell; END_VAR
n1.value := 1; n2.value := 20; n3.value := 300;
n1.next := REF(n2); n2.next := REF(n3);
p := REF(n1);
WHILE p <> NULL DO sum := sum + p^.value; p := p^.next; END_WHILE;
c.next := ADR(c);
c.next^.value := 4000;
sum := sum + c.value;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.sum"), 4321);
    EXPECT_EQ(run.errors(), "");
}

TEST(SelfContainment, AnFbMayReferToItsOwnType) {
    StProgram run(R"(
FUNCTION_BLOCK Link
VAR_INPUT next : REF_TO Link; END_VAR
VAR_OUTPUT depth : INT; END_VAR
IF next <> NULL THEN depth := next^.depth + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a, b : Link; END_VAR
b();
a(next := REF(b));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.a.depth"), 1);
}

} // namespace
} // namespace eposp::compiler::test
