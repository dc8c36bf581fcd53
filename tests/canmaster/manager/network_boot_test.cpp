// The CiA 302 network boot-up (EPOS P firmware specification 8.1) on a virtual bus of plain
// CANopen slaves, judged by the errors it reports (table 1), the slaves' NMT states and the
// NMT commands on the bus.
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/nmt_master.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/manager/network_boot.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace eposp::manager {
namespace {

using namespace std::chrono_literals;
using canopen::NmtState;
using canopen::NodeId;

constexpr std::uint8_t kPort = 2;
constexpr std::uint32_t kDeviceType = 0x0002'0192;
constexpr canopen::LssAddress kIdentity{.vendor_id = 0xFB,
                                        .product_code = 0x6220'0000,
                                        .revision_number = 0x2126'0000,
                                        .serial_number = 0};
constexpr std::uint32_t kMandatorySlave =
    assignment::kSlave | assignment::kBootSlave | assignment::kMandatory;
constexpr std::uint32_t kOptionalSlave = assignment::kSlave | assignment::kBootSlave;
constexpr std::uint16_t kHeartbeatMs = 100;

/// A CANopen slave with an identity, a heartbeat (50 ms unless told) and a configuration date and
/// time in 0x1020 (CiA 301 7.5.2.24).
struct Slave {
    canopen::ObjectDictionary od;
    std::unique_ptr<can::VirtualPort> port;
    std::unique_ptr<canopen::Node> node;

    Slave(core::EventLoop& loop, can::VirtualBus& bus, NodeId id, canopen::LssAddress identity,
          std::uint32_t device_type, std::uint16_t heartbeat_ms = 50) {
        od.add_object(0x1020, "Verify Configuration", canopen::ObjectCode::Array);
        od.add_sub(0x1020, 1, "Configuration Date", canopen::DataType::Unsigned32,
                   canopen::Access::ReadWrite, canopen::encode(std::uint32_t{0x1234}));
        od.add_sub(0x1020, 2, "Configuration Time", canopen::DataType::Unsigned32,
                   canopen::Access::ReadWrite, canopen::encode(std::uint32_t{0x5678}));
        port = bus.connect("slave-" + std::to_string(id));
        canopen::NodeConfig config;
        config.node_id = id;
        config.device_type = device_type;
        config.identity = identity;
        node = std::make_unique<canopen::Node>(loop, *port, od, config);
        set_heartbeat(heartbeat_ms);
        node->start();
    }
    NmtState state() const { return node->nmt_state(); }
    /// The producer heartbeat time, also after a reset communication.
    void set_heartbeat(std::uint16_t ms) {
        canopen::SubObject& entry = *od.find(0x1017, 0);
        entry.default_value = canopen::encode(ms);
        entry.value = entry.default_value;
    }
};

/// The manager's node on port 2: SDO client, NMT master and heartbeat consumer on one port, and
/// a record of every NMT command on the bus.
struct Network {
    core::EventLoop loop;
    can::VirtualBus bus{loop};
    std::unique_ptr<can::VirtualPort> master_port = bus.connect("epos-p");
    std::unique_ptr<can::VirtualPort> monitor = bus.connect("monitor");
    canopen::ObjectDictionary master_od;
    canopen::SdoClient sdo{loop, *master_port};
    canopen::NmtMaster nmt{*master_port};
    std::unique_ptr<canopen::HeartbeatConsumer> heartbeat;
    std::map<NodeId, std::unique_ptr<Slave>> slaves;
    NetworkList list;
    std::unique_ptr<NetworkBoot> boot;
    std::vector<ManagerError> errors;
    std::vector<std::pair<std::uint8_t, NodeId>> nmt_commands;
    std::vector<NodeId> lost;
    bool master_operational = false;

    Network() {
        canopen::add_heartbeat_consumer_objects(master_od, 0x80);
        heartbeat = std::make_unique<canopen::HeartbeatConsumer>(
            loop, master_od, [](std::uint16_t) {}, kPort);
        heartbeat->set_nmt_state(NmtState::PreOperational);
        master_port->on_receive([this](const can::Frame& frame) {
            sdo.on_frame(frame);
            heartbeat->on_frame(frame);
        });
        monitor->on_receive([this](const can::Frame& frame) {
            if (frame.id == 0 && frame.dlc == 2) {
                nmt_commands.emplace_back(frame.data[0], frame.data[1]);
            }
        });
    }

    Slave& add_slave(NodeId id, canopen::LssAddress identity = kIdentity,
                     std::uint32_t device_type = kDeviceType) {
        auto slave = std::make_unique<Slave>(loop, bus, id, identity, device_type);
        Slave& added = *slave;
        slaves[id] = std::move(slave);
        return added;
    }

    /// Expects node `id` with the default identity and a heartbeat; 0x1016 watches it.
    SlaveEntry& expect(NodeId id, std::uint32_t assignment) {
        SlaveEntry entry;
        entry.node_id = id;
        entry.assignment = assignment;
        entry.device_type = kDeviceType;
        entry.identity = kIdentity;
        entry.heartbeat = std::chrono::milliseconds(kHeartbeatMs);
        const std::uint32_t consumer =
            std::uint32_t{kPort} << 24 | std::uint32_t{id} << 16 | kHeartbeatMs;
        EXPECT_EQ(master_od.write(0x1016, static_cast<std::uint8_t>(list.slaves.size() + 1),
                                  canopen::encode(consumer)),
                  canopen::AbortCode::None);
        list.slaves.push_back(entry);
        return list.slaves.back();
    }

    void start() {
        boot = std::make_unique<NetworkBoot>(
            loop, ManagerServices{sdo, nmt, *heartbeat},
            [this](const ManagerError& error) { errors.push_back(error); });
        boot->on_master_operational([this] { master_operational = true; });
        boot->on_slave_lost([this](NodeId node) { lost.push_back(node); });
        boot->start(list);
    }

    bool started_all() const {
        return std::ranges::find(nmt_commands, std::pair<std::uint8_t, NodeId>{0x01, 0}) !=
               nmt_commands.end();
    }
    bool started(NodeId node) const {
        return std::ranges::find(nmt_commands, std::pair<std::uint8_t, NodeId>{0x01, node}) !=
               nmt_commands.end();
    }
};

std::string listed(const std::vector<ManagerError>& errors) {
    std::ostringstream out;
    for (const ManagerError& e : errors) {
        out << "node " << int(e.node) << " code 0x" << std::hex << e.code << std::dec
            << (e.warning ? " (warning); " : "; ");
    }
    return out.str();
}

bool has_error(const std::vector<ManagerError>& errors, NodeId node, BootError error,
               bool warning) {
    return std::ranges::any_of(errors, [&](const ManagerError& e) {
        return e.node == node && e.code == static_cast<std::uint16_t>(error) &&
               e.warning == warning;
    });
}

TEST(NetworkBoot, AllGoodBootsEverySlaveAndStartsThemAllAtOnce) {
    Network network;
    network.add_slave(2);
    network.add_slave(3);
    network.expect(2, kMandatorySlave);
    network.expect(3, kOptionalSlave);
    network.start();
    network.loop.run_for(1s);

    EXPECT_TRUE(network.errors.empty()) << listed(network.errors);
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_EQ(network.boot->report().slaves.size(), 2u);
    EXPECT_EQ(network.nmt_commands.front(), (std::pair<std::uint8_t, NodeId>{0x82, 0}));
    EXPECT_TRUE(network.started_all());
    EXPECT_EQ(network.slaves[2]->state(), NmtState::Operational);
    EXPECT_EQ(network.slaves[3]->state(), NmtState::Operational);
    EXPECT_FALSE(network.master_operational); // 0x1F80 = 7: the application starts it
}

TEST(NetworkBoot, TheBootWaitsTheBootTimeBeforeItAsksTheSlaves) {
    Network network;
    network.add_slave(2);
    network.expect(2, kMandatorySlave);
    network.list.boot_time = 300ms;
    network.start();
    network.loop.run_for(290ms);
    EXPECT_TRUE(network.boot->report().slaves.empty());
    EXPECT_EQ(network.sdo.pending(2), 0u);
    network.loop.run_for(100ms);
    EXPECT_EQ(network.boot->report().slaves.size(), 1u);
}

struct Mismatch {
    const char* name;
    BootError error;
    canopen::LssAddress identity;
    std::uint32_t device_type;
};

class IdentityMismatch : public ::testing::TestWithParam<Mismatch> {};

TEST_P(IdentityMismatch, OnAMandatorySlaveStopsTheBootWithItsCode) {
    Network network;
    network.add_slave(2, GetParam().identity, GetParam().device_type);
    network.add_slave(3);
    network.expect(2, kMandatorySlave);
    network.expect(3, kOptionalSlave);
    network.start();
    network.loop.run_for(1s);

    EXPECT_TRUE(has_error(network.errors, 2, GetParam().error, false));
    EXPECT_FALSE(network.boot->report().network_started);
    EXPECT_TRUE(network.nmt_commands.size() == 1); // only the reset communication
    EXPECT_EQ(network.slaves[2]->state(), NmtState::PreOperational);
    EXPECT_EQ(network.slaves[3]->state(), NmtState::PreOperational);
}

TEST_P(IdentityMismatch, OnAnOptionalSlaveIsAWarningAndTheOthersStartOneByOne) {
    Network network;
    network.add_slave(2);
    network.add_slave(3, GetParam().identity, GetParam().device_type);
    network.expect(2, kMandatorySlave);
    network.expect(3, kOptionalSlave);
    network.start();
    network.loop.run_for(1s);

    EXPECT_TRUE(has_error(network.errors, 3, GetParam().error, true));
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_FALSE(network.started_all());
    EXPECT_TRUE(network.started(2));
    EXPECT_FALSE(network.started(3));
    EXPECT_EQ(network.slaves[2]->state(), NmtState::Operational);
    EXPECT_EQ(network.slaves[3]->state(), NmtState::PreOperational);
}

canopen::LssAddress with(canopen::LssPart part, std::uint32_t value) {
    canopen::LssAddress identity = kIdentity;
    identity.set_part(part, value);
    return identity;
}

INSTANTIATE_TEST_SUITE_P(
    Table1, IdentityMismatch,
    ::testing::Values(Mismatch{"DeviceType", BootError::DeviceType, kIdentity, 0x0002'0191},
                      Mismatch{"VendorId", BootError::VendorId,
                               with(canopen::LssPart::VendorId, 0xFC), kDeviceType},
                      Mismatch{"ProductCode", BootError::ProductCode,
                               with(canopen::LssPart::ProductCode, 0x7300'0000), kDeviceType},
                      Mismatch{"RevisionNumber", BootError::RevisionNumber,
                               with(canopen::LssPart::RevisionNumber, 0x2125'0000), kDeviceType}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(NetworkBoot, SerialNumberMismatchOnAMandatorySlave) {
    Network network;
    network.add_slave(2, with(canopen::LssPart::SerialNumber, 77));
    network.expect(2, kMandatorySlave).identity.serial_number = 78;
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(has_error(network.errors, 2, BootError::SerialNumber, false));
    EXPECT_FALSE(network.boot->report().network_started);
}

TEST(NetworkBoot, ZeroExpectedValuesAreNotChecked) {
    Network network;
    network.add_slave(2, with(canopen::LssPart::SerialNumber, 12345), 0x0001'0191);
    SlaveEntry& entry = network.expect(2, kMandatorySlave);
    entry.device_type = 0;
    entry.identity = {};
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(network.errors.empty());
    EXPECT_EQ(network.boot->report().slaves.front().device_type, 0x0001'0191u);
}

TEST(NetworkBoot, ConfigurationDateMismatchOnAMandatorySlave) {
    Network network;
    network.add_slave(2);
    SlaveEntry& entry = network.expect(2, kMandatorySlave);
    entry.configuration_date = 0x1234;
    entry.configuration_time = 0x5679; // the slave has 0x5678
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(has_error(network.errors, 2, BootError::ConfigurationDateTime, false));
    EXPECT_FALSE(network.boot->report().network_started);
}

TEST(NetworkBoot, MatchingConfigurationDateAndTimePass) {
    Network network;
    network.add_slave(2);
    SlaveEntry& entry = network.expect(2, kMandatorySlave);
    entry.configuration_date = 0x1234;
    entry.configuration_time = 0x5678;
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(network.errors.empty());
    EXPECT_TRUE(network.boot->report().network_started);
}

TEST(NetworkBoot, TheConfigurationIsWrittenBeforeTheSlaveStarts) {
    Network network;
    Slave& slave = network.add_slave(2);
    network.expect(2, kMandatorySlave).configuration = {
        {0x1017, 0, canopen::encode(std::uint16_t{40})}};
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(network.errors.empty());
    EXPECT_EQ(slave.od.get_as<std::uint16_t>(0x1017, 0), 40u);
}

TEST(NetworkBoot, AMissingMandatorySlaveIsNoAnswerAndHoldsTheStartBack) {
    Network network;
    network.add_slave(3);
    network.expect(2, kMandatorySlave);
    network.expect(3, kOptionalSlave);
    network.start();
    network.loop.run_for(3s);
    EXPECT_TRUE(has_error(network.errors, 2, BootError::NoAnswer, false));
    EXPECT_FALSE(network.boot->report().network_started);
    EXPECT_EQ(network.slaves[3]->state(), NmtState::PreOperational);
}

TEST(NetworkBoot, AMandatorySlaveThatBootsLateStartsTheNetwork) {
    Network network;
    network.expect(2, kMandatorySlave);
    network.start();
    network.loop.run_for(3s);
    ASSERT_FALSE(network.boot->report().network_started);

    network.add_slave(2); // powered up late: its boot-up message starts its boot
    network.loop.run_for(1s);
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_EQ(network.slaves[2]->state(), NmtState::Operational);
}

// The slave powers up while the manager's read of its 0x1000 goes unanswered, and produces no
// heartbeat until it is configured: its boot-up message alone must start its boot again, or the
// read's timeout leaves it failed for good.
TEST(NetworkBoot, ABootUpMessageDuringItsFailingBootStartsTheBootAgain) {
    Network network;
    network.expect(2, kMandatorySlave).configuration = {
        {0x1017, 0, canopen::encode(std::uint16_t{50})}};
    network.start();
    network.loop.run_for(600ms); // the boot time is over: 0x1000 is being read
    ASSERT_GT(network.sdo.pending(2), 0u);

    network.slaves[2] = std::make_unique<Slave>(network.loop, network.bus, 2, kIdentity,
                                                kDeviceType, /*heartbeat_ms=*/0);
    network.loop.run_for(3s);
    EXPECT_TRUE(network.boot->booted(2)) << listed(network.errors);
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_EQ(network.slaves[2]->state(), NmtState::Operational);
}

// Reset in the middle of its configuration, the slave loses what was written so far: the boot
// starts over and writes all of it, and no answer from before the reset is taken for a new one.
TEST(NetworkBoot, ASlaveThatResetsDuringItsConfigurationIsConfiguredFromTheStart) {
    Network network;
    Slave& slave = network.add_slave(2);
    SlaveEntry& entry = network.expect(2, kMandatorySlave);
    entry.configuration.push_back({0x1017, 0, canopen::encode(std::uint16_t{40})});
    for (std::uint16_t i = 0; i < 20; ++i) { // a long configuration, overwriting one object
        entry.configuration.push_back({0x1020, 1, canopen::encode(std::uint32_t{0x1234})});
    }
    network.start();
    for (int step = 0; step < 20'000 && slave.od.get_as<std::uint16_t>(0x1017, 0) != 40; ++step) {
        network.loop.run_for(100us);
    }
    network.loop.run_for(2ms);
    ASSERT_GT(network.sdo.pending(2), 0u) << "the configuration should still be running";

    slave.node->nmt().apply(canopen::NmtCommand::ResetNode);
    ASSERT_EQ(slave.od.get_as<std::uint16_t>(0x1017, 0), 50u); // back to its default
    network.loop.run_for(2s);
    EXPECT_TRUE(network.errors.empty()) << listed(network.errors);
    EXPECT_TRUE(network.boot->booted(2));
    EXPECT_EQ(slave.od.get_as<std::uint16_t>(0x1017, 0), 40u);
    EXPECT_EQ(slave.state(), NmtState::Operational);
}

TEST(NetworkBoot, AnOptionalSlaveThatBootsLateIsBootedAndStarted) {
    Network network;
    network.add_slave(2);
    network.expect(2, kMandatorySlave);
    network.expect(3, kOptionalSlave);
    network.start();
    network.loop.run_for(3s);
    ASSERT_TRUE(network.boot->report().network_started);
    EXPECT_TRUE(has_error(network.errors, 3, BootError::NoAnswer, true));

    network.add_slave(3);
    network.loop.run_for(1s);
    EXPECT_TRUE(network.boot->booted(3));
    EXPECT_TRUE(network.started(3));
    EXPECT_EQ(network.slaves[3]->state(), NmtState::Operational);
}

TEST(NetworkBoot, ASlaveThatRebootsMidRunIsBootedAndStartedAgain) {
    Network network;
    Slave& slave = network.add_slave(2);
    network.expect(2, kMandatorySlave);
    network.start();
    network.loop.run_for(1s);
    ASSERT_EQ(slave.state(), NmtState::Operational);

    slave.node->nmt().apply(canopen::NmtCommand::ResetNode); // e.g. its own watchdog
    network.loop.run_for(1s);
    EXPECT_EQ(network.lost, (std::vector<NodeId>{2}));
    EXPECT_TRUE(network.boot->booted(2));
    EXPECT_TRUE(network.started(2));
    EXPECT_EQ(slave.state(), NmtState::Operational);
}

TEST(NetworkBoot, HeartbeatLossMidRunIsALifeguardError) {
    Network network;
    Slave& slave = network.add_slave(2);
    network.expect(2, kMandatorySlave);
    network.start();
    network.loop.run_for(1s);
    ASSERT_TRUE(network.errors.empty());

    slave.od.set_as<std::uint16_t>(0x1017, 0, 0); // its heartbeat stops
    network.loop.run_for(1s);
    ASSERT_EQ(network.errors.size(), 1u);
    EXPECT_EQ(network.errors[0].node, 2);
    EXPECT_EQ(network.errors[0].code, kLifeguardError);
    EXPECT_EQ(network.lost, (std::vector<NodeId>{2}));
    EXPECT_FALSE(network.boot->booted(2));

    slave.od.set_as<std::uint16_t>(0x1017, 0, 50); // back: booted again at its next heartbeat
    network.loop.run_for(1s);
    EXPECT_TRUE(network.boot->booted(2));
}

TEST(NetworkBoot, NoHeartbeatWithinTheConsumerTimeIsAnErrorControlError) {
    Network network;
    Slave& slave = network.add_slave(2);
    slave.set_heartbeat(0);
    network.expect(2, kMandatorySlave);
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(has_error(network.errors, 2, BootError::ErrorControl, false));
    EXPECT_FALSE(network.boot->report().network_started);
}

TEST(NetworkBoot, AMandatoryNodeThatIsNotASlaveFailsAtOnce) {
    Network network;
    network.add_slave(2);
    network.expect(2, assignment::kMandatory);
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(has_error(network.errors, 2, BootError::NotSlave, false));
    EXPECT_FALSE(network.boot->report().network_started);
}

TEST(NetworkBoot, StartupBitsStartSlavesOneByOneAndTheMaster) {
    Network network;
    network.add_slave(2);
    network.add_slave(3);
    network.expect(2, kMandatorySlave);
    network.expect(3, kMandatorySlave);
    network.list.nmt_startup = nmt_startup::kMaster; // each node, master self-starting
    network.start();
    network.loop.run_for(1s);
    EXPECT_FALSE(network.started_all());
    EXPECT_TRUE(network.started(2));
    EXPECT_TRUE(network.started(3));
    EXPECT_TRUE(network.master_operational);
}

TEST(NetworkBoot, StartupBitThreeLeavesTheSlavesToTheApplication) {
    Network network;
    network.add_slave(2);
    network.expect(2, kMandatorySlave);
    network.list.nmt_startup |= nmt_startup::kDoNotStartSlaves;
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_EQ(network.slaves[2]->state(), NmtState::PreOperational);
}

TEST(NetworkBoot, AnEmptyNetworkListSendsNoNmtCommand) {
    Network network;
    network.add_slave(2);
    network.list.nmt_startup = nmt_startup::kMaster | nmt_startup::kStartAllNodes;
    network.start();
    network.loop.run_for(1s);
    EXPECT_TRUE(network.boot->report().network_started);
    EXPECT_TRUE(network.nmt_commands.empty());
    EXPECT_TRUE(network.master_operational);
    EXPECT_EQ(network.slaves[2]->state(), NmtState::PreOperational);
}

} // namespace
} // namespace eposp::manager
