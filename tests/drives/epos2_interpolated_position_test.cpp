// Interpolated Position Mode (7) of the simulated EPOS2 (EPOS2 FW spec 5.5, 8.2.69, 8.2.70,
// 8.2.123): PVT records queued in the FIFO by 0x20C1, started by controlword bit 4, ended by a
// record of time 0; the buffer's status, levels and sizes; the IPM error 0xFF0C on underflow
// and on a velocity above 0x607F; halt. The reference axis has 2000 qc per turn.
#include "eposp/drives/motion/pvt_segment.hpp"
#include "epos2_bus_fixture.hpp"

#include <cmath>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

constexpr std::int8_t kInterpolatedPositionMode = 7;
constexpr std::uint16_t kEnableIp = 0x0010;      // table 5-33, bit 4
constexpr std::uint16_t kHalt = 0x0100;          // bit 8
constexpr std::uint16_t kIpModeActive = 0x1000;  // table 8-114, bit 12
constexpr std::uint16_t kTargetReached = 0x0400; // bit 10
constexpr std::uint16_t kFault = 0x0008;
constexpr double kCountsPerRpm = 2000.0 / 60;

// Table 5-27: time u8 | velocity s24 | position s32, MSB to LSB.
canopen::Bytes pvt(std::int32_t position, std::int32_t velocity_rpm, std::uint8_t time_ms) {
    const std::uint64_t raw =
        (std::uint64_t{time_ms} << 56) |
        (std::uint64_t{static_cast<std::uint32_t>(velocity_rpm) & 0xFFFFFF} << 32) |
        static_cast<std::uint32_t>(position);
    return encode(raw);
}

class InterpolatedPosition : public Epos2DriveOnBus {
public:
    void enable_buffer() {
        write(0x60C4, 6, encode(std::uint8_t{0})); // clear, then enable access
        write(0x60C4, 6, encode(std::uint8_t{1}));
    }
    std::uint16_t buffer_status() { return read<std::uint16_t>(0x20C4, 1); }
    std::int32_t demand() { return drive.objects().get_as<std::int32_t>(0x6062, 0); }
    bool emcy_with_code(std::uint16_t code) const {
        for (const auto& emcy : emcys) {
            if (emcy.size() >= 2 && (emcy[0] | emcy[1] << 8) == code) {
                return true;
            }
        }
        return false;
    }
};

TEST_F(InterpolatedPosition, ARecordedPvtMotionIsInterpolatedAndEndsAtTimeZero) {
    configure_and_enable(kInterpolatedPositionMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kInterpolatedPositionMode);
    enable_buffer();
    write(0x20C1, 0, pvt(1000, 1200, 100)); // to 1000 qc at 1200 rpm in 100 ms
    write(0x20C1, 0, pvt(3000, 0, 100));    // to rest at 3000 qc
    write(0x20C1, 0, pvt(3000, 0, 0));      // the end
    EXPECT_EQ(read<std::uint16_t>(0x60C4, 4), 3u) << "records queued";
    EXPECT_EQ(read<std::uint32_t>(0x60C4, 2), 61u) << "free records";

    controlword(kEnableOperation | kEnableIp);
    loop.run_for(1ms); // the RPDO is applied; the motion starts now
    const motion::PvtSegment first(0, 0, 1000, 1200 * kCountsPerRpm, 0.1);
    run_with_sync(50ms);
    EXPECT_NEAR(demand(), first.at(0.05).position, 40);
    EXPECT_NE(tpdos.back().statusword & kIpModeActive, 0);
    EXPECT_NE(drive.objects().get_as<std::uint16_t>(0x20C4, 1) & 0x8000, 0) << "IP mode active";
    run_with_sync(250ms);
    EXPECT_EQ(demand(), 3000);
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x6064, 0), 3000, 20);
    EXPECT_EQ(tpdos.back().statusword & kIpModeActive, 0) << "time 0 ended it";
    EXPECT_NE(tpdos.back().statusword & kTargetReached, 0);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    EXPECT_TRUE(emcys.empty());
}

TEST_F(InterpolatedPosition, FewerThanTwoRecordsWhileActiveIsTheUnderflowError) {
    configure_and_enable(kInterpolatedPositionMode);
    enable_buffer();
    write(0x20C1, 0, pvt(500, 0, 50));
    controlword(kEnableOperation | kEnableIp);
    run_with_sync(20ms);
    EXPECT_TRUE(emcy_with_code(0xFF0C));
    EXPECT_NE(tpdos.back().statusword & kFault, 0);
    EXPECT_NE(buffer_status() & 0x0100, 0) << "underflow error, table 8-100";
}

TEST_F(InterpolatedPosition, AVelocityAboveMaxProfileVelocityAbortsTheMotion) {
    write(0x607F, 0, encode(std::uint32_t{2000}));
    configure_and_enable(kInterpolatedPositionMode);
    enable_buffer();
    write(0x20C1, 0, pvt(20000, 0, 100)); // peaks at 1.5 * 20000 qc / 0.1 s = 9000 rpm
    write(0x20C1, 0, pvt(20000, 0, 0));
    controlword(kEnableOperation | kEnableIp);
    run_with_sync(100ms);
    EXPECT_TRUE(emcy_with_code(0xFF0C));
    const std::uint16_t status = buffer_status();
    EXPECT_NE(status & 0x0400, 0) << "velocity error";
    EXPECT_NE(status & 0x0004, 0) << "velocity warning: above 0x6081 (1000 rpm) too";
}

TEST_F(InterpolatedPosition, TheBufferShowsItsLevelsAndRefusesRecordsWhileAccessIsDenied) {
    configure_and_enable(kInterpolatedPositionMode);
    write(0x20C1, 0, pvt(100, 0, 10));
    EXPECT_EQ(read<std::uint16_t>(0x60C4, 4), 0u) << "access denied after the mode started";
    EXPECT_EQ(buffer_status() & 0x4000, 0);
    enable_buffer();
    EXPECT_NE(buffer_status() & 0x4000, 0) << "buffer enabled";
    for (int i = 0; i < 3; ++i) {
        write(0x20C1, 0, pvt(100 * i, 0, 10));
    }
    EXPECT_NE(buffer_status() & 0x0001, 0) << "3 records: below the underflow level 4";
    for (int i = 3; i < 61; ++i) {
        write(0x20C1, 0, pvt(100 * i, 0, 10));
    }
    EXPECT_EQ(buffer_status() & 0x0003, 0x0002) << "61 records: above the overflow level 60";
    for (int i = 61; i < 65; ++i) {
        write(0x20C1, 0, pvt(100 * i, 0, 10));
    }
    EXPECT_EQ(read<std::uint16_t>(0x60C4, 4), 64u);
    EXPECT_EQ(read<std::uint32_t>(0x60C4, 2), 0u);
    EXPECT_NE(buffer_status() & 0x0200, 0) << "the 65th record overflowed";
    write(0x60C4, 6, encode(std::uint8_t{0}));
    EXPECT_EQ(buffer_status() & 0x7FFF, 0x0001) << "cleared: flags gone, access denied";
}

TEST_F(InterpolatedPosition, HaltStopsTheAxisWithTheProfileDeceleration) {
    configure_and_enable(kInterpolatedPositionMode);
    enable_buffer();
    write(0x20C1, 0, pvt(6000, 1800, 200));
    write(0x20C1, 0, pvt(12000, 0, 200));
    write(0x20C1, 0, pvt(12000, 0, 0));
    controlword(kEnableOperation | kEnableIp);
    run_with_sync(200ms); // at 1800 rpm
    controlword(kEnableOperation | kEnableIp | kHalt);
    run_with_sync(300ms); // 0x6084 = 10 000 rpm/s: at rest after 180 ms
    EXPECT_EQ(tpdos.back().statusword & kIpModeActive, 0);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x606B, 0), 0) << "velocity demand";
    EXPECT_LT(demand(), 12000);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    EXPECT_TRUE(emcys.empty());
}

} // namespace
} // namespace eposp::drives::epos2
