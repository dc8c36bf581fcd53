// maxon's MU_* and CAN_* blocks against the fake drive and fake nodes.

#include "motion_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::plcopen::test {
namespace {

constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Controller : AXIS_REF := (AxisNo := 255);
  Input : MU_GetDigitalInput;
  Output : MU_SetDigitalOutput;
  Analog : MU_GetAnalogInput;
  GetBit : MU_GetBitState;
  SetBit : MU_SetBitState;
  Count : MU_GetDeviceErrorCount;
  Entry : MU_GetDeviceError;
  Read : CAN_SdoRead;
  Write : CAN_SdoWrite;
  Nmt : CAN_Nmt;
  InputNumber : USINT := 2;
  SetOutput, SetTheBit, ReadIt, WriteIt, SendNmt : BOOL;
  Node : USINT := 5;
END_VAR
Input(Axis := Axis1, Enable := TRUE, Input := InputNumber);
Output(Axis := Axis1, Execute := SetOutput, Output := 3, State := TRUE);
Analog(Axis := Axis1, Enable := TRUE, Input := 2);
GetBit(Axis := Axis1, Enable := TRUE, Index := 16#6041, SubIndex := 0, BitNumber := 10);
SetBit(Axis := Axis1, Execute := SetTheBit, Index := 16#2078, SubIndex := 1, BitNumber := 0,
       State := TRUE);
Count(Axis := Axis1, Enable := TRUE);
Entry(Axis := Axis1, Enable := TRUE, ErrorNumber := 1);
Read(Execute := ReadIt, Port := 2, NodeId := Node, Index := 16#1000, SubIndex := 0);
Write(Execute := WriteIt, Port := 2, NodeId := Node, Index := 16#1017, SubIndex := 0,
      Data := 100, DataLength := 2);
Nmt(Execute := SendNmt, Port := 2, NodeId := 0, Command := 1);
END_PROGRAM
)ST";

class MaxonBlocks : public testing::TestWithParam<vm::Engine> {
protected:
    MaxonBlocks() : h(GetParam()) {
        h.link.nodes[{2, 5}] = {{{0x1000, 0}, 0x00020192}, {{0x1017, 0}, 0}};
        h.start(std::string(kProgram));
    }
    FakeDrive& drive() { return h.link.drives[1]; }
    MotionHarness h;
};

TEST_P(MaxonBlocks, DigitalAndAnalogInputsOfTheDrive) {
    drive().objects[{0x2071, 1}] = 0b100;  // the home switch functionality (bit 2)
    drive().objects[{0x207C, 2}] = 0xFF38; // -200 mV
    drive().sizes[{0x207C, 2}] = 2;
    h.cycle(3);
    EXPECT_TRUE(h.flag("Input.Valid"));
    EXPECT_TRUE(h.flag("Input.State"));
    EXPECT_EQ(h.get<std::int32_t>("Analog.Value"), -200);
    h.set<std::uint8_t>("InputNumber", 1);
    h.cycle(3);
    EXPECT_FALSE(h.flag("Input.State"));
    h.set<std::uint8_t>("InputNumber", 16);
    h.cycle();
    EXPECT_TRUE(h.flag("Input.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Input.ErrorID"), 0x1010);
}

TEST_P(MaxonBlocks, SettingABitKeepsTheOthers) {
    drive().objects[{0x2078, 1}] = 0x8002;
    drive().sizes[{0x2078, 1}] = 2;
    h.set_flag("SetOutput", true);
    h.cycle(4);
    EXPECT_TRUE(h.flag("Output.Done"));
    EXPECT_EQ(drive().object(0x2078, 1), 0x800AU); // output 3 set, bits 1 and 15 kept
    EXPECT_EQ(h.link.last_write_size, 2);
    h.set_flag("SetTheBit", true);
    h.cycle(4);
    EXPECT_TRUE(h.flag("SetBit.Done"));
    EXPECT_EQ(drive().object(0x2078, 1), 0x800BU);
}

TEST_P(MaxonBlocks, ABitOfAnyObject) {
    drive().objects[{0x6041, 0}] = 0x0437;
    h.cycle(3);
    EXPECT_TRUE(h.flag("GetBit.State"));
}

TEST_P(MaxonBlocks, TheDrivesErrorHistory) {
    drive().objects[{0x1003, 0}] = 2;
    drive().objects[{0x1003, 1}] = 0x00008611;
    h.cycle(3);
    EXPECT_EQ(h.get<std::uint8_t>("Count.ErrorCount"), 2);
    EXPECT_EQ(h.get<std::uint32_t>("Entry.DeviceErrorCode"), 0x8611U);
}

TEST_P(MaxonBlocks, SdoTransfersWithAnyNode) {
    h.set_flag("ReadIt", true);
    h.set_flag("WriteIt", true);
    h.cycle(2);
    EXPECT_TRUE(h.flag("Read.Done"));
    EXPECT_EQ(h.get<std::uint32_t>("Read.Data"), 0x00020192U);
    EXPECT_EQ(h.get<std::uint8_t>("Read.DataLength"), 4);
    EXPECT_TRUE(h.flag("Write.Done"));
    EXPECT_EQ((h.link.nodes[{2, 5}][{0x1017, 0}]), 100U);
    // A node without the object aborts: the code comes with the error.
    h.set_flag("ReadIt", false);
    h.set<std::uint8_t>("Node", 9);
    h.cycle();
    h.set_flag("ReadIt", true);
    h.cycle(2);
    EXPECT_TRUE(h.flag("Read.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Read.ErrorID"), 0x1030);
    EXPECT_EQ(h.get<std::uint32_t>("Read.AbortCode"), 0x06020000U);
}

TEST_P(MaxonBlocks, NmtToEveryNodeOfThePort) {
    h.set_flag("SendNmt", true);
    h.cycle();
    EXPECT_TRUE(h.flag("Nmt.Done"));
    ASSERT_EQ(h.link.nmt_sent.size(), 1U);
    EXPECT_EQ(h.link.nmt_sent[0].port, 2);
    EXPECT_EQ(h.link.nmt_sent[0].node, 0);
    EXPECT_EQ(h.link.nmt_sent[0].command, 1);
}

INSTANTIATE_TEST_SUITE_P(Engines, MaxonBlocks,
                         testing::Values(vm::Engine::Interpreter, vm::Engine::Compiled),
                         engine_name);

} // namespace
} // namespace eposp::plcopen::test
