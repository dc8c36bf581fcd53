// The rules chapter 8 puts on configuration objects, on the CAN-only bench: "Changes are only
// supported in 'Disable' state" (refused with 0x08000022 "wrong device state", table 4-12, while
// the power stage is on) and the gear that table 8-103 does not permit (8.2.79).
#include "epos2_bus_fixture.hpp"

#include <vector>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

struct Change {
    std::uint16_t index;
    std::uint8_t sub;
    canopen::Bytes value; ///< valid, and not the present value
};

// One writable entry of every object the remark names: 8.2.41, 8.2.62, 8.2.74 - 8.2.79,
// 8.2.81 - 8.2.83, 8.2.114 (the other factor group objects have one value only), 8.2.129,
// 8.2.130 (pole pair number).
std::vector<Change> disable_state_changes() {
    return {{0x2008, 0, encode(std::uint16_t{0x0100})}, {0x207B, 1, encode(std::uint16_t{8})},
            {0x2210, 1, encode(std::uint32_t{1000})},   {0x2210, 2, encode(std::uint16_t{2})},
            {0x2210, 4, encode(std::uint16_t{1})},      {0x2211, 1, encode(std::uint16_t{1000})},
            {0x2212, 1, encode(std::uint32_t{1000})},   {0x2213, 1, encode(std::uint32_t{7})},
            {0x2220, 0, encode(std::uint16_t{1})},      {0x2230, 1, encode(std::uint32_t{4})},
            {0x2230, 2, encode(std::uint16_t{3})},      {0x2230, 3, encode(std::uint32_t{5000})},
            {0x2301, 1, encode(std::int16_t{100})},     {0x2302, 2, encode(std::int32_t{10})},
            {0x2303, 3, encode(std::int8_t{-1})},       {0x608B, 0, encode(std::int8_t{-1})},
            {0x6402, 0, encode(std::uint16_t{11})},     {0x6410, 3, encode(std::uint8_t{2})}};
}

TEST_F(Epos2DriveOnBus, DisableStateObjectsRefuseChangesWhileThePowerStageIsOn) {
    configure_and_enable(1);
    for (const Change& change : disable_state_changes()) {
        EXPECT_EQ(try_write(change.index, change.sub, change.value), AbortCode::DeviceState)
            << fmt::format("0x{:04X} sub {}", change.index, change.sub);
    }
    // Writing the present value changes nothing; objects without the remark stay writable.
    EXPECT_EQ(try_write(0x2230, 3, encode(std::uint32_t{100'000})), AbortCode::None);
    EXPECT_EQ(try_write(0x6410, 4, encode(std::uint32_t{20'000})), AbortCode::None);

    controlword(kShutdown); // Ready to Switch On: the power stage is off
    run_with_sync(10ms);
    for (const Change& change : disable_state_changes()) {
        EXPECT_EQ(try_write(change.index, change.sub, change.value), AbortCode::None)
            << fmt::format("0x{:04X} sub {}", change.index, change.sub);
    }
}

// Table 8-103: a sinus commutated EC motor (10) on Incremental Encoder 1 permits no gear (*B),
// a DC motor (1) on it does; the numerator 0 ("no gear") is always accepted.
TEST_F(Epos2DriveOnBus, GearNumeratorIsRefusedWhereTable8_103PermitsNoGear) {
    write(0x6402, 0, encode(std::uint16_t{10}));
    EXPECT_EQ(try_write(0x2230, 1, encode(std::uint32_t{4})), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(try_write(0x2230, 1, encode(std::uint32_t{0})), AbortCode::None);
    write(0x6402, 0, encode(std::uint16_t{1}));
    EXPECT_EQ(try_write(0x2230, 1, encode(std::uint32_t{4})), AbortCode::None);
    write(0x2210, 2, encode(std::uint16_t{0})); // no sensor: Current Mode only (*A)
    EXPECT_EQ(try_write(0x2230, 1, encode(std::uint32_t{5})), AbortCode::ParameterIncompatibility);
}

} // namespace
} // namespace eposp::drives::epos2
