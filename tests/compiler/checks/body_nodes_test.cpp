// checks::BodyNodes, the lists of a body's statements and expressions the checks loop over: the
// order in which they report (each statement, its own expressions each before its parts, then
// the statements it holds), and the assignments, calls and names among them in that order.
#include "checks/body_nodes.hpp"
#include "parse_helpers.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::compiler::checks {
namespace {

template <typename Nodes>
std::vector<std::string> ranges_of(const Nodes& nodes) {
    std::vector<std::string> texts;
    for (const auto* node : nodes) {
        texts.push_back(std::to_string(node->range.begin.line) + ":" +
                        std::to_string(node->range.begin.column));
    }
    return texts;
}

TEST(BodyNodes, ListsStatementsThenTheirPartsInTheOrderTheChecksReport) {
    const auto parsed = test::parse_text("PROGRAM P\n"
                                         "VAR a : INT; b : BOOL; END_VAR\n"
                                         "IF b THEN a := F(1);\n"     // 3
                                         "ELSIF NOT b THEN a := 2;\n" // 4
                                         "END_IF;\n"
                                         "CASE a OF 1: G(x := a); END_CASE;\n" // 6
                                         "END_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const BodyNodes nodes(parsed.unit.pous.at(0).body);
    // IF, its two assignments, CASE and its call statement.
    EXPECT_EQ(ranges_of(nodes.statements()),
              (std::vector<std::string>{"3:1", "3:11", "4:18", "6:1", "6:14"}));
    // The IF's conditions (b, NOT b, its operand b), the first assignment (a, F(1): F, 1), the
    // second (a, 2), the CASE's selector and label (a, 1), the call G(x := a): G, a.
    EXPECT_EQ(ranges_of(nodes.expressions()),
              (std::vector<std::string>{"3:4", "4:7", "4:11", "3:11", "3:16", "3:16", "3:18",
                                        "4:18", "4:23", "6:6", "6:11", "6:14", "6:14", "6:21"}));
    EXPECT_EQ(ranges_of(nodes.assignments()), (std::vector<std::string>{"3:11", "4:18"}));
    EXPECT_EQ(ranges_of(nodes.calls()), (std::vector<std::string>{"3:16", "6:14"}));
    EXPECT_EQ(ranges_of(nodes.names()), (std::vector<std::string>{"3:4", "4:11", "3:11", "3:16",
                                                                  "4:18", "6:6", "6:14", "6:21"}));
}

} // namespace
} // namespace eposp::compiler::checks
