// The expressions, nested type specifications and initial values of a file are made in its
// unit's arena (ast/node_arena.hpp): moving the unit, or a vector of units growing, leaves every
// node where it was, and each node's destructor runs (its strings and vectors are freed; ASan's
// leak check and valgrind see what a missed one would leak).
#include "../parse_helpers.hpp"
#include "eposp/compiler/ast/ast_printer.hpp"
#include "eposp/compiler/ast/node_arena.hpp"

#include <array>
#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

namespace eposp::compiler::test {
namespace {

constexpr const char* kProgram = R"(
TYPE Limits : STRUCT low : ARRAY[1..3] OF INT := [1, 2, 3]; high : REF_TO INT; END_STRUCT;
END_TYPE
PROGRAM P
VAR a_rather_long_variable_name : ARRAY[0..9] OF DINT; s : STRING[20] := 'text'; END_VAR
a_rather_long_variable_name[2 * 3 + 1] := LIMIT(0, a_rather_long_variable_name[0] - 1, 100);
END_PROGRAM
)";

const ast::Expression& first_value(const ast::CompilationUnit& unit) {
    return *std::get<ast::AssignmentStatement>(unit.pous.front().body.front().node).value;
}

TEST(NodeArena, UnitsMovedKeepTheirNodesInPlace) {
    Parsed parsed = parse_text(kProgram);
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    ASSERT_NE(parsed.unit.nodes, nullptr);
    const std::string printed = ast::to_sexpr(parsed.unit);
    const ast::Expression* value = &first_value(parsed.unit);

    std::vector<ast::CompilationUnit> units;
    units.push_back(std::move(parsed.unit));
    for (int i = 0; i < 8; ++i) { // the vector grows, moving the first unit each time
        units.push_back(parse_text(kProgram).unit);
    }
    EXPECT_EQ(&first_value(units.front()), value);
    for (const ast::CompilationUnit& unit : units) {
        EXPECT_EQ(ast::to_sexpr(unit), printed);
    }
}

TEST(NodeArena, AFileThatDoesNotParseHasNoNodes) {
    const Parsed parsed = parse_text("PROGRAM P\nx := ;\nEND_PROGRAM\n");
    EXPECT_TRUE(parsed.diagnostics.has_errors());
    EXPECT_EQ(parsed.unit.nodes, nullptr);
    EXPECT_TRUE(parsed.unit.pous.empty());
}

struct Counted {
    int* destroyed;
    alignas(32) std::array<char, 40> payload;
    ~Counted() { ++*destroyed; }
};

TEST(NodeArena, RunsEachNodesDestructorAndAlignsIt) {
    int destroyed = 0;
    {
        ast::NodeArena arena;
        std::vector<ast::NodePtr<Counted>> nodes;
        for (int i = 0; i < 1000; ++i) { // beyond the first block
            nodes.push_back(arena.make<Counted>(&destroyed, std::array<char, 40>{}));
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(nodes.back().get()) % 32, 0U);
        }
        nodes.front().reset();
        EXPECT_EQ(destroyed, 1);
    }
    EXPECT_EQ(destroyed, 1000);
}

} // namespace
} // namespace eposp::compiler::test
