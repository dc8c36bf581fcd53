// The LSS master (CiA 305, EPOS2 FW spec 7.4): its request frames byte for byte, round trips
// with LSS slaves on a virtual bus, and timeouts as values.

#include "lss_test_support.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/lss_master.hpp"
#include "can/virtual_bus_test_support.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::kAddress;
using testing::master_frame;
using testing::master_frame_u32;
using testing::slave_frame;
using testing::SlaveNode;

constexpr core::Duration kTimeout = 100ms; // LssMasterConfig's default

LssAddress with_serial(std::uint32_t serial) {
    LssAddress address = kAddress;
    address.serial_number = serial;
    return address;
}

/// Keeps the result of a request and the loop time at which it came.
template <typename T>
struct Outcome {
    std::optional<LssResult<T>> result;
    core::TimePoint at{};

    LssMaster::Callback<T> callback(const core::EventLoop& loop) {
        return [this, &loop](const LssResult<T>& r) {
            result = r;
            at = loop.now();
        };
    }
};

class LssMasterTest : public ::testing::Test {
protected:
    LssMasterTest() {
        master_port->on_receive([this](const can::Frame& frame) { master.on_frame(frame); });
    }

    SlaveNode& add_slave(const LssAddress& address, NodeId node_id = kLssUnconfiguredNodeId,
                         bool can_store = true) {
        slaves.push_back(std::make_unique<SlaveNode>(bus, "slave" + std::to_string(slaves.size()),
                                                     address, node_id, can_store));
        return *slaves.back();
    }

    /// The frames on the wire from `sender` since `first`.
    std::vector<can::Frame> sent_by(std::string_view sender, std::size_t first = 0) const {
        std::vector<can::Frame> frames;
        for (std::size_t i = first; i < wire.events.size(); ++i) {
            if (wire.events[i].sender == sender && !wire.events[i].frame.error) {
                frames.push_back(wire.events[i].frame);
            }
        }
        return frames;
    }

    /// Switches the slave with `address` to configuration through the master.
    void select(const LssAddress& address) {
        Outcome<void> selected;
        master.switch_state_selective(address, selected.callback(loop));
        loop.run_for(kTimeout);
        ASSERT_TRUE(selected.result && selected.result->ok());
    }

    core::EventLoop loop;
    can::VirtualBus bus{loop}; // 1 Mbit/s
    can::testing::WireLog wire{bus};
    std::unique_ptr<can::VirtualPort> master_port = bus.connect("master");
    LssMaster master{loop, *master_port};
    std::vector<std::unique_ptr<SlaveNode>> slaves;
};

TEST_F(LssMasterTest, SwitchStateSelectiveReachesOnlyTheSlaveWithThatAddress) {
    SlaveNode& a = add_slave(with_serial(1));
    SlaveNode& b = add_slave(with_serial(2));
    Outcome<void> selected;
    master.switch_state_selective(with_serial(2), selected.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(selected.result);
    EXPECT_TRUE(selected.result->ok());
    EXPECT_EQ(a.slave().state(), LssState::Waiting);
    EXPECT_EQ(b.slave().state(), LssState::Configuration);
    EXPECT_EQ(sent_by("master"),
              (std::vector<can::Frame>{
                  master_frame(LssCommand::SwitchStateSelectiveVendorId, {0xFB, 0, 0, 0}),
                  master_frame(LssCommand::SwitchStateSelectiveProductCode, {0, 0, 0x01, 0x20}),
                  master_frame(LssCommand::SwitchStateSelectiveRevisionNumber, {3, 0, 2, 0}),
                  master_frame(LssCommand::SwitchStateSelectiveSerialNumber, {2, 0, 0, 0})}));
    EXPECT_EQ(sent_by("slave1"),
              std::vector{slave_frame(LssCommand::SwitchStateSelectiveResponse)});
    EXPECT_TRUE(sent_by("slave0").empty());
}

TEST_F(LssMasterTest, AMissingAnswerIsNoAnswerAfterTheTimeout) {
    add_slave(with_serial(1));
    Outcome<void> selected;
    const core::TimePoint start = loop.now();
    master.switch_state_selective(with_serial(9), selected.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(selected.result);
    ASSERT_FALSE(selected.result->ok());
    EXPECT_EQ(selected.result->error(),
              (LssError{LssErrorKind::NoAnswer, LssCommand::SwitchStateSelectiveVendorId, 0, 0}));
    EXPECT_EQ(describe(selected.result->error()), "no LSS slave answered switch state selective");
    EXPECT_EQ(selected.at, start + kTimeout);
}

TEST_F(LssMasterTest, ConfigureNodeIdAndStoreConfigurationRoundTrip) {
    SlaveNode& node = add_slave(kAddress);
    select(kAddress);
    Outcome<void> configured;
    Outcome<void> stored;
    master.configure_node_id(5, configured.callback(loop));
    master.store_configuration(stored.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(configured.result && stored.result);
    EXPECT_TRUE(configured.result->ok());
    EXPECT_TRUE(stored.result->ok());
    EXPECT_EQ(node.slave().pending_node_id(), 5);
    EXPECT_EQ(node.stored, (LssConfiguration{5, 1'000'000}));
}

TEST_F(LssMasterTest, OutOfRangeNodeIdIsRefusedWithErrorCode1) {
    SlaveNode& node = add_slave(kAddress);
    select(kAddress);
    Outcome<void> configured;
    master.configure_node_id(128, configured.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(configured.result);
    ASSERT_FALSE(configured.result->ok());
    EXPECT_EQ(configured.result->error(),
              (LssError{LssErrorKind::Refused, LssCommand::ConfigureNodeId, 1, 0}));
    EXPECT_EQ(describe(configured.result->error()),
              "LSS slave refused configure node-ID: node-ID out of range (error code 1)");
    EXPECT_EQ(node.slave().pending_node_id(), kLssUnconfiguredNodeId);
}

TEST_F(LssMasterTest, UnsupportedBitTimingIsRefusedWithErrorCode1) {
    add_slave(kAddress);
    select(kAddress);
    Outcome<void> configured;
    master.configure_bit_timing(0, 5, configured.callback(loop)); // index 5 is reserved
    loop.run_for(kTimeout);
    ASSERT_TRUE(configured.result && !configured.result->ok());
    EXPECT_EQ(describe(configured.result->error()),
              "LSS slave refused configure bit timing parameters: bit timing not supported (error "
              "code 1)");
}

TEST_F(LssMasterTest, StoreConfigurationWithoutStorageIsRefusedAsNotSupported) {
    add_slave(kAddress, kLssUnconfiguredNodeId, /*can_store=*/false);
    select(kAddress);
    Outcome<void> stored;
    master.store_configuration(stored.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(stored.result && !stored.result->ok());
    EXPECT_EQ(stored.result->error().code, kLssStoreNotSupported);
    EXPECT_EQ(describe(stored.result->error()),
              "LSS slave refused store configuration: store configuration not supported (error "
              "code 1)");
}

TEST_F(LssMasterTest, InquireIdentityAndNodeIdRoundTrip) {
    add_slave(kAddress, 42);
    select(kAddress);
    std::vector<Outcome<std::uint32_t>> parts(kLssPartCount);
    for (std::size_t i = 0; i < kLssPartCount; ++i) {
        master.inquire_identity(static_cast<LssPart>(i), parts[i].callback(loop));
    }
    Outcome<NodeId> node_id;
    master.inquire_node_id(node_id.callback(loop));
    loop.run_for(kTimeout);
    for (std::size_t i = 0; i < kLssPartCount; ++i) {
        ASSERT_TRUE(parts[i].result && parts[i].result->ok());
        EXPECT_EQ(parts[i].result->value(), kAddress.part(static_cast<LssPart>(i)));
    }
    ASSERT_TRUE(node_id.result && node_id.result->ok());
    EXPECT_EQ(**node_id.result, 42);
}

TEST_F(LssMasterTest, RequestsRunOneAtATimeInTheOrderTheyWereMade) {
    add_slave(kAddress, 42);
    select(kAddress);
    const std::size_t first = wire.events.size();
    std::vector<std::string> order;
    master.inquire_identity(LssPart::SerialNumber,
                            [&](const LssResult<std::uint32_t>&) { order.push_back("serial"); });
    master.inquire_node_id([&](const LssResult<NodeId>&) { order.push_back("node-ID"); });
    master.inquire_identity(LssPart::VendorId,
                            [&](const LssResult<std::uint32_t>&) { order.push_back("vendor"); });
    loop.run_for(kTimeout);
    EXPECT_EQ(order, (std::vector<std::string>{"serial", "node-ID", "vendor"}));
    std::vector<std::uint8_t> specifiers;
    for (std::size_t i = first; i < wire.events.size(); ++i) {
        specifiers.push_back(wire.events[i].frame.data[0]);
    }
    EXPECT_EQ(specifiers, (std::vector<std::uint8_t>{0x5D, 0x5D, 0x5E, 0x5E, 0x5A, 0x5A}));
}

TEST_F(LssMasterTest, CallbacksNeverRunInsideTheCallThatMadeTheRequest) {
    bool done = false;
    master.switch_state_global(LssState::Configuration,
                               [&](const LssResult<void>&) { done = true; });
    EXPECT_FALSE(done);
    loop.run_for(1ms);
    EXPECT_TRUE(done);
    EXPECT_TRUE(master.idle());
}

// The frames of the services, byte for byte (EPOS2 FW spec 7.4.2).
struct RequestCase {
    std::string name;
    std::function<void(LssMaster&)> make;
    can::Frame frame;
};

void PrintTo(const RequestCase& c, std::ostream* os) {
    *os << c.name;
}

class LssMasterRequestFrame : public LssMasterTest,
                              public ::testing::WithParamInterface<RequestCase> {};

TEST_P(LssMasterRequestFrame, IsTheCia305Layout) {
    const auto listener = bus.connect("listener"); // acknowledges the frames
    GetParam().make(master);
    loop.run_for(1s);
    const std::vector<can::Frame> frames = sent_by("master");
    ASSERT_FALSE(frames.empty());
    EXPECT_EQ(frames[0], GetParam().frame);
}

INSTANTIATE_TEST_SUITE_P(
    EveryService, LssMasterRequestFrame,
    ::testing::Values(
        RequestCase{"SwitchStateGlobalWaiting",
                    [](LssMaster& m) { m.switch_state_global(LssState::Waiting); },
                    master_frame(LssCommand::SwitchStateGlobal, {0})},
        RequestCase{"SwitchStateGlobalConfiguration",
                    [](LssMaster& m) { m.switch_state_global(LssState::Configuration); },
                    master_frame(LssCommand::SwitchStateGlobal, {1})},
        RequestCase{"ConfigureNodeId",
                    [](LssMaster& m) { m.configure_node_id(0x7F, [](const LssResult<void>&) {}); },
                    master_frame(LssCommand::ConfigureNodeId, {0x7F})},
        RequestCase{
            "ConfigureBitTiming",
            [](LssMaster& m) { m.configure_bit_timing(0, 4, [](const LssResult<void>&) {}); },
            master_frame(LssCommand::ConfigureBitTiming, {0, 4})},
        RequestCase{"ActivateBitTiming", [](LssMaster& m) { m.activate_bit_timing(0x0102, {}); },
                    master_frame(LssCommand::ActivateBitTiming, {0x02, 0x01})},
        RequestCase{"StoreConfiguration",
                    [](LssMaster& m) { m.store_configuration([](const LssResult<void>&) {}); },
                    master_frame(LssCommand::StoreConfiguration)},
        RequestCase{"InquireRevisionNumber",
                    [](LssMaster& m) {
                        m.inquire_identity(LssPart::RevisionNumber,
                                           [](const LssResult<std::uint32_t>&) {});
                    },
                    master_frame(LssCommand::InquireRevisionNumber)},
        RequestCase{"InquireNodeId",
                    [](LssMaster& m) { m.inquire_node_id([](const LssResult<NodeId>&) {}); },
                    master_frame(LssCommand::InquireNodeId)},
        RequestCase{
            "IdentifyNonConfiguredRemoteSlave",
            [](LssMaster& m) { m.identify_non_configured_slaves([](const LssResult<bool>&) {}); },
            master_frame(LssCommand::IdentifyNonConfiguredRemoteSlave)},
        RequestCase{"Fastscan",
                    [](LssMaster& m) {
                        m.fastscan({0xAABBCCDD, 12, LssPart::ProductCode, LssPart::RevisionNumber},
                                   [](const LssResult<bool>&) {});
                    },
                    master_frame(LssCommand::Fastscan, {0xDD, 0xCC, 0xBB, 0xAA, 12, 1, 2})}),
    [](const ::testing::TestParamInfo<RequestCase>& param) { return param.param.name; });

TEST_F(LssMasterTest, IdentifyRemoteSlavesSendsTheRangeAndCollectsAnswersForTheWholeTimeout) {
    add_slave(with_serial(10));
    add_slave(with_serial(20));
    add_slave(with_serial(30));
    Outcome<bool> identified;
    const core::TimePoint start = loop.now();
    master.identify_remote_slaves(
        {kAddress.vendor_id, kAddress.product_code, 0, 0xFFFFFFFF, 15, 30},
        identified.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(identified.result && identified.result->ok());
    EXPECT_TRUE(**identified.result);
    EXPECT_EQ(identified.at, start + kTimeout);
    EXPECT_EQ(
        sent_by("master"),
        (std::vector<can::Frame>{
            master_frame_u32(LssCommand::IdentifyRemoteSlaveVendorId, kAddress.vendor_id),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveProductCode, kAddress.product_code),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveRevisionLow, 0),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveRevisionHigh, 0xFFFFFFFF),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveSerialLow, 15),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveSerialHigh, 30)}));
    EXPECT_TRUE(sent_by("slave0").empty());
    EXPECT_EQ(sent_by("slave1"), std::vector{slave_frame(LssCommand::IdentifySlave)});
    EXPECT_EQ(sent_by("slave2"), std::vector{slave_frame(LssCommand::IdentifySlave)});

    Outcome<bool> nobody;
    master.identify_remote_slaves(
        {kAddress.vendor_id, kAddress.product_code, 0, 0xFFFFFFFF, 31, 99}, nobody.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(nobody.result && nobody.result->ok());
    EXPECT_FALSE(**nobody.result);
}

TEST_F(LssMasterTest, IdentifyNonConfiguredSlavesTellsWhetherAnyIsLeft) {
    add_slave(with_serial(1), 3);
    Outcome<bool> before;
    master.identify_non_configured_slaves(before.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(before.result && before.result->ok());
    EXPECT_FALSE(**before.result);

    add_slave(with_serial(2));
    Outcome<bool> after;
    master.identify_non_configured_slaves(after.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(after.result && after.result->ok());
    EXPECT_TRUE(**after.result);
}

// EPOS2 FW spec 7.4.2.5: nobody sends during the two switch delays.
TEST_F(LssMasterTest, ActivateBitTimingSwitchesAfterOneDelayAndResumesAfterTwo) {
    SlaveNode& node = add_slave(kAddress);
    select(kAddress);
    Outcome<void> configured;
    master.configure_bit_timing(0, *lss_bit_timing_index(250'000), configured.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(configured.result && configured.result->ok());

    const core::TimePoint start = loop.now();
    std::optional<core::TimePoint> switched;
    Outcome<void> activated;
    Outcome<std::uint32_t> serial;
    master.activate_bit_timing(
        50, [&] { switched = loop.now(); }, activated.callback(loop));
    master.inquire_identity(LssPart::SerialNumber, serial.callback(loop));
    const std::size_t first = wire.events.size();
    loop.run_for(1s);

    EXPECT_EQ(switched, start + 50ms);
    EXPECT_EQ(activated.at, start + 100ms);
    EXPECT_EQ(node.switched_bit_rates, std::vector<std::uint32_t>{250'000});
    EXPECT_EQ(node.slave().active_bit_rate(), 250'000U);
    ASSERT_TRUE(serial.result && serial.result->ok());
    // The inquiry waited for the end of the second switch delay.
    ASSERT_EQ(wire.events.size(), first + 3);
    EXPECT_EQ(wire.events[first + 1].frame, master_frame(LssCommand::InquireSerialNumber));
    EXPECT_EQ(wire.events[first + 1].start, start + 100ms);
}

// A slave that answers as the test says: raw frames into the master.
class LssMasterRawSlaveTest : public LssMasterTest {
protected:
    LssMasterRawSlaveTest() {
        raw->on_receive([this](const can::Frame& frame) {
            if (reply) {
                raw->send(reply(frame));
            }
        });
    }
    std::unique_ptr<can::VirtualPort> raw = bus.connect("raw");
    std::function<can::Frame(const can::Frame&)> reply;
};

TEST_F(LssMasterRawSlaveTest, ManufacturerSpecificErrorCarriesTheSpecificErrorByte) {
    reply = [](const can::Frame&) {
        return slave_frame(LssCommand::ConfigureNodeId, {0xFF, 7});
    };
    Outcome<void> configured;
    master.configure_node_id(3, configured.callback(loop));
    loop.run_for(kTimeout);
    ASSERT_TRUE(configured.result && !configured.result->ok());
    EXPECT_EQ(configured.result->error(),
              (LssError{LssErrorKind::Refused, LssCommand::ConfigureNodeId, 0xFF, 7}));
    EXPECT_EQ(
        describe(configured.result->error()),
        "LSS slave refused configure node-ID: manufacturer-specific error 7 (error code 255)");
}

TEST_F(LssMasterRawSlaveTest, AnswersOfAnotherServiceOrMalformedAreIgnored) {
    reply = [](const can::Frame& request) {
        return request.data[0] == 0x5A
                   ? lss_frame_u32(kLssSlaveCobId, LssCommand::InquireProductCode, 1)
                   : can::Frame::data_frame(kLssSlaveCobId, {0x5B, 1, 0, 0});
    };
    Outcome<std::uint32_t> vendor;
    Outcome<std::uint32_t> product;
    master.inquire_identity(LssPart::VendorId, vendor.callback(loop));
    master.inquire_identity(LssPart::ProductCode, product.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(vendor.result && product.result);
    EXPECT_EQ(vendor.result->error().kind, LssErrorKind::NoAnswer);
    EXPECT_EQ(product.result->error().kind, LssErrorKind::NoAnswer); // DLC 4, not LSS
}

TEST_F(LssMasterTest, APortThatRefusesTheRequestGivesNotSent) {
    add_slave(kAddress);
    master_port->force_error_state(can::ErrorState::BusOff);
    Outcome<NodeId> node_id;
    master.inquire_node_id(node_id.callback(loop));
    loop.run_for(1ms);
    ASSERT_TRUE(node_id.result && !node_id.result->ok());
    EXPECT_EQ(node_id.result->error().kind, LssErrorKind::NotSent);
    EXPECT_EQ(describe(node_id.result->error()),
              "the CAN port did not take the LSS request inquire node-ID");
}

TEST_F(LssMasterTest, ActivateBitTimingThatIsNotSentNeverSwitches) {
    add_slave(kAddress);
    master_port->force_error_state(can::ErrorState::BusOff);
    bool switched = false;
    Outcome<void> activated;
    master.activate_bit_timing(
        10, [&] { switched = true; }, activated.callback(loop));
    loop.run_for(1s);
    ASSERT_TRUE(activated.result && !activated.result->ok());
    EXPECT_EQ(activated.result->error().kind, LssErrorKind::NotSent);
    EXPECT_FALSE(switched);
}

} // namespace
} // namespace eposp::canopen
