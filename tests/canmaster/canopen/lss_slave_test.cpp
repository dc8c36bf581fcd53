// Conformance tests of the LSS slave (CiA 305, EPOS2 FW spec 7.4): raw request frames on a
// virtual bus, every answer checked byte for byte and for its time.

#include "lss_test_support.hpp"
#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/lss_slave.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "can/virtual_bus_test_support.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::kAddress;
using testing::master_frame;
using testing::master_frame_u32;
using testing::slave_frame;

constexpr std::uint32_t kBitrate = 1'000'000;
constexpr LssConfiguration kUnconfigured{kLssUnconfiguredNodeId, kBitrate};

LssSlaveConfig slave_config(LssConfiguration initial, bool only_when_nmt_stopped = false) {
    LssSlaveConfig config;
    config.initial = initial;
    config.only_when_nmt_stopped = only_when_nmt_stopped;
    return config;
}

class LssSlaveTest : public ::testing::Test {
protected:
    /// Creates the slave; tests that need other settings or hooks call it again first.
    void make_slave(LssSlaveConfig config = slave_config(kUnconfigured), LssSlaveHooks hooks = {}) {
        slave.reset();
        slave = std::make_unique<LssSlave>(loop, *device, kAddress, config, std::move(hooks));
        device->on_receive([this](const can::Frame& frame) { slave->on_frame(frame); });
    }

    /// Sends `request` from the master's port and returns every answer. An answer is sent at
    /// once: it starts when the request's intermission ends.
    std::vector<can::Frame> exchange(const can::Frame& request) {
        inbox.frames.clear();
        inbox.times.clear();
        const core::TimePoint start = loop.now();
        tester->send(request);
        loop.run_for(50ms);
        if (!inbox.frames.empty()) {
            EXPECT_EQ(inbox.times[0], start + can::frame_duration(request, kBitrate) +
                                          testing::time_to_receive(inbox.frames[0], kBitrate));
        }
        return inbox.frames;
    }

    /// The one answer to `request`, or nullopt when the slave stays silent.
    std::optional<can::Frame> answer(const can::Frame& request) {
        const std::vector<can::Frame> answers = exchange(request);
        EXPECT_LE(answers.size(), 1U);
        return answers.empty() ? std::nullopt : std::optional(answers[0]);
    }

    void to_configuration() {
        exchange(master_frame(LssCommand::SwitchStateGlobal, {1}));
        ASSERT_EQ(slave->state(), LssState::Configuration);
    }

    core::EventLoop loop;
    can::VirtualBus bus{loop}; // 1 Mbit/s
    std::unique_ptr<can::VirtualPort> tester = bus.connect("master");
    std::unique_ptr<can::VirtualPort> device = bus.connect("slave");
    can::testing::Inbox inbox{*tester, loop};
    std::unique_ptr<LssSlave> slave;

    void SetUp() override { make_slave(); }
};

TEST_F(LssSlaveTest, StartsInWaitingWithItsStoredConfigurationActiveAndPending) {
    make_slave(slave_config({42, 500'000}));
    EXPECT_EQ(slave->state(), LssState::Waiting);
    EXPECT_EQ(slave->active_node_id(), 42);
    EXPECT_EQ(slave->pending_node_id(), 42);
    EXPECT_EQ(slave->active_bit_rate(), 500'000U);
    EXPECT_EQ(slave->pending_bit_rate(), 500'000U);
    EXPECT_EQ(slave->address(), kAddress);
    EXPECT_FALSE(slave->silent());
}

TEST_F(LssSlaveTest, SwitchStateGlobalEntersConfigurationAndWaitingWithoutAnswer) {
    EXPECT_TRUE(exchange(master_frame(LssCommand::SwitchStateGlobal, {1})).empty());
    EXPECT_EQ(slave->state(), LssState::Configuration);
    EXPECT_TRUE(exchange(master_frame(LssCommand::SwitchStateGlobal, {0})).empty());
    EXPECT_EQ(slave->state(), LssState::Waiting);
}

TEST_F(LssSlaveTest, SwitchStateGlobalIgnoresUndefinedModes) {
    exchange(master_frame(LssCommand::SwitchStateGlobal, {2}));
    EXPECT_EQ(slave->state(), LssState::Waiting);
    to_configuration();
    exchange(master_frame(LssCommand::SwitchStateGlobal, {0xFF}));
    EXPECT_EQ(slave->state(), LssState::Configuration);
}

std::vector<can::Frame> selective_frames(const LssAddress& address) {
    return {
        master_frame_u32(LssCommand::SwitchStateSelectiveVendorId, address.vendor_id),
        master_frame_u32(LssCommand::SwitchStateSelectiveProductCode, address.product_code),
        master_frame_u32(LssCommand::SwitchStateSelectiveRevisionNumber, address.revision_number),
        master_frame_u32(LssCommand::SwitchStateSelectiveSerialNumber, address.serial_number)};
}

TEST_F(LssSlaveTest, SwitchStateSelectiveWithItsAddressAnswers0x44AndEntersConfiguration) {
    const std::vector<can::Frame> frames = selective_frames(kAddress);
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
        EXPECT_TRUE(exchange(frames[i]).empty());
        EXPECT_EQ(slave->state(), LssState::Waiting);
    }
    EXPECT_EQ(answer(frames.back()), slave_frame(LssCommand::SwitchStateSelectiveResponse));
    EXPECT_EQ(slave->state(), LssState::Configuration);
}

class LssSlaveSelectiveMismatch : public LssSlaveTest,
                                  public ::testing::WithParamInterface<LssPart> {};

TEST_P(LssSlaveSelectiveMismatch, AnotherAddressLeavesTheSlaveSilentInWaiting) {
    LssAddress other = kAddress;
    other.set_part(GetParam(), kAddress.part(GetParam()) + 1);
    for (const can::Frame& frame : selective_frames(other)) {
        EXPECT_TRUE(exchange(frame).empty());
    }
    EXPECT_EQ(slave->state(), LssState::Waiting);
}

INSTANTIATE_TEST_SUITE_P(EveryPart, LssSlaveSelectiveMismatch,
                         ::testing::Values(LssPart::VendorId, LssPart::ProductCode,
                                           LssPart::RevisionNumber, LssPart::SerialNumber));

TEST_F(LssSlaveTest, SwitchStateSelectiveOutOfOrderStartsOver) {
    const std::vector<can::Frame> frames = selective_frames(kAddress);
    for (const std::size_t i : {0, 2, 1, 3}) {
        EXPECT_TRUE(exchange(frames[i]).empty());
    }
    EXPECT_EQ(slave->state(), LssState::Waiting);
    // A vendor-ID always starts a new sequence, so the complete one that follows works.
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
        exchange(frames[i]);
    }
    EXPECT_EQ(answer(frames.back()), slave_frame(LssCommand::SwitchStateSelectiveResponse));
}

TEST_F(LssSlaveTest, SwitchStateSelectiveIsIgnoredInConfiguration) {
    to_configuration();
    for (const can::Frame& frame : selective_frames(kAddress)) {
        EXPECT_TRUE(exchange(frame).empty());
    }
}

// EPOS2 FW spec 7.4.1, table 7-66: configuration-only services are ignored in waiting.
class LssSlaveConfigurationOnly : public LssSlaveTest,
                                  public ::testing::WithParamInterface<can::Frame> {};

TEST_P(LssSlaveConfigurationOnly, IsIgnoredInWaiting) {
    LssSlaveHooks hooks;
    hooks.switch_bit_rate = [](std::uint32_t) {
        FAIL() << "bit rate switched in waiting";
    };
    hooks.store_configuration = [](const LssConfiguration&) {
        ADD_FAILURE() << "stored in waiting";
        return LssStoreResult::Stored;
    };
    make_slave(slave_config(kUnconfigured), hooks);
    EXPECT_TRUE(exchange(GetParam()).empty());
    EXPECT_EQ(slave->state(), LssState::Waiting);
    EXPECT_EQ(slave->pending_node_id(), kLssUnconfiguredNodeId);
    EXPECT_EQ(slave->pending_bit_rate(), kBitrate);
    EXPECT_FALSE(slave->silent());
}

INSTANTIATE_TEST_SUITE_P(Table7_66, LssSlaveConfigurationOnly,
                         ::testing::Values(master_frame(LssCommand::ConfigureNodeId, {5}),
                                           master_frame(LssCommand::ConfigureBitTiming, {0, 2}),
                                           master_frame(LssCommand::ActivateBitTiming, {10, 0}),
                                           master_frame(LssCommand::StoreConfiguration),
                                           master_frame(LssCommand::InquireVendorId),
                                           master_frame(LssCommand::InquireProductCode),
                                           master_frame(LssCommand::InquireRevisionNumber),
                                           master_frame(LssCommand::InquireSerialNumber),
                                           master_frame(LssCommand::InquireNodeId)));

struct NodeIdCase {
    NodeId requested;
    std::uint8_t error_code;
};

class LssSlaveConfigureNodeId : public LssSlaveTest,
                                public ::testing::WithParamInterface<NodeIdCase> {};

// EPOS2 FW spec 7.4.2.3: error code 0 success, 1 node-ID out of range; CiA 305 allows 0xFF.
TEST_P(LssSlaveConfigureNodeId, AnswersTheErrorCodeAndKeepsOnlyAValidNodeIdPending) {
    const NodeIdCase& c = GetParam();
    to_configuration();
    EXPECT_EQ(answer(master_frame(LssCommand::ConfigureNodeId, {c.requested})),
              slave_frame(LssCommand::ConfigureNodeId, {c.error_code, 0}));
    EXPECT_EQ(slave->pending_node_id(), c.error_code == 0 ? c.requested : kLssUnconfiguredNodeId);
    EXPECT_EQ(slave->active_node_id(), kLssUnconfiguredNodeId);
}

INSTANTIATE_TEST_SUITE_P(ValidAndOutOfRange, LssSlaveConfigureNodeId,
                         ::testing::Values(NodeIdCase{1, 0}, NodeIdCase{64, 0}, NodeIdCase{127, 0},
                                           NodeIdCase{0xFF, 0}, NodeIdCase{0, 1},
                                           NodeIdCase{128, 1}, NodeIdCase{0xFE, 1}));

TEST_F(LssSlaveTest, ConfiguredNodeIdTakesEffectAtResetCommunication) {
    make_slave(slave_config({10, kBitrate}));
    to_configuration();
    answer(master_frame(LssCommand::ConfigureNodeId, {20}));
    EXPECT_EQ(answer(master_frame(LssCommand::InquireNodeId)),
              slave_frame(LssCommand::InquireNodeId, {10}));
    EXPECT_EQ(slave->reset_communication(), 20);
    EXPECT_EQ(slave->active_node_id(), 20);
    EXPECT_EQ(slave->state(), LssState::Waiting);
    to_configuration();
    EXPECT_EQ(answer(master_frame(LssCommand::InquireNodeId)),
              slave_frame(LssCommand::InquireNodeId, {20}));
}

TEST_F(LssSlaveTest, InquireNodeIdOfAnUnconfiguredSlaveIs0xFF) {
    to_configuration();
    EXPECT_EQ(answer(master_frame(LssCommand::InquireNodeId)),
              slave_frame(LssCommand::InquireNodeId, {0xFF}));
}

TEST_F(LssSlaveTest, FirstNodeIdRequestsResetCommunicationWhenSwitchedToWaiting) {
    int resets = 0;
    LssSlaveHooks hooks;
    hooks.request_reset_communication = [&] {
        ++resets;
        slave->reset_communication();
    };
    make_slave(slave_config(kUnconfigured), hooks);
    to_configuration();
    answer(master_frame(LssCommand::ConfigureNodeId, {7}));
    exchange(master_frame(LssCommand::SwitchStateGlobal, {0}));
    EXPECT_EQ(resets, 1);
    EXPECT_EQ(slave->active_node_id(), 7);
    // A node-ID that replaces another one waits for the next reset communication.
    to_configuration();
    answer(master_frame(LssCommand::ConfigureNodeId, {8}));
    exchange(master_frame(LssCommand::SwitchStateGlobal, {0}));
    EXPECT_EQ(resets, 1);
    EXPECT_EQ(slave->active_node_id(), 7);
    EXPECT_EQ(slave->pending_node_id(), 8);
}

struct BitTimingCase {
    std::uint8_t table_selector;
    std::uint8_t table_index;
    std::optional<std::uint32_t> bit_rate; ///< nullopt: not supported
};

class LssSlaveConfigureBitTiming : public LssSlaveTest,
                                   public ::testing::WithParamInterface<BitTimingCase> {};

// EPOS2 FW spec 7.4.2.4 with the CiA bit timing table: error code 1 "bit timing not supported".
TEST_P(LssSlaveConfigureBitTiming, MakesTheTableRatePendingOrAnswersNotSupported) {
    const BitTimingCase& c = GetParam();
    LssSlaveHooks hooks;
    hooks.switch_bit_rate = [](std::uint32_t) {
    };
    make_slave(slave_config(kUnconfigured), hooks);
    to_configuration();
    const std::uint8_t error_code = c.bit_rate ? kLssSuccess : kLssBitTimingNotSupported;
    EXPECT_EQ(
        answer(master_frame(LssCommand::ConfigureBitTiming, {c.table_selector, c.table_index})),
        slave_frame(LssCommand::ConfigureBitTiming, {error_code, 0}));
    EXPECT_EQ(slave->pending_bit_rate(), c.bit_rate.value_or(kBitrate));
    EXPECT_EQ(slave->active_bit_rate(), kBitrate);
}

INSTANTIATE_TEST_SUITE_P(
    CiaBitTimingTable, LssSlaveConfigureBitTiming,
    ::testing::Values(BitTimingCase{0, 0, 1'000'000}, BitTimingCase{0, 1, 800'000},
                      BitTimingCase{0, 2, 500'000}, BitTimingCase{0, 3, 250'000},
                      BitTimingCase{0, 4, 125'000}, BitTimingCase{0, 5, std::nullopt},
                      BitTimingCase{0, 6, 50'000}, BitTimingCase{0, 7, 20'000},
                      BitTimingCase{0, 8, 10'000}, BitTimingCase{0, 9, std::nullopt},
                      BitTimingCase{0, 0xFF, std::nullopt}, BitTimingCase{1, 0, std::nullopt}));

TEST_F(LssSlaveTest, ConfigureBitTimingIsNotSupportedWithoutABitRateHook) {
    to_configuration();
    EXPECT_EQ(answer(master_frame(LssCommand::ConfigureBitTiming, {0, 3})),
              slave_frame(LssCommand::ConfigureBitTiming, {kLssBitTimingNotSupported, 0}));
    EXPECT_EQ(slave->pending_bit_rate(), kBitrate);
}

// EPOS2 FW spec 7.4.2.5, figure 7-65: deaf for one switch delay, switch, then listening but
// silent for another.
TEST_F(LssSlaveTest, ActivateBitTimingSwitchesAfterOneDelayAndSpeaksAgainAfterTwo) {
    std::vector<std::pair<core::TimePoint, std::uint32_t>> switches;
    std::vector<std::pair<core::TimePoint, bool>> silences;
    LssSlaveHooks hooks;
    hooks.switch_bit_rate = [&](std::uint32_t rate) {
        switches.emplace_back(loop.now(), rate);
    };
    hooks.on_silence = [&](bool silent) {
        silences.emplace_back(loop.now(), silent);
    };
    make_slave(slave_config(kUnconfigured), hooks);
    to_configuration();
    answer(master_frame(LssCommand::ConfigureBitTiming, {0, 3}));

    const can::Frame activate = master_frame(LssCommand::ActivateBitTiming, {0x0A, 0x00}); // 10 ms
    const core::TimePoint received = loop.now() + testing::time_to_receive(activate, kBitrate);
    inbox.frames.clear();
    inbox.times.clear();
    tester->send(activate);
    loop.run_for(5ms);
    EXPECT_TRUE(slave->silent());
    // During the first delay the slave is switching and takes nothing from the bus.
    tester->send(master_frame(LssCommand::ConfigureNodeId, {9}));
    loop.run_for(7ms);
    EXPECT_TRUE(inbox.frames.empty());
    EXPECT_EQ(slave->pending_node_id(), kLssUnconfiguredNodeId);
    // During the second it listens, and answers when it ends.
    tester->send(master_frame(LssCommand::InquireNodeId));
    loop.run_for(10ms);
    const can::Frame node_id = slave_frame(LssCommand::InquireNodeId, {0xFF});
    ASSERT_EQ(inbox.frames, std::vector{node_id});
    EXPECT_EQ(inbox.times[0], received + 20ms + testing::time_to_receive(node_id, kBitrate));
    EXPECT_FALSE(slave->silent());

    ASSERT_EQ(switches.size(), 1U);
    EXPECT_EQ(switches[0], std::make_pair(received + 10ms, std::uint32_t{250'000}));
    ASSERT_EQ(silences.size(), 2U);
    EXPECT_EQ(silences[0], std::make_pair(received, true));
    EXPECT_EQ(silences[1], std::make_pair(received + 20ms, false));
    EXPECT_EQ(slave->active_bit_rate(), 250'000U);
    EXPECT_EQ(slave->state(), LssState::Configuration);
}

TEST_F(LssSlaveTest, ActivateBitTimingIsIgnoredWithoutABitRateHook) {
    to_configuration();
    EXPECT_TRUE(exchange(master_frame(LssCommand::ActivateBitTiming, {10, 0})).empty());
    EXPECT_FALSE(slave->silent());
}

struct StoreCase {
    std::optional<LssStoreResult> hook_result; ///< nullopt: no store hook
    std::uint8_t error_code;
};

class LssSlaveStoreConfiguration : public LssSlaveTest,
                                   public ::testing::WithParamInterface<StoreCase> {};

// EPOS2 FW spec 7.4.2.6: 0 success, 1 not supported, 2 storage media access error.
TEST_P(LssSlaveStoreConfiguration, StoresThePendingConfigurationAndAnswersItsErrorCode) {
    const StoreCase& c = GetParam();
    std::vector<LssConfiguration> stored;
    LssSlaveHooks hooks;
    hooks.switch_bit_rate = [](std::uint32_t) {
    };
    if (c.hook_result) {
        hooks.store_configuration = [&, result = *c.hook_result](const LssConfiguration& config) {
            stored.push_back(config);
            return result;
        };
    }
    make_slave(slave_config(kUnconfigured), hooks);
    to_configuration();
    answer(master_frame(LssCommand::ConfigureNodeId, {33}));
    answer(master_frame(LssCommand::ConfigureBitTiming, {0, 4}));
    EXPECT_EQ(answer(master_frame(LssCommand::StoreConfiguration)),
              slave_frame(LssCommand::StoreConfiguration, {c.error_code, 0}));
    if (c.hook_result) {
        EXPECT_EQ(stored, (std::vector<LssConfiguration>{{33, 125'000}}));
    }
}

INSTANTIATE_TEST_SUITE_P(ErrorCodes, LssSlaveStoreConfiguration,
                         ::testing::Values(StoreCase{LssStoreResult::Stored, 0},
                                           StoreCase{std::nullopt, 1},
                                           StoreCase{LssStoreResult::NotSupported, 1},
                                           StoreCase{LssStoreResult::StorageAccessError, 2}));

struct InquireCase {
    LssCommand cs;
    std::uint32_t value;
};

class LssSlaveInquireIdentity : public LssSlaveTest,
                                public ::testing::WithParamInterface<InquireCase> {};

// EPOS2 FW spec 7.4.2.7-7.4.2.10: the number, UNSIGNED32 little-endian in bytes 1..4.
TEST_P(LssSlaveInquireIdentity, AnswersTheNumberFromTheIdentityObject) {
    to_configuration();
    EXPECT_EQ(answer(master_frame(GetParam().cs)),
              lss_frame_u32(kLssSlaveCobId, GetParam().cs, GetParam().value));
}

INSTANTIATE_TEST_SUITE_P(
    EveryPart, LssSlaveInquireIdentity,
    ::testing::Values(InquireCase{LssCommand::InquireVendorId, kAddress.vendor_id},
                      InquireCase{LssCommand::InquireProductCode, kAddress.product_code},
                      InquireCase{LssCommand::InquireRevisionNumber, kAddress.revision_number},
                      InquireCase{LssCommand::InquireSerialNumber, kAddress.serial_number}));

TEST_F(LssSlaveTest, InquireSerialNumberIsLittleEndianOnTheWire) {
    to_configuration();
    EXPECT_EQ(answer(master_frame(LssCommand::InquireSerialNumber)),
              slave_frame(LssCommand::InquireSerialNumber, {0x78, 0x56, 0x34, 0x12}));
}

std::vector<can::Frame> identify_frames(std::uint32_t vendor, std::uint32_t product,
                                        std::uint32_t revision_low, std::uint32_t revision_high,
                                        std::uint32_t serial_low, std::uint32_t serial_high) {
    return {master_frame_u32(LssCommand::IdentifyRemoteSlaveVendorId, vendor),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveProductCode, product),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveRevisionLow, revision_low),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveRevisionHigh, revision_high),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveSerialLow, serial_low),
            master_frame_u32(LssCommand::IdentifyRemoteSlaveSerialHigh, serial_high)};
}

struct IdentifyCase {
    std::vector<can::Frame> frames;
    bool answers;
};

class LssSlaveIdentifyRemoteSlave : public LssSlaveTest,
                                    public ::testing::WithParamInterface<IdentifyCase> {};

// EPOS2 FW spec 7.4.2.12: vendor-ID and product code equal, the ranges inclusive.
TEST_P(LssSlaveIdentifyRemoteSlave, AnswersWhenItsAddressIsInTheRangeInBothStates) {
    const IdentifyCase& c = GetParam();
    for (const LssState state : {LssState::Waiting, LssState::Configuration}) {
        exchange(master_frame(LssCommand::SwitchStateGlobal, {static_cast<std::uint8_t>(state)}));
        std::vector<can::Frame> answers;
        for (const can::Frame& frame : c.frames) {
            const std::vector<can::Frame> got = exchange(frame);
            answers.insert(answers.end(), got.begin(), got.end());
        }
        EXPECT_EQ(answers, c.answers ? std::vector{slave_frame(LssCommand::IdentifySlave)}
                                     : std::vector<can::Frame>{});
        EXPECT_EQ(slave->state(), state);
    }
}

constexpr std::uint32_t kV = kAddress.vendor_id;
constexpr std::uint32_t kP = kAddress.product_code;
constexpr std::uint32_t kR = kAddress.revision_number;
constexpr std::uint32_t kS = kAddress.serial_number;

INSTANTIATE_TEST_SUITE_P(
    Ranges, LssSlaveIdentifyRemoteSlave,
    ::testing::Values(
        IdentifyCase{identify_frames(kV, kP, 0, 0xFFFFFFFF, 0, 0xFFFFFFFF), true},
        IdentifyCase{identify_frames(kV, kP, kR, kR, kS, kS), true},
        IdentifyCase{identify_frames(kV + 1, kP, 0, 0xFFFFFFFF, 0, 0xFFFFFFFF), false},
        IdentifyCase{identify_frames(kV, kP - 1, 0, 0xFFFFFFFF, 0, 0xFFFFFFFF), false},
        IdentifyCase{identify_frames(kV, kP, kR + 1, 0xFFFFFFFF, 0, 0xFFFFFFFF), false},
        IdentifyCase{identify_frames(kV, kP, 0, kR - 1, 0, 0xFFFFFFFF), false},
        IdentifyCase{identify_frames(kV, kP, kR, kR, kS + 1, 0xFFFFFFFF), false},
        IdentifyCase{identify_frames(kV, kP, kR, kR, 0, kS - 1), false}));

TEST_F(LssSlaveTest, IdentifyRemoteSlaveOutOfOrderIsNotAnswered) {
    std::vector<can::Frame> frames = identify_frames(kV, kP, 0, 0xFFFFFFFF, 0, 0xFFFFFFFF);
    std::swap(frames[2], frames[3]);
    for (const can::Frame& frame : frames) {
        EXPECT_TRUE(exchange(frame).empty());
    }
}

// EPOS2 FW spec 7.4.2.13: only a slave without node-ID (active and pending) answers 0x50.
TEST_F(LssSlaveTest, IdentifyNonConfiguredRemoteSlaveIsAnsweredOnlyWithoutNodeId) {
    const can::Frame request = master_frame(LssCommand::IdentifyNonConfiguredRemoteSlave);
    EXPECT_EQ(answer(request), slave_frame(LssCommand::IdentifyNonConfiguredSlave));
    to_configuration();
    EXPECT_EQ(answer(request), slave_frame(LssCommand::IdentifyNonConfiguredSlave));
    answer(master_frame(LssCommand::ConfigureNodeId, {5}));
    EXPECT_EQ(answer(request), std::nullopt);

    make_slave(slave_config({5, kBitrate}));
    EXPECT_EQ(answer(request), std::nullopt);
    make_slave(slave_config({0, kBitrate})); // EPOS2 7.4: node-ID 0 is "not configured" too
    EXPECT_EQ(answer(request), slave_frame(LssCommand::IdentifyNonConfiguredSlave));
}

can::Frame fastscan(std::uint32_t id, std::uint8_t bit_checked, LssPart sub, LssPart next) {
    return lss_fastscan_frame({id, bit_checked, sub, next});
}

const can::Frame kFastscanConfirmFrame =
    fastscan(0, kFastscanConfirm, LssPart::VendorId, LssPart::VendorId);
const can::Frame kIdentifySlave = slave_frame(LssCommand::IdentifySlave);

TEST_F(LssSlaveTest, FastscanFramesCarryIdNumberBitCheckedLssSubAndLssNext) {
    EXPECT_EQ(fastscan(0x12345678, 7, LssPart::RevisionNumber, LssPart::SerialNumber),
              master_frame(LssCommand::Fastscan, {0x78, 0x56, 0x34, 0x12, 7, 2, 3}));
}

TEST_F(LssSlaveTest, FastscanConfirmIsAnsweredByANonConfiguredSlaveOnly) {
    EXPECT_EQ(answer(kFastscanConfirmFrame), kIdentifySlave);
    make_slave(slave_config({3, kBitrate}));
    EXPECT_EQ(answer(kFastscanConfirmFrame), std::nullopt);
}

TEST_F(LssSlaveTest, FastscanAnswersWhenTheBitsFromBitCheckedUpMatch) {
    exchange(kFastscanConfirmFrame);
    const std::uint32_t vendor = kAddress.vendor_id; // 0xFB
    // 0xFB is 1111'1011: bits 31..8 are 0, bits 7..3 are 1, bit 2 is 0.
    EXPECT_EQ(answer(fastscan(0, 8, LssPart::VendorId, LssPart::VendorId)), kIdentifySlave);
    EXPECT_EQ(answer(fastscan(0xF8, 3, LssPart::VendorId, LssPart::VendorId)), kIdentifySlave);
    EXPECT_EQ(answer(fastscan(0xF0, 3, LssPart::VendorId, LssPart::VendorId)), std::nullopt);
    EXPECT_EQ(answer(fastscan(0xFC, 2, LssPart::VendorId, LssPart::VendorId)), std::nullopt);
    EXPECT_EQ(answer(fastscan(0x100, 8, LssPart::VendorId, LssPart::VendorId)), std::nullopt);
    EXPECT_EQ(answer(fastscan(vendor, 0, LssPart::VendorId, LssPart::VendorId)), kIdentifySlave);
    EXPECT_EQ(slave->state(), LssState::Waiting);
}

TEST_F(LssSlaveTest, FastscanThroughAllFourPartsEntersConfiguration) {
    exchange(kFastscanConfirmFrame);
    const LssPart parts[] = {LssPart::VendorId, LssPart::ProductCode, LssPart::RevisionNumber,
                             LssPart::SerialNumber};
    for (std::size_t i = 0; i < 4; ++i) {
        const LssPart next = parts[(i + 1) % 4];
        // A request for a later part is not for this slave yet.
        if (i < 3) {
            EXPECT_EQ(answer(fastscan(kAddress.part(next), 0, next, next)), std::nullopt);
        }
        EXPECT_EQ(slave->state(), LssState::Waiting);
        EXPECT_EQ(answer(fastscan(kAddress.part(parts[i]), 0, parts[i], next)), kIdentifySlave);
    }
    EXPECT_EQ(slave->state(), LssState::Configuration);
    // Fastscan is a waiting-state service.
    EXPECT_EQ(answer(kFastscanConfirmFrame), std::nullopt);
}

TEST_F(LssSlaveTest, FastscanMismatchKeepsTheSlaveAtItsPart) {
    exchange(kFastscanConfirmFrame);
    EXPECT_EQ(answer(fastscan(kAddress.vendor_id + 1, 0, LssPart::VendorId, LssPart::ProductCode)),
              std::nullopt);
    EXPECT_EQ(answer(fastscan(kAddress.vendor_id, 0, LssPart::VendorId, LssPart::ProductCode)),
              kIdentifySlave);
    // The confirm starts over at the vendor-ID.
    exchange(kFastscanConfirmFrame);
    EXPECT_EQ(
        answer(fastscan(kAddress.product_code, 0, LssPart::ProductCode, LssPart::RevisionNumber)),
        std::nullopt);
}

class LssSlaveFastscanInvalid : public LssSlaveTest,
                                public ::testing::WithParamInterface<can::Frame> {};

TEST_P(LssSlaveFastscanInvalid, RequestIsIgnored) {
    exchange(kFastscanConfirmFrame);
    EXPECT_EQ(answer(GetParam()), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(
    OutOfRangeFields, LssSlaveFastscanInvalid,
    ::testing::Values(master_frame(LssCommand::Fastscan, {0xFB, 0, 0, 0, 32, 0, 0}),
                      master_frame(LssCommand::Fastscan, {0xFB, 0, 0, 0, 0x7F, 0, 0}),
                      master_frame(LssCommand::Fastscan, {0xFB, 0, 0, 0, 0x81, 0, 0}),
                      master_frame(LssCommand::Fastscan, {0xFB, 0, 0, 0, 0, 4, 1}),
                      master_frame(LssCommand::Fastscan, {0xFB, 0, 0, 0, 0, 0, 4})));

class LssSlaveMalformed : public LssSlaveTest, public ::testing::WithParamInterface<can::Frame> {};

TEST_P(LssSlaveMalformed, FrameIsIgnored) {
    to_configuration();
    EXPECT_TRUE(exchange(GetParam()).empty());
}

can::Frame with_dlc(can::Frame frame, std::uint8_t dlc) {
    frame.dlc = dlc;
    return frame;
}

INSTANTIATE_TEST_SUITE_P(
    NotLss, LssSlaveMalformed,
    ::testing::Values(with_dlc(master_frame(LssCommand::InquireNodeId), 1),
                      with_dlc(master_frame(LssCommand::InquireNodeId), 7),
                      can::Frame::remote_frame(kLssMasterCobId, 8),
                      lss_frame(kLssSlaveCobId, LssCommand::InquireNodeId),
                      lss_frame(0x7E6, LssCommand::InquireNodeId),
                      can::Frame::data_frame(kLssMasterCobId, {0x5E, 0, 0, 0, 0, 0, 0, 0}, true),
                      master_frame(static_cast<LssCommand>(0x99))));

// EPOS2 FW spec 7.4: "Layer Setting Services are only accessible in NMT slave state Stopped".
TEST_F(LssSlaveTest, OnlyWhenNmtStoppedIgnoresLssInOtherNmtStates) {
    make_slave(slave_config({9, kBitrate}, true));
    const can::Frame to_config = master_frame(LssCommand::SwitchStateGlobal, {1});
    slave->set_nmt_state(NmtState::PreOperational);
    exchange(to_config);
    EXPECT_EQ(slave->state(), LssState::Waiting);
    slave->set_nmt_state(NmtState::Operational);
    exchange(to_config);
    EXPECT_EQ(slave->state(), LssState::Waiting);
    slave->set_nmt_state(NmtState::Stopped);
    exchange(to_config);
    EXPECT_EQ(slave->state(), LssState::Configuration);
    EXPECT_EQ(answer(master_frame(LssCommand::InquireNodeId)),
              slave_frame(LssCommand::InquireNodeId, {9}));
}

TEST_F(LssSlaveTest, OnlyWhenNmtStoppedStillServesADeviceWithoutNodeId) {
    make_slave(slave_config(kUnconfigured, true));
    EXPECT_EQ(answer(kFastscanConfirmFrame), kIdentifySlave);
}

TEST(LssAddressFromDictionary, ReadsTheIdentityObject) {
    ObjectDictionary dictionary;
    dictionary.add_object(0x1018, "Identity Object", ObjectCode::Record);
    dictionary.add_sub(0x1018, 1, "Vendor ID", DataType::Unsigned32, Access::ReadOnly,
                       encode(kAddress.vendor_id));
    dictionary.add_sub(0x1018, 2, "Product Code", DataType::Unsigned32, Access::ReadOnly,
                       encode(kAddress.product_code));
    dictionary.add_sub(0x1018, 3, "Revision Number", DataType::Unsigned32, Access::ReadOnly,
                       encode(kAddress.revision_number));
    dictionary.add_sub(0x1018, 4, "Serial Number", DataType::Unsigned32, Access::ReadOnly,
                       encode(kAddress.serial_number));
    EXPECT_EQ(lss_address_from_dictionary(dictionary), kAddress);
}

} // namespace
} // namespace eposp::canopen
