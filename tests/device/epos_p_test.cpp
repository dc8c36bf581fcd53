// The EPOS P as a library: its two ports, the internal EPOS2 and the PLC on one virtual loop.
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/compiler/compiler.hpp"
#include "eposp/device/epos_p.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;

vm::Image compile_program(const std::string& source) {
    compiler::SourceManager sources;
    const compiler::FileId file = sources.add("main.st", source);
    compiler::Diagnostics diagnostics;
    auto image = compiler::compile(sources, std::span(&file, 1), diagnostics);
    EXPECT_TRUE(image.has_value());
    return std::move(*image);
}

TEST(EposP, TheInternalEpos2BootsAsNodeOneOnPortOneOnly) {
    EposP device;
    std::vector<can::Frame> internal;
    std::vector<can::Frame> external;
    device.internal_port().on_receive([&](const can::Frame& frame) { internal.push_back(frame); });
    device.external_port().on_receive([&](const can::Frame& frame) { external.push_back(frame); });
    device.loop().run_for(10ms);

    ASSERT_FALSE(internal.empty());
    EXPECT_EQ(internal.front().id, 0x701u); // the boot-up message of node 1 (CiA 301 7.2.8.3.2)
    EXPECT_EQ(internal.front().payload().size(), 1u);
    EXPECT_EQ(internal.front().payload()[0], 0x00);
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::PreOperational);
    EXPECT_TRUE(external.empty());
}

TEST(EposP, RunsTheProgramsTasksAndTimersInTheLoopsTime) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(R"(
        PROGRAM Main
        VAR scans : DINT; delay : TON; elapsed : BOOL; END_VAR
        scans := scans + 1;
        delay(IN := TRUE, PT := T#250ms);
        elapsed := delay.Q;
        END_PROGRAM)")));
    ASSERT_FALSE(device.plc().runtime().start(vm::StartMode::Cold));

    device.loop().run_for(245ms); // a task without a configuration runs every 10 ms
    EXPECT_EQ(*device.plc().value_of("Main.scans"), "25");
    EXPECT_EQ(*device.plc().value_of("Main.elapsed"), "FALSE");
    device.loop().run_for(10ms);
    EXPECT_EQ(*device.plc().value_of("Main.elapsed"), "TRUE");
    EXPECT_TRUE(device.plc().errors().empty());
}

} // namespace
} // namespace eposp::device
