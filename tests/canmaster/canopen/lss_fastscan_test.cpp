// Node-ID assignment over LSS (CiA 305): fastscan over a virtual bus with several non-configured
// slaves, and the switch-state-selective alternative.

#include "lss_test_support.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/lss_fastscan.hpp"
#include "eposp/canopen/lss_master.hpp"
#include "can/virtual_bus_test_support.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::kAddress;
using testing::SlaveNode;

constexpr core::Duration kWindow = 100ms; // LssMasterConfig's default timeout
/// Requests in one round of an unknown address: the confirm, then 32 bits and a confirm of
/// each of the four parts.
constexpr int kRequestsPerRound = 1 + 4 * 33;

LssAddress with_serial(std::uint32_t serial) {
    LssAddress address = kAddress;
    address.serial_number = serial;
    return address;
}

NodeIdAllocator counting_from(NodeId first) {
    return [next = first](const LssAddress&) mutable {
        return next++;
    };
}

class LssFastscanTest : public ::testing::Test {
protected:
    LssFastscanTest() {
        master_port->on_receive([this](const can::Frame& frame) { master.on_frame(frame); });
    }

    SlaveNode& add_slave(const LssAddress& address, NodeId node_id = kLssUnconfiguredNodeId,
                         bool can_store = true) {
        slaves.push_back(std::make_unique<SlaveNode>(bus, "slave" + std::to_string(slaves.size()),
                                                     address, node_id, can_store));
        return *slaves.back();
    }

    /// Runs the loop until `report` is set, at most 10 virtual minutes.
    void run_until(const std::optional<LssAssignmentReport>& report) {
        for (int second = 0; second < 600 && !report; ++second) {
            loop.run_for(1s);
        }
    }

    std::optional<LssAssignmentReport> scan(NodeIdAllocator allocate) {
        std::optional<LssAssignmentReport> report;
        fastscan.scan(std::move(allocate),
                      [&](const LssAssignmentReport& result) { report = result; });
        run_until(report);
        return report;
    }

    std::optional<LssAssignmentReport> assign(std::vector<LssAssignment> targets) {
        std::optional<LssAssignmentReport> report;
        fastscan.assign(std::move(targets),
                        [&](const LssAssignmentReport& result) { report = result; });
        run_until(report);
        return report;
    }

    int fastscan_requests() const {
        return static_cast<int>(std::count_if(
            wire.events.begin(), wire.events.end(), [](const can::testing::RecordedEvent& event) {
                return event.frame.id == kLssMasterCobId &&
                       event.frame.data[0] == static_cast<std::uint8_t>(LssCommand::Fastscan);
            }));
    }

    core::EventLoop loop;
    can::VirtualBus bus{loop}; // 1 Mbit/s
    can::testing::WireLog wire{bus};
    std::unique_ptr<can::VirtualPort> master_port = bus.connect("master");
    LssMaster master{loop, *master_port};
    LssFastscan fastscan{master};
    std::vector<std::unique_ptr<SlaveNode>> slaves;
};

TEST_F(LssFastscanTest, FindsEveryNonConfiguredSlaveAndGivesEachANodeId) {
    const std::vector<std::uint32_t> serials = {0x5A5A'0001, 0x0000'0007, 0xFFFF'FFFE, 0x1234'5678,
                                                0x8000'0000};
    for (const std::uint32_t serial : serials) {
        add_slave(with_serial(serial));
    }
    // A configured slave with the lowest address takes no part.
    SlaveNode& configured = add_slave(with_serial(1), 3);

    const std::optional<LssAssignmentReport> report = scan(counting_from(10));

    ASSERT_TRUE(report);
    ASSERT_TRUE(report->complete()) << report->failure->message;
    // Sending each bit under test as 0 finds the lowest address first.
    std::vector<std::uint32_t> sorted = serials;
    std::sort(sorted.begin(), sorted.end());
    std::vector<LssAssignment> expected;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        expected.push_back({with_serial(sorted[i]), static_cast<NodeId>(10 + i)});
    }
    EXPECT_EQ(report->assigned, expected);
    for (std::size_t i = 0; i < serials.size(); ++i) {
        LssSlave& slave = slaves[i]->slave();
        const auto found =
            std::find_if(expected.begin(), expected.end(),
                         [&](const LssAssignment& a) { return a.address == slave.address(); });
        ASSERT_NE(found, expected.end());
        // Its first node-ID made the device reset communication: it is active already.
        EXPECT_EQ(slave.active_node_id(), found->node_id);
        EXPECT_EQ(slave.state(), LssState::Waiting);
    }
    EXPECT_EQ(configured.slave().active_node_id(), 3);
    EXPECT_EQ(configured.slave().pending_node_id(), 3);

    // Every request waits one window; the node-ID configuration adds little.
    EXPECT_EQ(fastscan_requests(), 5 * kRequestsPerRound + 1);
    EXPECT_GE(loop.now() - core::TimePoint{}, (5 * kRequestsPerRound + 1) * kWindow);
    EXPECT_LT(loop.now() - core::TimePoint{}, (5 * kRequestsPerRound + 1) * kWindow + 2s);

    std::optional<LssResult<bool>> left;
    master.identify_non_configured_slaves([&](const LssResult<bool>& r) { left = r; });
    loop.run_for(1s);
    ASSERT_TRUE(left && left->ok());
    EXPECT_FALSE(**left);
}

TEST_F(LssFastscanTest, FindsSlavesThatDifferInEveryPartInAddressOrder) {
    LssAddress other_vendor = kAddress;
    other_vendor.vendor_id = 0x0000'0100;
    LssAddress other_product = kAddress;
    other_product.product_code = 0x1000'0000;
    LssAddress other_revision = kAddress;
    other_revision.revision_number = 0x0001'0000;
    for (const LssAddress& address : {kAddress, other_vendor, other_product, other_revision}) {
        add_slave(address);
    }
    const std::optional<LssAssignmentReport> report = scan(counting_from(1));
    ASSERT_TRUE(report && report->complete());
    EXPECT_EQ(report->assigned,
              (std::vector<LssAssignment>{
                  {other_product, 1}, {other_revision, 2}, {kAddress, 3}, {other_vendor, 4}}));
}

TEST_F(LssFastscanTest, KnownPartsAreConfirmedWithOneRequestEach) {
    LssFastscanConfig config;
    config.vendor_id = kAddress.vendor_id;
    config.product_code = kAddress.product_code;
    config.revision_number = kAddress.revision_number;
    LssFastscan known{master, config};
    add_slave(with_serial(0x10));
    add_slave(with_serial(0x20));
    std::optional<LssAssignmentReport> report;
    known.scan(counting_from(1), [&](const LssAssignmentReport& result) { report = result; });
    run_until(report);
    ASSERT_TRUE(report && report->complete());
    EXPECT_EQ(report->assigned.size(), 2U);
    EXPECT_EQ(fastscan_requests(), 2 * (1 + 3 + 33) + 1);
}

TEST_F(LssFastscanTest, AKnownPartThatNoSlaveHasStopsTheScanWithTheReason) {
    LssFastscanConfig config;
    config.vendor_id = 0x99;
    LssFastscan known{master, config};
    add_slave(kAddress);
    std::optional<LssAssignmentReport> report;
    known.scan(counting_from(1), [&](const LssAssignmentReport& result) { report = result; });
    run_until(report);
    ASSERT_TRUE(report && !report->complete());
    EXPECT_EQ(report->failure->message,
              "LSS fastscan: no non-configured slave has the vendor-ID 0x00000099");
}

TEST_F(LssFastscanTest, WithoutNonConfiguredSlavesItEndsAfterOneConfirm) {
    add_slave(with_serial(1), 5);
    const std::optional<LssAssignmentReport> report = scan(counting_from(1));
    ASSERT_TRUE(report && report->complete());
    EXPECT_TRUE(report->assigned.empty());
    EXPECT_EQ(fastscan_requests(), 1);
}

TEST_F(LssFastscanTest, StoresEachNodeIdWhenConfiguredTo) {
    LssFastscanConfig config;
    config.store_configuration = true;
    LssFastscan storing{master, config};
    SlaveNode& a = add_slave(with_serial(1));
    SlaveNode& b = add_slave(with_serial(2));
    std::optional<LssAssignmentReport> report;
    storing.scan(counting_from(20), [&](const LssAssignmentReport& result) { report = result; });
    run_until(report);
    ASSERT_TRUE(report && report->complete());
    EXPECT_EQ(a.stored, (LssConfiguration{20, 1'000'000}));
    EXPECT_EQ(b.stored, (LssConfiguration{21, 1'000'000}));
}

TEST_F(LssFastscanTest, ASlaveThatCannotStoreStopsTheScanAndIsLeftInWaiting) {
    LssFastscanConfig config;
    config.store_configuration = true;
    LssFastscan storing{master, config};
    SlaveNode& node = add_slave(kAddress, kLssUnconfiguredNodeId, /*can_store=*/false);
    std::optional<LssAssignmentReport> report;
    storing.scan(counting_from(20), [&](const LssAssignmentReport& result) { report = result; });
    run_until(report);
    loop.run_for(1s);
    ASSERT_TRUE(report && !report->complete());
    EXPECT_TRUE(report->assigned.empty());
    EXPECT_EQ(report->failure->message,
              "LSS slave refused store configuration: store configuration not supported (error "
              "code 1) (" +
                  to_string(kAddress) + ")");
    EXPECT_EQ(node.slave().state(), LssState::Waiting);
}

TEST_F(LssFastscanTest, AnInvalidNodeIdFromTheAllocatorStopsTheScan) {
    SlaveNode& node = add_slave(kAddress);
    const std::optional<LssAssignmentReport> report =
        scan([](const LssAddress&) { return NodeId{0}; });
    loop.run_for(1s);
    ASSERT_TRUE(report && !report->complete());
    EXPECT_EQ(report->failure->message,
              "no valid node-ID (0) for the LSS slave with vendor-ID 0x000000FB, product code "
              "0x20010000, revision number 0x00020003, serial number 0x12345678");
    EXPECT_EQ(node.slave().state(), LssState::Waiting);
    EXPECT_EQ(node.slave().pending_node_id(), kLssUnconfiguredNodeId);
}

TEST_F(LssFastscanTest, KnownAddressesAreAssignedThroughSwitchStateSelective) {
    SlaveNode& a = add_slave(with_serial(1));
    SlaveNode& b = add_slave(with_serial(2));
    SlaveNode& renumbered = add_slave(with_serial(3), 7);
    const std::optional<LssAssignmentReport> report =
        assign({{with_serial(3), 30}, {with_serial(1), 31}});
    ASSERT_TRUE(report && report->complete());
    EXPECT_EQ(report->assigned,
              (std::vector<LssAssignment>{{with_serial(3), 30}, {with_serial(1), 31}}));
    EXPECT_EQ(a.slave().active_node_id(), 31);
    EXPECT_EQ(b.slave().pending_node_id(), kLssUnconfiguredNodeId);
    // A node that had a node-ID keeps it until its next reset communication.
    EXPECT_EQ(renumbered.slave().active_node_id(), 7);
    EXPECT_EQ(renumbered.slave().pending_node_id(), 30);
    EXPECT_EQ(fastscan_requests(), 0);
}

TEST_F(LssFastscanTest, AnUnknownAddressStopsTheAssignmentWithTheReason) {
    add_slave(with_serial(1));
    const std::optional<LssAssignmentReport> report =
        assign({{with_serial(1), 5}, {with_serial(9), 6}});
    ASSERT_TRUE(report && !report->complete());
    EXPECT_EQ(report->assigned, (std::vector<LssAssignment>{{with_serial(1), 5}}));
    EXPECT_EQ(report->failure->message,
              "no LSS slave answered switch state selective (" + to_string(with_serial(9)) + ")");
}

TEST_F(LssFastscanTest, StartingWhileRunningIsAProgrammingError) {
    add_slave(kAddress);
    fastscan.scan(counting_from(1), [](const LssAssignmentReport&) {});
    EXPECT_TRUE(fastscan.running());
    EXPECT_THROW(fastscan.assign({}, [](const LssAssignmentReport&) {}), std::logic_error);
}

TEST_F(LssFastscanTest, DestroyingTheScanAbandonsItWithoutItsCallback) {
    add_slave(kAddress);
    bool called = false;
    auto scan = std::make_unique<LssFastscan>(master);
    scan->scan(counting_from(1), [&](const LssAssignmentReport&) { called = true; });
    loop.run_for(1s);
    scan.reset();
    loop.run_for(60s);
    EXPECT_FALSE(called);
    EXPECT_TRUE(master.idle());
}

} // namespace
} // namespace eposp::canopen
