#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/canopen/pdo_service.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace {

using eposp::can::BusConfig;
using eposp::can::Frame;
using eposp::can::VirtualBus;
using eposp::canopen::AbortCode;
using eposp::canopen::Access;
using eposp::canopen::DataType;
using eposp::canopen::encode;
using eposp::canopen::ObjectDictionary;
using eposp::canopen::PdoService;
using eposp::core::EventLoop;

constexpr std::uint32_t kBitrate = 1'000'000;
constexpr auto kSyncPeriod = std::chrono::milliseconds(1);
constexpr auto kSimulated = std::chrono::seconds(1);

void write(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub, std::uint32_t value,
           std::size_t size) {
    const auto bytes = encode(value);
    if (od.write(index, sub, std::span(bytes).first(size)) != AbortCode::None) {
        throw std::logic_error("benchmark set-up write refused");
    }
}

// TPDO n (1-based): COB-ID 0x180 + n, type 1 (every SYNC), two UNSIGNED32 objects 0x3000 + 2n
// and 0x3001 + 2n: 8 bytes.
void add_tpdos(ObjectDictionary& od, std::size_t count) {
    eposp::canopen::add_pdo_objects(od, 1, 0, count);
    for (std::size_t n = 1; n <= count; ++n) {
        const auto comm = static_cast<std::uint16_t>(0x1800 + n - 1);
        const auto map = static_cast<std::uint16_t>(0x1A00 + n - 1);
        write(od, map, 0, 0, 1);
        for (std::uint8_t k = 0; k < 2; ++k) {
            const auto index = static_cast<std::uint16_t>(0x3000 + 2 * n + k);
            od.add_variable(index, "Process value", DataType::Unsigned32, Access::ReadOnly,
                            encode(static_cast<std::uint32_t>(0x1234'5678 * (n + k))))
                .pdo_mappable = true;
            write(od, map, static_cast<std::uint8_t>(k + 1), std::uint32_t{index} << 16 | 0x20, 4);
        }
        write(od, map, 0, 2, 1);
        write(od, comm, 2, 1, 1);
        write(od, comm, 1, static_cast<std::uint32_t>(0x180 + n), 4);
    }
}

// N synchronous TPDOs of 8 bytes on one node, SYNC every millisecond from a master, on a
// 1 Mbit/s virtual bus. One iteration simulates one second, so the reported time is the wall
// time per simulated second. Counters: PDO frames the master received and bus bits (stuff bits
// and intermission included) per simulated second; those bits as a fraction of the bit rate;
// the PDO frames as a fraction of the most 8-byte frames the bit rate allows (SYNCs left out)
// and of the N x 1000 asked for; frames lost to a full transmit queue per simulated second.
void BM_SynchronousTpdos(benchmark::State& state) {
    const auto tpdo_count = static_cast<std::size_t>(state.range(0));
    double pdo_frames = 0;
    double bits = 0;
    double lost = 0;
    double simulated_seconds = 0;
    for (auto _ : state) {
        EventLoop loop;
        VirtualBus bus(loop, BusConfig{.bitrate = kBitrate});
        auto device = bus.connect("device");
        auto master = bus.connect("master");
        ObjectDictionary od;
        add_tpdos(od, tpdo_count);
        PdoService pdo(loop, *device, od);
        device->on_receive([&pdo](const Frame& frame) {
            if (frame.id == 0x080) {
                pdo.on_sync(0);
            }
            pdo.on_frame(frame);
        });
        std::uint64_t received = 0;
        master->on_receive([&received](const Frame&) { ++received; });
        pdo.set_nmt_state(eposp::canopen::NmtState::Operational);
        loop.every(kSyncPeriod, [&master] { master->send(Frame::data_frame(0x080, {})); });
        loop.run_for(kSimulated);

        const auto statistics = bus.statistics();
        pdo_frames += static_cast<double>(received);
        bits += static_cast<double>(statistics.bits);
        lost += static_cast<double>(device->statistics().tx_overflows);
        simulated_seconds += std::chrono::duration<double>(kSimulated).count();
    }
    const double asked = static_cast<double>(tpdo_count) * 1000.0 * simulated_seconds;
    const auto sample = Frame::data_frame(0x181, {0x78, 0x56, 0x34, 0x12, 0xF0, 0xAC, 0x68, 0x24});
    const double most_frames_per_s =
        kBitrate / static_cast<double>(eposp::can::frame_length(sample).total());
    state.counters["pdo_frames_per_sim_s"] = pdo_frames / simulated_seconds;
    state.counters["bits_per_sim_s"] = bits / simulated_seconds;
    state.counters["of_bitrate"] = bits / simulated_seconds / kBitrate;
    state.counters["pdo_frames_of_max"] = pdo_frames / simulated_seconds / most_frames_per_s;
    state.counters["pdo_frames_of_asked"] = pdo_frames / asked;
    state.counters["lost_per_sim_s"] = lost / simulated_seconds;
    state.counters["sim_s_per_wall_s"] =
        benchmark::Counter(simulated_seconds, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynchronousTpdos)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(6)
    ->Arg(8)
    ->Arg(9)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
