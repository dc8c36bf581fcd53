// Initial values that belong to types (IEC 61131-3 ed. 3, 6.4.2): a type declaration's own
// default, structure member defaults, and the errors in them, reported once.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++count;
    }
    return count;
}

TEST(StructMemberDefault, ErrorIsReportedOnceForAnArrayOfTheStruct) {
    const std::string errors =
        diagnostics_of("TYPE S : STRUCT m : INT := 1.5; END_STRUCT END_TYPE\n"
                       "PROGRAM Main\nVAR a : ARRAY[1..4] OF S; b : S; END_VAR\nEND_PROGRAM\n");
    EXPECT_EQ(occurrences(errors, "error:"), 1U) << errors;
    EXPECT_NE(errors.find("test.st:1:28: error: the initial value must be a constant INT"),
              std::string::npos)
        << errors;
}

} // namespace
} // namespace eposp::compiler::test
