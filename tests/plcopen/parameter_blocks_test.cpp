// The parameter blocks and the SDO readers against the fake drive: PLCopen parameter numbers,
// any object by number, the size of a write, SDO aborts, signed values.

#include "motion_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::plcopen::test {
namespace {

constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  ReadLimit : MC_ReadParameter;
  WriteLimit : MC_WriteParameter;
  WriteRaw : MC_WriteParameter;
  ReadRaw : MC_ReadParameter;
  ReadFlag : MC_ReadBoolParameter;
  Velocity : MC_ReadActualVelocity;
  Current : MC_ReadActualCurrent;
  Read, Write, WriteRawGo : BOOL;
  Number : DINT := 2;
  RawNumber : DINT := 16#208100;
END_VAR
ReadLimit(Axis := Axis1, Enable := Read, ParameterNumber := Number);
WriteLimit(Axis := Axis1, Execute := Write, ParameterNumber := Number, Value := 5000);
WriteRaw(Axis := Axis1, Execute := WriteRawGo, ParameterNumber := RawNumber, Value := -7);
ReadRaw(Axis := Axis1, Enable := TRUE, ParameterNumber := 16#208100);
ReadFlag(Axis := Axis1, Enable := TRUE, ParameterNumber := 16#210000);
Velocity(Axis := Axis1, Enable := TRUE);
Current(Axis := Axis1, Enable := TRUE);
END_PROGRAM
)ST";

class ParameterBlocks : public testing::TestWithParam<vm::Engine> {
protected:
    ParameterBlocks() : h(GetParam()) { h.start(std::string(kProgram)); }
    FakeDrive& drive() { return h.link.drives[1]; }
    MotionHarness h;
};

TEST_P(ParameterBlocks, APLCopenParameterIsWrittenAndReadBack) {
    h.set_flag("Write", true);
    h.cycle(3);
    EXPECT_TRUE(h.flag("WriteLimit.Done"));
    EXPECT_EQ(drive().object(0x607D, 2), 5000U); // SWLimitPos
    EXPECT_EQ(h.link.last_write_size, 4);
    h.set_flag("Read", true);
    h.cycle(3);
    EXPECT_TRUE(h.flag("ReadLimit.Valid"));
    EXPECT_EQ(h.get<std::int32_t>("ReadLimit.Value"), 5000);
    // Enable FALSE: nothing valid, the value cleared.
    h.set_flag("Read", false);
    h.cycle();
    EXPECT_FALSE(h.flag("ReadLimit.Valid"));
    EXPECT_EQ(h.get<std::int32_t>("ReadLimit.Value"), 0);
}

TEST_P(ParameterBlocks, ParametersTheDriveDoesNotHaveAreErrors) {
    h.set<std::int32_t>("Number", 16); // MaxJerk
    h.set_flag("Read", true);
    h.set_flag("Write", true);
    h.cycle();
    EXPECT_EQ(h.get<std::uint16_t>("ReadLimit.ErrorID"), 0x1011);
    EXPECT_EQ(h.get<std::uint16_t>("WriteLimit.ErrorID"), 0x1011);
    h.set_flag("Write", false);
    h.set<std::int32_t>("Number", 1); // CommandedPosition is read-only
    h.cycle();
    h.set_flag("Write", true);
    h.cycle();
    EXPECT_EQ(h.get<std::uint16_t>("WriteLimit.ErrorID"), 0x1011);
}

TEST_P(ParameterBlocks, AnObjectIsReadFirstSoTheWriteHasItsSize) {
    drive().sizes[{0x2081, 0}] = 2;
    h.set_flag("WriteRawGo", true);
    h.cycle(4);
    EXPECT_TRUE(h.flag("WriteRaw.Done"));
    EXPECT_EQ(h.link.last_write_size, 2);
    EXPECT_EQ(static_cast<std::int32_t>(drive().object(0x2081)), -7);
    EXPECT_EQ(h.get<std::int32_t>("ReadRaw.Value"), -7);
}

TEST_P(ParameterBlocks, AnSdoAbortIsAnErrorOfTheBlock) {
    h.set<std::int32_t>("RawNumber", 0x2FFF00);
    h.set_flag("WriteRawGo", true);
    h.cycle(4);
    EXPECT_TRUE(h.flag("WriteRaw.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("WriteRaw.ErrorID"), 0x1030);
    EXPECT_FALSE(h.flag("WriteRaw.Busy"));
}

TEST_P(ParameterBlocks, ActualValuesAreReadWithTheirSign) {
    drive().objects[{0x606C, 0}] = static_cast<std::uint32_t>(-1500);
    drive().objects[{0x6078, 0}] = 0xFFF6;
    drive().sizes[{0x6078, 0}] = 2;
    drive().objects[{0x2100, 0}] = 1;
    h.cycle(3);
    EXPECT_TRUE(h.flag("Velocity.Valid"));
    EXPECT_EQ(h.get<std::int32_t>("Velocity.Velocity"), -1500);
    EXPECT_EQ(h.get<std::int32_t>("Current.Current"), -10);
    EXPECT_TRUE(h.flag("ReadFlag.Value"));
    // The readers keep reading: a new value shows a cycle or two later.
    drive().objects[{0x606C, 0}] = 250;
    h.cycle(3);
    EXPECT_EQ(h.get<std::int32_t>("Velocity.Velocity"), 250);
}

INSTANTIATE_TEST_SUITE_P(Engines, ParameterBlocks,
                         testing::Values(vm::Engine::Interpreter, vm::Engine::Compiled),
                         engine_name);

} // namespace
} // namespace eposp::plcopen::test
