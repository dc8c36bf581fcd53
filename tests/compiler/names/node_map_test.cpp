// sema::NodeMap, the table from AST nodes to what a stage found for them (the identifiers'
// symbols, the expressions' types): every node set is found, as last set, across its growth.
#include "eposp/compiler/sema/node_map.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace eposp::compiler::sema {
namespace {

struct Node {
    int id = 0;
};

TEST(NodeMap, FindsEveryNodeAsLastSetAndNoOther) {
    std::vector<Node> nodes(10000);
    std::vector<int> values(nodes.size());
    NodeMap<Node, int> map;
    EXPECT_EQ(map.find(&nodes[0]), nullptr);
    for (std::size_t i = 0; i < nodes.size(); i += 2) { // every other node, through many growths
        map.set(&nodes[i], &values[i]);
    }
    for (std::size_t i = 0; i < nodes.size(); i += 4) { // set again: the last value counts
        map.set(&nodes[i], &values[i + 1]);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const int* expected = i % 2 != 0 ? nullptr : (i % 4 == 0 ? &values[i + 1] : &values[i]);
        ASSERT_EQ(map.find(&nodes[i]), expected) << "node " << i;
    }
}

} // namespace
} // namespace eposp::compiler::sema
