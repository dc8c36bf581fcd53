#include "eposp/vm/symbol_lookup.hpp"
#include "sample_image.hpp"

#include <gtest/gtest.h>

namespace eposp::vm::test {
namespace {

// Sample image: Inst0 (type Main) at s+8 with counter (DINT) at +0, values
// (ARRAY[1..4] OF DINT) at +4 and r (LREAL) at +24; a 2x2 matrix symbol is added here.
Image image_with_matrix() {
    auto image = sample_image();
    const auto dint = 0U;
    image.types.push_back(
        {"ARRAY[0..1] OF DINT", TypeKind::Array, Scalar::Bool, 8, dint, 0, 2, {}});
    const auto row = static_cast<std::uint32_t>(image.types.size() - 1);
    image.types.push_back(
        {"ARRAY[0..1, 0..1] OF DINT", TypeKind::Array, Scalar::Bool, 16, row, 0, 2, {}});
    image.symbols.push_back({"Inst0.m", static_cast<std::uint32_t>(image.types.size() - 1), 8});
    return image;
}

struct LookupCase {
    const char* path;
    std::uint32_t offset;
    const char* type;
};

void PrintTo(const LookupCase& c, std::ostream* os) {
    *os << c.path;
}

class SymbolLookup : public ::testing::TestWithParam<LookupCase> {};

TEST_P(SymbolLookup, ResolvesFullPaths) {
    const auto image = image_with_matrix();
    const auto found = lookup_variable(image, GetParam().path);
    ASSERT_TRUE(found) << found.error();
    EXPECT_EQ(found->offset, GetParam().offset);
    EXPECT_EQ(image.types[found->type].name, GetParam().type);
}

INSTANTIATE_TEST_SUITE_P(Paths, SymbolLookup,
                         ::testing::Values(LookupCase{"Inst0", 8, "Main"},
                                           LookupCase{"Inst0.counter", 8, "DINT"},
                                           LookupCase{"inst0.R", 32, "LREAL"},
                                           LookupCase{"Inst0.values[1]", 12, "DINT"},
                                           LookupCase{"Inst0.values[4]", 24, "DINT"},
                                           LookupCase{"Inst0.m[1, 0]", 16, "DINT"},
                                           LookupCase{"Inst0.m[1][1]", 20, "DINT"},
                                           LookupCase{"Inst0.m[1]", 16, "ARRAY[0..1] OF DINT"}));

TEST(SymbolLookup, ExplainsWhatIsWrongWithAPath) {
    const auto image = image_with_matrix();
    EXPECT_EQ(lookup_variable(image, "Other.x").error(), "no variable Other.x");
    EXPECT_EQ(lookup_variable(image, "Inst0.nope").error(), "Inst0 has no field nope");
    EXPECT_EQ(lookup_variable(image, "Inst0.values[5]").error(),
              "index 5 outside ARRAY[1..4] OF DINT");
    EXPECT_EQ(lookup_variable(image, "Inst0.counter[1]").error(), "Inst0.counter is not an array");
    EXPECT_EQ(lookup_variable(image, "Inst0.values[x]").error(),
              "expected an index at position 13 of Inst0.values[x]");
    EXPECT_EQ(lookup_variable(image, "Inst0.values[1").error(), "missing ] in Inst0.values[1");
}

} // namespace
} // namespace eposp::vm::test
