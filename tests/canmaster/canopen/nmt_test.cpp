#include "service_bench.hpp"
#include "eposp/canopen/nmt_master.hpp"
#include "eposp/canopen/nmt_slave.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::at_ms;
using testing::Sent;
using testing::ServiceBench;

constexpr NodeId kNode = 5;

class NmtSlaveTest : public ::testing::Test {
protected:
    NmtSlaveTest() {
        bench.device->on_receive([this](const can::Frame& frame) { nmt.on_frame(frame); });
        nmt.on_state_change([this](NmtState state) { states.push_back(state); });
    }

    /// Boots the slave and forgets what the boot did.
    void boot() {
        nmt.boot();
        bench.run_for(1ms);
        resets.clear();
        states.clear();
    }

    /// Sends an NMT command from the tester and lets it arrive.
    void command(NmtCommand command, NodeId target) {
        bench.tester->send(
            can::Frame::data_frame(kNmtCanId, {static_cast<std::uint8_t>(command), target}));
        bench.run_for(1ms);
    }

    ServiceBench bench;
    std::vector<std::string> resets;
    std::vector<NmtState> states;
    NmtSlave nmt{*bench.device,
                 kNode,
                 {.application = [this] { resets.emplace_back("application"); },
                  .communication =
                      [this] {
                          resets.emplace_back("communication");
                      }}};
};

TEST_F(NmtSlaveTest, IsInitialisingUntilBooted) {
    EXPECT_EQ(nmt.state(), NmtState::Initialising);
    command(NmtCommand::Start, kNode);
    EXPECT_EQ(nmt.state(), NmtState::Initialising);
    EXPECT_TRUE(bench.device_frames().empty());
}

TEST_F(NmtSlaveTest, BootResetsApplicationThenCommunicationAndSendsBootUp) {
    nmt.boot();
    bench.run_for(1ms);
    EXPECT_EQ(resets, (std::vector<std::string>{"application", "communication"}));
    EXPECT_EQ(states, (std::vector{NmtState::Initialising, NmtState::PreOperational}));
    EXPECT_EQ(nmt.state(), NmtState::PreOperational);
    // CiA 301 7.2.8.3.2.1: the boot-up message, 0x700 + node-ID with one byte 0x00.
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"}}));
}

// CiA 301 7.3.2.2, figure 48 and its transition table; EPOS2 FW spec table 7-65.
struct TransitionCase {
    NmtState from;
    NmtCommand command;
    NmtState to;
    std::vector<std::string> resets; ///< the reset handlers called, in order
    std::vector<NmtState> told;      ///< what the state listeners heard
    bool boot_up;
};

std::string command_name(NmtCommand command) {
    switch (command) {
    case NmtCommand::Start:
        return "Start";
    case NmtCommand::Stop:
        return "Stop";
    case NmtCommand::EnterPreOperational:
        return "EnterPreOperational";
    case NmtCommand::ResetNode:
        return "ResetNode";
    case NmtCommand::ResetCommunication:
        return "ResetCommunication";
    }
    return "Unknown";
}

std::string state_name(NmtState state) {
    std::string name(to_string(state));
    std::erase(name, '-');
    return name;
}

void PrintTo(const TransitionCase& c, std::ostream* os) {
    *os << to_string(c.from) << " + " << command_name(c.command);
}

const std::vector<std::string> kNoReset;
const std::vector<std::string> kResetNode{"application", "communication"};
const std::vector<std::string> kResetCommunication{"communication"};
const std::vector<NmtState> kAfterReset{NmtState::Initialising, NmtState::PreOperational};

using enum NmtState;
using enum NmtCommand;

const std::vector<TransitionCase> kTransitions = {
    {PreOperational, Start, Operational, kNoReset, {Operational}, false},
    {PreOperational, Stop, Stopped, kNoReset, {Stopped}, false},
    {PreOperational, EnterPreOperational, PreOperational, kNoReset, {}, false},
    {PreOperational, ResetNode, PreOperational, kResetNode, kAfterReset, true},
    {PreOperational, ResetCommunication, PreOperational, kResetCommunication, kAfterReset, true},
    {Operational, Start, Operational, kNoReset, {}, false},
    {Operational, Stop, Stopped, kNoReset, {Stopped}, false},
    {Operational, EnterPreOperational, PreOperational, kNoReset, {PreOperational}, false},
    {Operational, ResetNode, PreOperational, kResetNode, kAfterReset, true},
    {Operational, ResetCommunication, PreOperational, kResetCommunication, kAfterReset, true},
    {Stopped, Start, Operational, kNoReset, {Operational}, false},
    {Stopped, Stop, Stopped, kNoReset, {}, false},
    {Stopped, EnterPreOperational, PreOperational, kNoReset, {PreOperational}, false},
    {Stopped, ResetNode, PreOperational, kResetNode, kAfterReset, true},
    {Stopped, ResetCommunication, PreOperational, kResetCommunication, kAfterReset, true},
};

class NmtTransition : public NmtSlaveTest,
                      public ::testing::WithParamInterface<std::tuple<TransitionCase, NodeId>> {};

TEST_P(NmtTransition, CommandFromEveryStateAddressedToTheNodeOrToAll) {
    const auto& [c, target] = GetParam();
    boot();
    if (c.from == Operational) {
        command(Start, kNode);
    } else if (c.from == Stopped) {
        command(Stop, kNode);
    }
    ASSERT_EQ(nmt.state(), c.from);
    states.clear();
    const std::size_t frames_before = bench.device_frames().size();

    command(c.command, target);

    EXPECT_EQ(nmt.state(), c.to);
    EXPECT_EQ(resets, c.resets);
    EXPECT_EQ(states, c.told);
    const auto frames = bench.device_frames();
    ASSERT_EQ(frames.size(), frames_before + (c.boot_up ? 1 : 0));
    if (c.boot_up) {
        // The boot-up is sent the moment the command arrives, and starts after its intermission.
        const auto& command_frame = bench.wire.events.at(bench.wire.events.size() - 2);
        ASSERT_EQ(command_frame.sender, "tester");
        EXPECT_EQ(frames.back(), (Sent{testing::after_intermission(command_frame.end), "705#00"}));
    }
}

std::string
transition_name(const ::testing::TestParamInfo<std::tuple<TransitionCase, NodeId>>& tested) {
    const auto& [c, target] = tested.param;
    return state_name(c.from) + command_name(c.command) +
           (target == kAllNodes ? "ToAll" : "ToNode");
}

INSTANTIATE_TEST_SUITE_P(NmtCiA301, NmtTransition,
                         ::testing::Combine(::testing::ValuesIn(kTransitions),
                                            ::testing::Values(kNode, kAllNodes)),
                         transition_name);

TEST_F(NmtSlaveTest, IgnoresFramesThatAreNotACommandForIt) {
    boot();
    for (const char* frame : {
             "000#0106",      // another node
             "000#01",        // too short
             "000#010500",    // too long
             "000#0305",      // no such command
             "000#R2",        // remote frame
             "00000000#0105", // extended identifier
             "001#0105",      // not the NMT identifier
         }) {
        bench.send(frame);
        bench.run_for(1ms);
        EXPECT_EQ(nmt.state(), NmtState::PreOperational) << frame;
    }
    EXPECT_TRUE(states.empty());
    EXPECT_EQ(bench.device_frames().size(), 1U); // the boot-up
}

TEST_F(NmtSlaveTest, LocalControlAppliesCommandsAsTheNetworkWould) {
    boot();
    nmt.apply(NmtCommand::Start);
    EXPECT_EQ(nmt.state(), NmtState::Operational);
    nmt.apply(NmtCommand::ResetCommunication);
    bench.run_for(1ms);
    EXPECT_EQ(nmt.state(), NmtState::PreOperational);
    EXPECT_EQ(resets, kResetCommunication);
    EXPECT_EQ(bench.device_frames().back().frame, "705#00");
}

TEST(NmtSlave, NodeIdSetByTheResetCommunicationHandlerNamesTheBootUp) {
    ServiceBench bench;
    NodeId pending = kNode; // what LSS configured
    NmtSlave* self = nullptr;
    NmtSlave nmt(*bench.device, kNode, {.application = {}, .communication = [&] {
                                            self->set_node_id(pending);
                                        }});
    self = &nmt;
    bench.device->on_receive([&](const can::Frame& frame) { nmt.on_frame(frame); });
    nmt.boot();
    pending = 9;

    bench.send("000#8205");
    bench.run_for(1ms);
    EXPECT_EQ(bench.device_frames().back().frame, "709#00");
    EXPECT_EQ(nmt.node_id(), 9);
    bench.send("000#0105");
    bench.run_for(1ms);
    EXPECT_EQ(nmt.state(), NmtState::PreOperational);
    bench.send("000#0109");
    bench.run_for(1ms);
    EXPECT_EQ(nmt.state(), NmtState::Operational);
}

TEST_F(NmtSlaveTest, WithoutAValidNodeIdStaysInitialisingAndSendsNoBootUp) {
    nmt.set_node_id(255); // CiA 305: not configured
    nmt.boot();
    bench.run_for(1ms);
    EXPECT_EQ(nmt.state(), NmtState::Initialising);
    EXPECT_TRUE(bench.device_frames().empty());

    nmt.set_node_id(kNode);
    nmt.apply(NmtCommand::ResetCommunication);
    bench.run_for(1ms);
    EXPECT_EQ(nmt.state(), NmtState::PreOperational);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(1), "705#00"}}));
}

TEST(NmtMaster, SendsCommandToOneNodeOrToAll) {
    ServiceBench bench;
    NmtMaster master(*bench.tester);
    master.send(NmtCommand::Start, 5);
    master.send(NmtCommand::ResetCommunication);
    master.send(NmtCommand::EnterPreOperational, 127);
    bench.run_for(1ms);
    std::vector<std::string> frames;
    for (const Sent& sent : bench.sent_by("tester")) {
        frames.push_back(sent.frame);
    }
    EXPECT_EQ(frames, (std::vector<std::string>{"000#0105", "000#8200", "000#807F"}));
}

TEST(NmtMaster, RefusesANodeIdAbove127) {
    ServiceBench bench;
    NmtMaster master(*bench.tester);
    EXPECT_THROW(master.send(NmtCommand::Stop, 128), std::invalid_argument);
}

TEST(NmtMaster, DrivesSlavesThroughTheBus) {
    ServiceBench bench;
    auto other = bench.bus.connect("other");
    NmtSlave a(*bench.device, 5, {});
    NmtSlave b(*other, 6, {});
    bench.device->on_receive([&](const can::Frame& frame) { a.on_frame(frame); });
    other->on_receive([&](const can::Frame& frame) { b.on_frame(frame); });
    a.boot();
    b.boot();
    NmtMaster master(*bench.tester);

    master.send(NmtCommand::Start);
    master.send(NmtCommand::Stop, 6);
    bench.run_for(1ms);

    EXPECT_EQ(a.state(), NmtState::Operational);
    EXPECT_EQ(b.state(), NmtState::Stopped);
}

} // namespace
} // namespace eposp::canopen
