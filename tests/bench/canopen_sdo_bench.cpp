#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/sdo_server.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cstdint>
#include <memory>
#include <stdexcept>

// SDO throughput on the virtual bus in virtual time: one client, one server, nothing else on
// the bus. Counters (all per simulated second, not wall time):
//   bytes_per_s      payload bytes per simulated second
//   of_bitrate       payload bits per second / bit rate: the share of the bus's physical limit
//                    that carries payload
//   wire_efficiency  payload bits / bits the transfer's frames occupied on the wire, each frame
//                    at its true length (stuff bits and intermission, can/frame_timing.hpp)
//   bus_load         wire bits / (simulated seconds * bit rate)
// so that of_bitrate = wire_efficiency * bus_load: what the frame format costs, and what the
// protocol's round trips cost. The wall time per iteration is the simulator's cost.

namespace {

using eposp::can::BusConfig;
using eposp::can::VirtualBus;
using eposp::can::VirtualPort;
using eposp::can::WireEvent;
using eposp::canopen::AbortCode;
using eposp::canopen::Access;
using eposp::canopen::Bytes;
using eposp::canopen::DataType;
using eposp::canopen::ObjectDictionary;
using eposp::canopen::SdoClient;
using eposp::canopen::SdoProtocol;
using eposp::canopen::SdoRequestOptions;
using eposp::canopen::SdoServer;
using eposp::core::EventLoop;

constexpr eposp::canopen::NodeId kNode = 1;
constexpr std::uint16_t kU32 = 0x2000;
constexpr std::uint16_t kDomain = 0x2100;
constexpr std::size_t kExpeditedTransfers = 500;
constexpr std::size_t kDomainSize = 32 * 1024;

enum class Kind { Expedited, Segmented, Block };
enum class Direction { Download, Upload };

/// A master with an SDO client and one slave with an SDO server on a bus of `bitrate`.
struct Network {
    explicit Network(std::uint32_t bitrate) : bus(loop, BusConfig{.bitrate = bitrate}) {
        bus.add_observer([this](const WireEvent& event) {
            if (!event.frame.error) {
                wire_bits += eposp::can::frame_length(event.frame).total();
            }
        });
        od.add_variable(kU32, "u32", DataType::Unsigned32, Access::ReadWrite, Bytes(4));
        od.add_variable(kDomain, "domain", DataType::Domain, Access::ReadWrite, {});
        master->on_receive([this](const auto& frame) { client.on_frame(frame); });
        slave->on_receive([this](const auto& frame) { server.on_frame(frame); });
    }

    EventLoop loop;
    VirtualBus bus;
    std::uint64_t wire_bits = 0;
    std::unique_ptr<VirtualPort> master = bus.connect("master");
    std::unique_ptr<VirtualPort> slave = bus.connect("slave");
    ObjectDictionary od;
    SdoServer server{loop, *slave, od, kNode};
    SdoClient client{loop, *master};
};

struct Measurement {
    double payload_bytes = 0;
    double seconds = 0;
    double wire_bits = 0;
};

Measurement transfer(Kind kind, Direction direction, std::uint32_t bitrate) {
    Network net(bitrate);
    const SdoRequestOptions options{.protocol = kind == Kind::Block ? SdoProtocol::Block
                                                                    : SdoProtocol::Segmented,
                                    .protocol_switch_threshold = 0};
    const std::size_t transfers = kind == Kind::Expedited ? kExpeditedTransfers : 1;
    const std::uint16_t index = kind == Kind::Expedited ? kU32 : kDomain;
    const std::size_t size = kind == Kind::Expedited ? 4 : kDomainSize;
    if (direction == Direction::Upload) {
        net.od.set(index, 0, Bytes(size, 0x5A));
    }
    std::size_t completed = 0;
    eposp::core::TimePoint end{};
    auto done = [&](AbortCode code) {
        if (code != AbortCode::None) {
            throw std::runtime_error("canopen_sdo_bench: a transfer failed");
        }
        if (++completed == transfers) {
            end = net.loop.now();
        }
    };
    for (std::size_t i = 0; i < transfers; ++i) {
        if (direction == Direction::Upload) {
            net.client.upload(
                kNode, index, 0, [&done](AbortCode code, Bytes) { done(code); }, options);
        } else {
            net.client.download(kNode, index, 0, Bytes(size, static_cast<std::uint8_t>(i)), done,
                                options);
        }
    }
    while (completed < transfers) {
        net.loop.run_for(std::chrono::milliseconds(100));
    }
    return {static_cast<double>(transfers * size),
            std::chrono::duration<double>(end.time_since_epoch()).count(),
            static_cast<double>(net.wire_bits)};
}

void BM_Sdo(benchmark::State& state, Kind kind, Direction direction, std::uint32_t bitrate) {
    Measurement total;
    for (auto _ : state) {
        const Measurement m = transfer(kind, direction, bitrate);
        total.payload_bytes += m.payload_bytes;
        total.seconds += m.seconds;
        total.wire_bits += m.wire_bits;
    }
    const double payload_bits = 8 * total.payload_bytes;
    state.counters["bytes_per_s"] = total.payload_bytes / total.seconds;
    state.counters["of_bitrate"] = payload_bits / total.seconds / bitrate;
    state.counters["wire_efficiency"] = payload_bits / total.wire_bits;
    state.counters["bus_load"] = total.wire_bits / (total.seconds * bitrate);
}

constexpr std::uint32_t k1M = 1'000'000;
constexpr std::uint32_t k125k = 125'000;

BENCHMARK_CAPTURE(BM_Sdo, expedited_download_1M, Kind::Expedited, Direction::Download, k1M);
BENCHMARK_CAPTURE(BM_Sdo, expedited_upload_1M, Kind::Expedited, Direction::Upload, k1M);
BENCHMARK_CAPTURE(BM_Sdo, segmented_download_1M, Kind::Segmented, Direction::Download, k1M);
BENCHMARK_CAPTURE(BM_Sdo, segmented_upload_1M, Kind::Segmented, Direction::Upload, k1M);
BENCHMARK_CAPTURE(BM_Sdo, block_download_1M, Kind::Block, Direction::Download, k1M);
BENCHMARK_CAPTURE(BM_Sdo, block_upload_1M, Kind::Block, Direction::Upload, k1M);
BENCHMARK_CAPTURE(BM_Sdo, expedited_download_125k, Kind::Expedited, Direction::Download, k125k);
BENCHMARK_CAPTURE(BM_Sdo, expedited_upload_125k, Kind::Expedited, Direction::Upload, k125k);
BENCHMARK_CAPTURE(BM_Sdo, segmented_download_125k, Kind::Segmented, Direction::Download, k125k);
BENCHMARK_CAPTURE(BM_Sdo, segmented_upload_125k, Kind::Segmented, Direction::Upload, k125k);
BENCHMARK_CAPTURE(BM_Sdo, block_download_125k, Kind::Block, Direction::Download, k125k);
BENCHMARK_CAPTURE(BM_Sdo, block_upload_125k, Kind::Block, Direction::Upload, k125k);

} // namespace
