// What every YAML file users write (an axis, a network) is held to, before its own keys are read.

#include "eposp/yaml/reader.hpp"

#include <gtest/gtest.h>

namespace eposp::yaml {
namespace {

/// Reads a mapping of integers named a and b.
core::Result<int> sum_of(std::string_view text) {
    return parse<int>(text, "f.yaml", [](Reader& in, const YAML::Node& root) {
        int sum = 0;
        in.each_key(root, "the file",
                    {{"a",
                      [&](const YAML::Node& node) {
                          sum += in.scalar<int>(node, "a");
                      }},
                     {"b", [&](const YAML::Node& node) {
                          sum += in.scalar<int>(node, "b");
                      }}});
        return sum;
    });
}

TEST(YamlReader, ReadsEachKeyOnce) {
    const auto sum = sum_of("a: 1\nb: 2\n");
    ASSERT_TRUE(sum) << sum.error();
    EXPECT_EQ(*sum, 3);
}

TEST(YamlReader, AKeyGivenTwiceIsAnErrorAtTheSecond) {
    const auto sum = sum_of("a: 1\nb: 2\na: 5\n");
    ASSERT_FALSE(sum);
    EXPECT_EQ(sum.error(), "f.yaml:3:1: error: duplicate key 'a' in 'the file'");
}

TEST(YamlReader, ASecondDocumentIsAnErrorWhereItStarts) {
    const auto sum = sum_of("a: 1\n---\nb: 2\n");
    ASSERT_FALSE(sum);
    EXPECT_EQ(sum.error(), "f.yaml:2:1: error: a second YAML document: a file holds one");
}

TEST(YamlReader, ADocumentEndMarkerAloneIsNoSecondDocument) {
    const auto sum = sum_of("a: 1\nb: 2\n...\n");
    ASSERT_TRUE(sum) << sum.error();
    EXPECT_EQ(*sum, 3);
}

// A fuzz finding: yaml-cpp's LoadAll never returns on this text (each further "document"
// consumes nothing), so counting documents with it hung the reader.
TEST(YamlReader, TextAfterAStrayFlowEndEnds) {
    const auto sum = sum_of(",\xff iz -1}}\n");
    EXPECT_FALSE(sum);
}

} // namespace
} // namespace eposp::yaml
