// The drive's numbers, bit for bit: a profile position move, a target changed on the way and a
// quick stop, sampled every 10 ms (the motor's current, speed and angle as the model holds them,
// and the actual values 0x6064 / 0x606C / 0x6078 as a master reads them). The simulation's speed
// work (docs/performance.md) must not change one bit of these; a change of the physics on purpose
// updates the table (the failure message prints the new row in the table's own format).
#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/test/moving_epos2_network.hpp"

#include <chrono>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <ostream>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

using namespace std::chrono_literals;

struct Sample {
    std::int64_t ms; ///< virtual time
    double current;  ///< A, the motor model's state
    double speed;    ///< rad/s
    double angle;    ///< rad
    std::int32_t position_actual;
    std::int32_t velocity_actual;
    std::int16_t current_actual;
    friend bool operator==(const Sample&, const Sample&) = default;
};

// As a row of the table.
std::string source_row(const Sample& s) {
    return fmt::format("{{{}, {:a}, {:a}, {:a}, {}, {}, {}}},", s.ms, s.current, s.speed, s.angle,
                       s.position_actual, s.velocity_actual, s.current_actual);
}
void PrintTo(const Sample& sample, std::ostream* out) {
    *out << source_row(sample);
}

// The reference axis (`eposp drive epos2` without --config), commanded as by SDO writes.
std::vector<Sample> commanded_run() {
    core::EventLoop loop;
    can::VirtualBus bus{loop};
    const std::unique_ptr<can::VirtualPort> port = bus.connect("epos2");
    // A node alone on the bus sees no acknowledgement and goes error-passive (0x8120, 4.2.15).
    const std::unique_ptr<can::VirtualPort> listener = bus.connect("master");
    Epos2DriveConfig config;
    config.dictionary.node_id = 2;
    Epos2Drive drive(loop, *port, std::move(config));
    drive.start();
    const auto write = [&drive](std::uint16_t index, auto value) {
        ASSERT_EQ(drive.objects().write(index, 0, canopen::encode(value)),
                  canopen::AbortCode::None);
    };
    const auto at = [&loop](core::Duration when, const std::function<void()>& fn) {
        loop.run_until(core::TimePoint{when});
        fn();
    };
    std::vector<Sample> samples;
    const auto sample_until = [&](core::Duration end) {
        while (loop.now() + 10ms <= core::TimePoint{end}) {
            loop.run_for(10ms);
            const plant::MotorState& motor = drive.axis().motor().state();
            const auto& od = drive.objects();
            samples.push_back(
                {std::chrono::duration_cast<std::chrono::milliseconds>(
                     loop.now().time_since_epoch())
                     .count(),
                 motor.current, motor.speed, motor.angle, od.get_as<std::int32_t>(0x6064, 0),
                 od.get_as<std::int32_t>(0x606C, 0), od.get_as<std::int16_t>(0x6078, 0)});
        }
    };
    at(10ms, [&] {
        write(0x6081, std::uint32_t{1500});
        write(0x6083, std::uint32_t{8000});
        write(0x6084, std::uint32_t{12000});
        write(0x6085, std::uint32_t{20000});
        write(0x6040, std::uint16_t{0x0006}); // shutdown
    });
    at(20ms, [&] { write(0x6040, std::uint16_t{0x000F}); }); // switch on, enable operation
    at(50ms, [&] {
        write(0x607A, std::int32_t{6000});
        write(0x6040, std::uint16_t{0x003F}); // new set-point, absolute, at once
    });
    at(55ms, [&] { write(0x6040, std::uint16_t{0x000F}); });
    sample_until(250ms);
    write(0x607A, std::int32_t{-3000}); // at 245 ms: reverses on the way
    write(0x6040, std::uint16_t{0x003F});
    sample_until(255ms);
    write(0x6040, std::uint16_t{0x000F});
    sample_until(400ms);
    write(0x6040, std::uint16_t{0x000B}); // at 395 ms: quick stop
    sample_until(600ms);
    return samples;
}

// Recorded at commit bd64bf7, before the speed work: {ms, current, speed, angle, 0x6064, 0x606C,
// 0x6078}.
const std::vector<Sample> kReference = {
    {65, 0x1.4740da6bbf282p-2, 0x1.82aca13e986d1p+3, 0x1.627cd5d231013p-4, 27, 90, 320},
    {75, 0x1.25965056b1d35p-2, 0x1.4bc1adea6aea3p+4, 0x1.ff220e7f02aa3p-3, 79, 180, 287},
    {85, 0x1.f4ab403528b35p-3, 0x1.cf57ea92c8c63p+4, 0x1.fce6834604e5ep-2, 158, 270, 244},
    {95, 0x1.5e75d9ab9d072p-2, 0x1.2e0603c71929bp+5, 0x1.a99c7cd143c09p-1, 264, 330, 342},
    {105, 0x1.2f8382ac7bab5p-2, 0x1.6fb21988128c5p+5, 0x1.3fffa4501a9ecp+0, 397, 420, 296},
    {115, 0x1.0572e775adf29p-2, 0x1.b4a046d49d941p+5, 0x1.c0c6498513581p+0, 558, 510, 255},
    {125, 0x1.614dbbca1a3dep-2, 0x1.f7543d56d2a74p+5, 0x1.2b6325213215p+1, 744, 570, 345},
    {135, 0x1.325b665880239p-2, 0x1.1cc37d016d5ap+6, 0x1.813c185bc0023p+1, 958, 660, 299},
    {145, 0x1.919f797327bf9p-2, 0x1.3efb841096701p+6, 0x1.e1c96cbffe5aap+1, 1198, 720, 392},
    {155, 0x1.64196fc0dd24p-2, 0x1.60c47609c7085p+6, 0x1.2686501d5e18bp+2, 1464, 810, 348},
    {165, 0x1.351ad975c04cep-2, 0x1.81c99c517617ap+6, 0x1.6182a67043f4ap+2, 1758, 900, 302},
    {175, 0x1.02ac63f886af6p-2, 0x1.a21eb10565c1p+6, 0x1.a1dc69692d743p+2, 2078, 990, 253},
    {185, 0x1.ac322770da43fp-3, 0x1.c3cf9e971c716p+6, 0x1.e78cc22dc9dd9p+2, 2424, 1080, 209},
    {195, 0x1.37bda6b06ce8bp-2, 0x1.e6c2299b7fa57p+6, 0x1.195027673367bp+3, 2798, 1140, 304},
    {205, 0x1.054aeed6560a6p-2, 0x1.038cd0cd63ebbp+7, 0x1.4188af747d692p+3, 3198, 1230, 255},
    {215, 0x1.b1676e59365bcp-3, 0x1.148241daa3d2p+7, 0x1.6c7740d855a02p+3, 3625, 1320, 212},
    {225, -0x1.15fd328ae67f1p-2, 0x1.f0f9a499db685p+6, 0x1.9676297b4d2dap+3, 4043, 1200, -271},
    {235, -0x1.124bde2f4f6b8p-2, 0x1.bdcfeecb4437fp+6, 0x1.bc295a0b3b19dp+3, 4418, 1080, -268},
    {245, -0x1.0e87fdc625eabp-2, 0x1.8b843f78ac9e4p+6, 0x1.ddd5eb5e8e82ap+3, 4753, 960, -264},
    {255, -0x1.0aae0335d3b7fp-2, 0x1.59e16238a977dp+6, 0x1.fb832b106431dp+3, 5048, 840, -260},
    {265, -0x1.05d3350aad833p-2, 0x1.28775be81b4d5p+6, 0x1.0a94c02e4968cp+4, 5303, 720, -256},
    {275, -0x1.0a3ac1e85850bp-2, 0x1.ea9cfd9a62548p+5, 0x1.156b971db6d0dp+4, 5519, 600, -260},
    {285, -0x1.056057da693bdp-2, 0x1.88790f65b8073p+5, 0x1.1e3cf3edeead6p+4, 5694, 480, -255},
    {295, -0x1.09cc5ef33d922p-2, 0x1.229e09c39385bp+5, 0x1.2512a10012fbbp+4, 5830, 360, -260},
    {305, -0x1.96a8da0b11008p-2, 0x1.7955ff1fab6f4p+4, 0x1.29dec6b706187p+4, 5925, 270, -397},
    {315, -0x1.08849102fdea2p-2, 0x1.67d3cfcb6d27ap+3, 0x1.2ca82a6eca638p+4, 5981, 120, -258},
    {325, -0x1.40630913ff575p-3, -0x1.9573ae8bbd5cfp-1, 0x1.2d7169fb0137ep+4, 5997, 0, -156},
    {335, -0x1.18c34d38e72ecp-3, -0x1.e8c488026341bp+2, 0x1.2cd13fc5f8927p+4, 5984, -90, -137},
    {345, -0x1.993a992daa665p-2, -0x1.0f4b62619587ap+4, 0x1.2adf5457fecadp+4, 5945, -120, -400},
    {355, -0x1.e272a40ab65abp-3, -0x1.9b5192d6f60f8p+4, 0x1.277a4cfc39393p+4, 5878, -240, -236},
    {365, -0x1.923c0df815161p-3, -0x1.114777463bf94p+5, 0x1.22aecc3f29ccap+4, 5782, -330, -196},
    {375, -0x1.3f5dd6c91f88bp-3, -0x1.553f7a7a20309p+5, 0x1.1c85d10383de2p+4, 5660, -420, -156},
    {385, -0x1.048abb23e9314p-2, -0x1.9c78ae5f5fc57p+5, 0x1.1500a8420dba8p+4, 5510, -480, -254},
    {395, -0x1.5eab3a1c96e6ep-2, -0x1.de70b4b8789eep+5, 0x1.0c2012b0b17ffp+4, 5334, -540, -342},
    {405, 0x1.7c84fb8825a77p-2, -0x1.1c6bb795bfb8ap+5, 0x1.0535b48e77dc6p+4, 5196, -360, 372},
    {415, 0x1.be360b629cef7p-2, -0x1.0b50d3458ee2bp+4, 0x1.00ff33ead2514p+4, 5112, -180, 436},
    {425, -0x1.a877ba37243f2p-5, 0x1.21dea2020d348p+0, 0x1.ffdfd910dbd1dp+3, 5091, 0, -52},
    {435, -0x1.d666f34ad291p-5, -0x1.f5cb38a918caep-3, 0x1.ffe1846ff53dep+3, 5091, 0, -57},
    {445, -0x1.a76e62c031c81p-5, -0x1.ac35d9e4aede2p-3, 0x1.ffc58a8dc5f32p+3, 5090, 0, -52},
    {455, -0x1.7730145ceae09p-5, -0x1.8d884b8d7f4b5p-7, 0x1.ffb0135e47263p+3, 5089, 0, -46},
    {465, -0x1.80a040cc8fa67p-5, -0x1.3cd398242a1b9p-3, 0x1.ffa98a303f2d4p+3, 5089, 0, -47},
    {475, 0x1.829079acbfea1p-4, 0x1.21bd6d02c4242p-4, 0x1.ff973e7ec6c37p+3, 5088, -30, 94},
    {485, -0x1.577768924c807p-5, 0x0p+0, 0x1.ff97674f729a3p+3, 5088, 0, -42},
    {495, -0x1.5f8e442ae23aap-5, -0x1.dc3c6efa77fa2p-11, 0x1.ff9765df1f64bp+3, 5088, 0, -43},
    {505, -0x1.679712a464eeep-5, -0x1.cde98cfa963aep-6, 0x1.ff96769d7e3bp+3, 5088, 0, -44},
    {515, -0x1.6f9fe83ba7ad4p-5, -0x1.7e4c65a5fb6d1p-4, 0x1.ff91be1755872p+3, 5088, 0, -45},
    {525, -0x1.77a8c4f70f43dp-5, -0x1.91f6bd931a59bp-3, 0x1.ff86230723d91p+3, 5088, 0, -46},
    {535, -0x1.4464db359bb8fp-5, 0x0p+0, 0x1.ff7e8c40429dfp+3, 5087, 0, -40},
    {545, -0x1.4b354d428091dp-5, 0x0p+0, 0x1.ff7e8c40429dfp+3, 5087, 0, -40},
    {555, -0x1.5205bf44283ffp-5, 0x0p+0, 0x1.ff7e8c40429dfp+3, 5087, 0, -41},
    {565, -0x1.58d63145cfee2p-5, 0x0p+0, 0x1.ff7e8c40429dfp+3, 5087, 0, -42},
    {575, -0x1.5fa36fae58ee8p-5, -0x1.27219a6cc0d2ep-10, 0x1.ff7e8a1a27992p+3, 5087, 0, -43},
    {585, -0x1.66658898557p-5, -0x1.a2e67d966351ap-6, 0x1.ff7da99f42125p+3, 5087, 0, -44},
    {595, -0x1.6d27a785f3144p-5, -0x1.4f42ca00f7beep-4, 0x1.ff797a96935bcp+3, 5087, 0, -45},
};

TEST(Epos2ReferenceTrajectory, MoveReversalAndQuickStopGiveTheRecordedSamplesBitForBit) {
    const std::vector<Sample> samples = commanded_run();
    ASSERT_EQ(samples.size(), kReference.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        EXPECT_EQ(samples[i], kReference[i]);
    }
}

/// FNV-1a, 64 bits.
class Fnv1a {
public:
    void add(std::uint64_t value, int bytes = 8) {
        for (int i = 0; i < bytes; ++i) {
            hash_ = (hash_ ^ ((value >> (8 * i)) & 0xFF)) * 0x100000001B3ULL;
        }
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xCBF29CE484222325ULL;
};

// Eight drives moving on one virtual bus, every wire event (start and end of frame to the
// nanosecond, identifier, data, sender) folded into one hash for 1.2 s of SYNC, TPDOs and
// RPDOs. The speed work on the bus and the drives must not move one frame by a bit time nor
// change one byte: a change of the bus or drive behaviour on purpose updates the figures (the
// failure message prints the new hash).
TEST(Epos2NetworkTrace, MovingDrivesGiveTheRecordedWireEvents) {
    core::EventLoop loop;
    test::MovingEpos2Network network(loop, 8);
    Fnv1a hash;
    std::uint64_t events = 0;
    network.bus().add_observer([&](const can::WireEvent& event) {
        ++events;
        hash.add(static_cast<std::uint64_t>(event.start.time_since_epoch().count()));
        hash.add(static_cast<std::uint64_t>(event.end.time_since_epoch().count()));
        hash.add(event.frame.id, 4);
        hash.add(event.frame.dlc, 1);
        for (const std::uint8_t byte : event.frame.payload()) {
            hash.add(byte, 1);
        }
        for (const char c : event.sender) {
            hash.add(static_cast<std::uint8_t>(c), 1);
        }
    });
    for (int millisecond = 0; millisecond < 1200; ++millisecond) {
        network.run_millisecond();
    }
    EXPECT_EQ(events, 10896U);
    EXPECT_EQ(hash.value(), 0xC1DA1CA6C7754EE9U) << std::hex << "0x" << hash.value();
}

} // namespace
} // namespace eposp::drives::epos2
