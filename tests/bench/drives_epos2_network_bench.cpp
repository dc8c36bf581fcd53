#include "../drives/plant_test_motor.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/test/epos2_network.hpp"

#include <benchmark/benchmark.h>
#include <chrono>

namespace {

using namespace eposp;
using namespace std::chrono_literals;

// N whole simulated EPOS2s on one virtual bus, operational, enabled in Profile Position Mode
// with TPDO 3 (statusword, position) on every SYNC, the master sending SYNC at 1 kHz and a new
// back-and-forth target by RPDO 3 every 500 ms. One iteration is one simulated millisecond;
// "simulated_s" is simulated seconds per second (issue 6 asks ≥ 100 for 8 drives).
void BM_Epos2Network(benchmark::State& state) {
    const auto count = static_cast<std::size_t>(state.range(0));
    core::EventLoop loop;
    drives::epos2::Epos2DriveConfig config;
    config.axis = drives::plant::test::tuned_axis();
    test::Epos2Network network = test::make_epos2_network(loop, count, config);
    auto master = network.bus->connect("master");
    master->on_receive([](const can::Frame&) {});
    // The master's configuration, written the way its SDOs would leave it.
    for (auto& drive : network.drives) {
        auto& od = drive->objects();
        const auto node = drive->node().node_id();
        od.set_as(0x1802, 2, std::uint8_t{1});
        od.set_as(0x1802, 1, std::uint32_t{0x4000'0380U + node});
        drive->node().pdo().reload();
        od.set_as(0x6081, 0, std::uint32_t{1000});
        od.set_as(0x6083, 0, std::uint32_t{10000});
        od.set_as(0x6084, 0, std::uint32_t{10000});
    }
    master->send(can::Frame::data_frame(canopen::kNmtCanId, {0x01, 0x00}));
    const auto rpdo = [&](std::uint16_t word, std::int32_t target) {
        for (auto& drive : network.drives) {
            const auto t = canopen::encode(target);
            master->send(can::Frame::data_frame(0x400U + drive->node().node_id(),
                                                {static_cast<std::uint8_t>(word),
                                                 static_cast<std::uint8_t>(word >> 8), t[0], t[1],
                                                 t[2], t[3]}));
        }
    };
    for (const int word : {0x0006, 0x0007, 0x000F}) { // shutdown, switch on, enable
        rpdo(static_cast<std::uint16_t>(word), 0);
        loop.run_for(5ms);
    }
    std::int64_t millisecond = 0;
    for (auto _ : state) {
        if (millisecond % 500 == 0) {
            rpdo(0x003F, (millisecond / 500) % 2 == 0 ? 20000 : 0);
        } else if (millisecond % 500 == 1) {
            rpdo(0x000F, 0);
        }
        master->send(can::Frame::data_frame(0x080, {}));
        loop.run_for(1ms);
        ++millisecond;
    }
    state.counters["simulated_s"] =
        benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Epos2Network)->Arg(1)->Arg(8)->Arg(32);

} // namespace
