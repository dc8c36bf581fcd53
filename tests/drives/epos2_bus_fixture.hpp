#pragma once

// The test bench of a simulated EPOS2 driven purely through CAN frames, the way a CANopen master
// configures and moves a real one: NMT, SDO writes, controlword and target by RPDO, statusword
// and position by TPDO on SYNC, EMCY on errors. All in virtual time.
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "plant_test_motor.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <vector>

namespace eposp::drives::epos2 {
namespace test {

using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

constexpr canopen::NodeId kNode = 2;
constexpr std::uint32_t kSyncId = 0x080;
constexpr std::uint32_t kEmcyId = 0x080 + kNode;
constexpr std::uint32_t kRpdo1Id = 0x200 + kNode; // controlword (8.2.18)
constexpr std::uint32_t kRpdo3Id = 0x400 + kNode; // controlword, target position (8.2.20)
constexpr std::uint32_t kTpdo3Id = 0x380 + kNode; // statusword, position actual (8.2.28)

// Table 3-4 under the mask of CiA 402 (bits 0-3, 5, 6).
constexpr std::uint16_t kStateMask = 0x006F;
constexpr std::uint16_t kOperationEnabled = 0x0027;
constexpr std::uint16_t kSwitchOnDisabled = 0x0040;
constexpr std::uint16_t kFault = 0x0008;

// Table 3-6.
constexpr std::uint16_t kShutdown = 0x0006;
constexpr std::uint16_t kSwitchOn = 0x0007;
constexpr std::uint16_t kEnableOperation = 0x000F;
constexpr std::uint16_t kFaultReset = 0x0080;
constexpr std::uint16_t kNewSetpoint = 0x0010;
constexpr std::uint16_t kChangeImmediately = 0x0020;

struct Tpdo {
    double time = 0; ///< seconds of virtual time
    std::uint16_t statusword = 0;
    std::int32_t position = 0;
};

inline Epos2DriveConfig drive_config(plant::AxisParameters axis) {
    Epos2DriveConfig config;
    config.dictionary.node_id = kNode;
    config.axis = axis;
    return config;
}

class Epos2DriveOnBus : public ::testing::Test {
public:
    explicit Epos2DriveOnBus(plant::AxisParameters axis = plant::test::tuned_axis())
        : drive(loop, *device, drive_config(axis)) {
        master->on_receive([this](const can::Frame& frame) { receive(frame); });
        drive.start();
        loop.run_for(10ms);
    }

    double now() const {
        return std::chrono::duration<double>(loop.now().time_since_epoch()).count();
    }
    void receive(const can::Frame& frame) {
        client.on_frame(frame);
        if (frame.id == kTpdo3Id) {
            tpdos.push_back({now(), canopen::decode<std::uint16_t>(frame.payload().subspan(0, 2)),
                             canopen::decode<std::int32_t>(frame.payload().subspan(2, 4))});
        } else if (frame.id == kEmcyId) {
            emcys.emplace_back(frame.payload().begin(), frame.payload().end());
            emcy_times.push_back(now());
        }
    }

    /// An SDO download: the drive's answer (nullopt: none within 20 ms).
    std::optional<AbortCode> try_write(std::uint16_t index, std::uint8_t sub,
                                       canopen::Bytes value) {
        std::optional<AbortCode> result;
        client.download(kNode, index, sub, std::move(value),
                        [&result](AbortCode code) { result = code; });
        loop.run_for(20ms);
        return result;
    }
    void write(std::uint16_t index, std::uint8_t sub, canopen::Bytes value) {
        ASSERT_EQ(try_write(index, sub, std::move(value)), AbortCode::None)
            << fmt::format("0x{:04X} sub {}", index, sub);
    }
    template <typename T>
    T read(std::uint16_t index, std::uint8_t sub) {
        std::optional<canopen::Bytes> value;
        client.upload(kNode, index, sub, [&value](AbortCode code, canopen::Bytes bytes) {
            EXPECT_EQ(code, AbortCode::None);
            value = std::move(bytes);
        });
        loop.run_for(20ms);
        EXPECT_TRUE(value.has_value());
        return canopen::decode<T>(value.value_or(canopen::Bytes(sizeof(T))));
    }

    void nmt(canopen::NmtCommand command) {
        master->send(can::Frame::data_frame(canopen::kNmtCanId,
                                            {static_cast<std::uint8_t>(command), kNode}));
        loop.run_for(5ms);
    }
    void controlword(std::uint16_t word) {
        master->send(can::Frame::data_frame(kRpdo1Id, {static_cast<std::uint8_t>(word & 0xFF),
                                                       static_cast<std::uint8_t>(word >> 8)}));
    }
    void controlword_and_target(std::uint16_t word, std::int32_t target) {
        const canopen::Bytes t = encode(target);
        master->send(can::Frame::data_frame(kRpdo3Id, {static_cast<std::uint8_t>(word & 0xFF),
                                                       static_cast<std::uint8_t>(word >> 8), t[0],
                                                       t[1], t[2], t[3]}));
    }
    /// The master's SYNC every millisecond for `duration`.
    void run_with_sync(std::chrono::milliseconds duration) {
        for (auto elapsed = 0ms; elapsed < duration; elapsed += 1ms) {
            master->send(can::Frame::data_frame(kSyncId, {}));
            loop.run_for(1ms);
        }
    }

    /// What a master does to a fresh EPOS2: TPDO 3 on every SYNC, NMT start, profile
    /// parameters, enable by RPDO.
    void configure_and_enable(std::int8_t mode) {
        write(0x1802, 2, encode(std::uint8_t{1}));                       // synchronous, every SYNC
        write(0x1802, 1, encode(std::uint32_t{0x4000'0000 | kTpdo3Id})); // valid, no RTR
        write(0x6060, 0, encode(mode));
        write(0x6081, 0, encode(std::uint32_t{1000}));  // rpm
        write(0x6083, 0, encode(std::uint32_t{10000})); // rpm/s
        write(0x6084, 0, encode(std::uint32_t{10000}));
        nmt(canopen::NmtCommand::Start);
        for (const std::uint16_t word : {kShutdown, kSwitchOn, kEnableOperation}) {
            controlword(word);
            run_with_sync(10ms);
        }
        ASSERT_FALSE(tpdos.empty());
        ASSERT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    }

    std::optional<Tpdo> first_tpdo_with(std::uint16_t bit, double after) const {
        for (const Tpdo& tpdo : tpdos) {
            if (tpdo.time > after && (tpdo.statusword & bit) != 0) {
                return tpdo;
            }
        }
        return std::nullopt;
    }

    core::EventLoop loop;
    can::VirtualBus bus{loop};
    std::unique_ptr<can::VirtualPort> device = bus.connect("epos2");
    std::unique_ptr<can::VirtualPort> master = bus.connect("master");
    canopen::SdoClient client{loop, *master};
    Epos2Drive drive;
    std::vector<Tpdo> tpdos;
    std::vector<std::vector<std::uint8_t>> emcys;
    std::vector<double> emcy_times; ///< seconds, beside emcys
};

using EmcyBytes = std::array<std::uint8_t, 8>;

inline EmcyBytes emcy_bytes(const std::vector<std::uint8_t>& frame) {
    EmcyBytes bytes{};
    EXPECT_EQ(frame.size(), bytes.size());
    std::copy_n(frame.begin(), std::min(frame.size(), bytes.size()), bytes.begin());
    return bytes;
}

// The error as table 4-11 and 4.1 give it: its EMCY (code, register, five zero bytes) the first
// the master saw, the register in 0x1001 and the newest history entry.
inline void expect_emcy(Epos2DriveOnBus& bench, std::uint16_t code, std::uint8_t error_register) {
    ASSERT_FALSE(bench.emcys.empty());
    EXPECT_EQ(emcy_bytes(bench.emcys.front()),
              (EmcyBytes{static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
                         error_register, 0, 0, 0, 0, 0}));
    EXPECT_EQ(bench.read<std::uint8_t>(0x1001, 0), error_register);
    EXPECT_EQ(bench.read<std::uint8_t>(0x1003, 0), 1U) << "one entry in the history";
    EXPECT_EQ(bench.read<std::uint32_t>(0x1003, 1) & 0xFFFF, code);
}

// … and the drive in Fault.
inline void expect_error(Epos2DriveOnBus& bench, std::uint16_t code, std::uint8_t error_register) {
    expect_emcy(bench, code, error_register);
    EXPECT_EQ(bench.drive.state(), motion::DriveState::Fault);
    EXPECT_EQ(bench.read<std::uint16_t>(0x6041, 0) & kStateMask, kFault);
}

} // namespace test
} // namespace eposp::drives::epos2
