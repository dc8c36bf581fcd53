#pragma once

#include "service_bench.hpp"
#include "eposp/can/frame_timing.hpp"
#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/sdo_protocol.hpp"
#include "eposp/canopen/sdo_server.hpp"

#include <chrono>
#include <cstdint>
#include <fmt/format.h>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

// Shared by the SDO tests: a dictionary with an object of every kind the tests need, a server
// on the device port of a ServiceBench, and frame-time helpers for a 1 Mbit/s bus.

namespace eposp::canopen {

/// GoogleTest prints abort codes as the specification names them.
inline void PrintTo(AbortCode code, std::ostream* os) {
    *os << fmt::format("0x{:08X} ({})", static_cast<std::uint32_t>(code), describe(code));
}

} // namespace eposp::canopen

namespace eposp::canopen::testing {

using namespace std::chrono_literals;

/// Requests on 0x605, responses on 0x585.
inline constexpr NodeId kServerNode = 5;

/// 12 bytes: a segmented upload of two segments, the second with 5 bytes.
inline constexpr std::string_view kDeviceName = "EPOS2 24/5 X";

/// The objects the SDO tests read and write.
inline void add_sdo_test_objects(ObjectDictionary& od) {
    od.add_variable(0x1000, "Device Type", DataType::Unsigned32, Access::ReadOnly,
                    encode<std::uint32_t>(0x0002'0192));
    od.add_variable(0x1008, "Manufacturer Device Name", DataType::VisibleString, Access::Const,
                    encode_string(kDeviceName));
    od.add_variable(0x2000, "u8", DataType::Unsigned8, Access::ReadWrite, {0});
    od.add_variable(0x2001, "u16", DataType::Unsigned16, Access::ReadWrite, {0, 0});
    od.add_variable(0x2002, "u32", DataType::Unsigned32, Access::ReadWrite,
                    encode<std::uint32_t>(0));
    SubObject& limited = od.add_variable(0x2003, "u32 10..1000", DataType::Unsigned32,
                                         Access::ReadWrite, encode<std::uint32_t>(10));
    limited.low_limit = encode<std::uint32_t>(10);
    limited.high_limit = encode<std::uint32_t>(1000);
    od.add_variable(0x2004, "u64", DataType::Unsigned64, Access::ReadWrite,
                    encode<std::uint64_t>(0));
    od.add_variable(0x2005, "write-only", DataType::Unsigned32, Access::WriteOnly,
                    encode<std::uint32_t>(0));
    od.add_variable(0x2006, "string", DataType::VisibleString, Access::ReadWrite, {});
    SubObject& hooked = od.add_variable(0x2007, "refuses 0", DataType::Unsigned32,
                                        Access::ReadWrite, encode<std::uint32_t>(1));
    hooked.on_write = [](std::span<const std::uint8_t> value) {
        return decode<std::uint32_t>(value) == 0 ? AbortCode::DeviceState : AbortCode::None;
    };
    od.add_variable(0x2100, "domain", DataType::Domain, Access::ReadWrite, {});
}

/// Bytes 1, 2, 3, ..., n.
inline Bytes counting_bytes(std::size_t n) {
    Bytes out(n);
    for (std::size_t i = 0; i < n; ++i) {
        out[i] = static_cast<std::uint8_t>(i + 1);
    }
    return out;
}

/// Bytes as hex digits, the way candump writes them.
inline std::string hex(std::span<const std::uint8_t> bytes) {
    std::string out;
    for (const std::uint8_t byte : bytes) {
        out += fmt::format("{:02X}", byte);
    }
    return out;
}

/// The CRC of a block transfer as its end message carries it: low byte first.
inline std::string crc_hex(std::span<const std::uint8_t> data) {
    const std::uint16_t crc = sdo::block_crc(data);
    return fmt::format("{:02X}{:02X}", crc & 0xFF, crc >> 8);
}

// Frame times on the 1 Mbit/s bus of a ServiceBench.

/// When receivers get `frame` that started at `start`.
inline core::TimePoint end_of(core::TimePoint start, std::string_view frame) {
    const auto bits = can::frame_length(*can::parse_candump_frame(frame)).to_end_of_frame();
    return start + static_cast<std::int64_t>(bits) * 1us;
}
/// When the next frame may start after `frame` that started at `start` (intermission included).
inline core::TimePoint next_slot(core::TimePoint start, std::string_view frame) {
    const auto bits = can::frame_length(*can::parse_candump_frame(frame)).total();
    return start + static_cast<std::int64_t>(bits) * 1us;
}

using Replies = std::vector<std::string>;

/// A ServiceBench that hands out what the device sent since the last look.
struct SdoBench : ServiceBench {
    /// The device's frames since the last call, in candump form.
    Replies new_device_frames() {
        Replies out;
        const auto frames = device_frames();
        for (; seen < frames.size(); ++seen) {
            out.push_back(frames[seen].frame);
        }
        return out;
    }
    /// Lets 10 ms pass and returns what the device sent meanwhile.
    Replies settle() {
        run_for(10ms);
        return new_device_frames();
    }
    /// The tester sends `frame`; returns what the device sent in the next 10 ms.
    Replies exchange(std::string_view frame) {
        send(frame);
        return settle();
    }

    std::size_t seen = 0;
};

/// The device port runs an SDO server for node 5 over add_sdo_test_objects(); the tester plays
/// the client with raw frames.
struct SdoServerBench : SdoBench {
    explicit SdoServerBench(SdoServerConfig config = {})
        : server(loop, *device, od, kServerNode, config) {
        add_sdo_test_objects(od);
        add_sdo_server_objects(od, kServerNode);
        device->on_receive([this](const can::Frame& frame) { server.on_frame(frame); });
    }

    ObjectDictionary od;
    SdoServer server;
};

/// The device port runs an SDO client; the tester plays the servers with raw frames.
struct SdoClientBench : SdoBench {
    explicit SdoClientBench(SdoClientConfig config = {}) : client(loop, *device, config) {
        device->on_receive([this](const can::Frame& frame) { client.on_frame(frame); });
    }

    SdoClient client;
};

/// What an SdoClient callback reported.
struct Outcome {
    std::optional<AbortCode> code; ///< empty until the callback ran
    Bytes value;
    int calls = 0;

    SdoClient::UploadCallback upload() {
        return [this](AbortCode c, Bytes v) {
            code = c;
            value = std::move(v);
            ++calls;
        };
    }
    SdoClient::DownloadCallback download() {
        return [this](AbortCode c) {
            code = c;
            ++calls;
        };
    }
};

} // namespace eposp::canopen::testing
