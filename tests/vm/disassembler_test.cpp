#include "eposp/vm/disassembler.hpp"
#include "sample_image.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::vm::test {
namespace {

using ::testing::HasSubstr;

TEST(Disassembler, ShowsTablesAndCodeWithLinesAndNames) {
    const auto text = disassemble(sample_image());
    EXPECT_THAT(text, HasSubstr("MainTask INTERVAL 1000000 ns PRIORITY 1 stack 1024: Main@s+8"));
    EXPECT_THAT(text, HasSubstr("PROGRAM Main code [0, 10) frame 0 out 16 instance 32"));
    EXPECT_THAT(text, HasSubstr("Inst0.counter : DINT @ s+8"));
    EXPECT_THAT(text, HasSubstr("%I4.0 : INT @ s+40"));
    EXPECT_THAT(text, HasSubstr("SQRT(LREAL) : LREAL"));
    EXPECT_THAT(text, HasSubstr("L3        0  AddI32 i+0, i+0, #1"));
    EXPECT_THAT(text, HasSubstr("2  Call Twice"));
    EXPECT_THAT(text, HasSubstr("3  Stx32 i+4, i+0, o+4 [1 +4 x4]"));
    EXPECT_THAT(text, HasSubstr("5  CallNative SQRT"));
    EXPECT_THAT(text, HasSubstr("7  JLtI32 i+0, i+0, ->9"));
    EXPECT_THAT(text, HasSubstr("8  JTab32 i+0, {from 1: ->9 ->9}, ->9"));
    EXPECT_THAT(text, HasSubstr("FUNCTION Twice:\n  L10      10  Add32 f+4, f+0, f+0"));
}

TEST(Disassembler, PrintsBrokenReferencesInsteadOfFailing) {
    auto image = sample_image();
    image.code[2].a = 77;
    image.code[0].opcode = static_cast<Opcode>(kOpcodeCount + 3);
    const auto text = disassemble(image);
    EXPECT_THAT(text, HasSubstr("Call <bad 77>"));
    EXPECT_THAT(text, HasSubstr("<unknown opcode"));
}

} // namespace
} // namespace eposp::vm::test
