#include "eposp/bench/native/expected_results.hpp"
#include "eposp/bench/native/program.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace eposp::bench::native {
namespace {

const ProgramEntry* find_program(std::string_view name) {
    const auto all = programs();
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const ProgramEntry& e) { return e.name == name; });
    return it == all.end() ? nullptr : &*it;
}

class NativeBenchProgram : public testing::TestWithParam<ExpectedResult> {};

TEST_P(NativeBenchProgram, GlobalsAfter1000ScansEqualTheReferenceTable) {
    const ExpectedResult& expected = GetParam();
    const ProgramEntry* entry = find_program(expected.program);
    ASSERT_NE(entry, nullptr) << "no translation of " << expected.program;

    const auto program = entry->make();
    run_scans(*program, kCheckedScans);

    const Globals& g = program->globals();
    EXPECT_EQ(g.cycles, expected.cycles);
    EXPECT_EQ(g.result, expected.result);
    // The table gives r to 6 decimals.
    EXPECT_EQ(std::llround(g.r * 1e6), std::llround(expected.r * 1e6)) << "r = " << g.r;
}

INSTANTIATE_TEST_SUITE_P(AllPrograms, NativeBenchProgram,
                         testing::ValuesIn(kExpectedAfter1000Scans),
                         [](const testing::TestParamInfo<ExpectedResult>& param_info) {
                             return std::string(param_info.param.program);
                         });

TEST(NativeBenchPrograms, RegistryHoldsExactlyTheProgramsOfTheReferenceTable) {
    ASSERT_EQ(programs().size(), kExpectedAfter1000Scans.size());
    for (const ExpectedResult& expected : kExpectedAfter1000Scans) {
        EXPECT_NE(find_program(expected.program), nullptr) << expected.program;
    }
}

} // namespace
} // namespace eposp::bench::native
