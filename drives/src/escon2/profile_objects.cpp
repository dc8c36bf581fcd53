// The device profile objects of the ESCON2 (firmware specification 6.2.58 - 6.2.81) with the
// units of 2.3 (0x60A9, 0x60AA).
#include "object_areas.hpp"

namespace eposp::drives::escon2 {
namespace {

using namespace canopen::od_types;
using canopen::AbortCode;
using canopen::decode;

constexpr std::int64_t kMaxSpeedRpm = 120'000; // table 101

// 6.2.58 - 6.2.62: the modes of table 100.
void add_device_control_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x603F, "Error code", kU16, kRO, 0).pdo_mappable();
    add_var(od, 0x6040, "Controlword", kU16, kRW, 0).pdo_mappable();
    add_var(od, 0x6041, "Statusword", kU16, kRO, 0).pdo_mappable();
    add_var(od, 0x6060, "Modes of operation", kI8, kRW, -121)
        .one_of({-121, -120})
        .pdo_mappable()
        .persistent();
    add_var(od, 0x6061, "Modes of operation display", kI8, kRO, -121).pdo_mappable();
}

// 6.2.63 - 6.2.75. 0x6076 is the nominal current times the torque constant and "changing the
// value with write access is not permitted". 0x6080 is at most 120'000 rpm, divided by the pole
// pairs for a brushless motor (table 101).
void add_velocity_and_profile_objects(canopen::ObjectDictionary& od,
                                      const Escon2DictionaryConfig& config) {
    add_var(od, 0x606B, "Velocity demand value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x606C, "Velocity actual value", kI32, kRO, 0).pdo_mappable();
    auto rated_torque = add_var(od, 0x6076, "Motor rated torque", kU32, kRW, 0);
    rated_torque.rule([](std::span<const std::uint8_t>) { return AbortCode::ReadOnly; });
    rated_torque.sub().on_read = [&od] {
        const std::uint64_t micro_newton_metres =
            std::uint64_t{od.get_as<std::uint32_t>(0x3001, 1)} *
            od.get_as<std::uint32_t>(0x3001, 5) / 1000; // mA · µNm/A
        return canopen::encode(static_cast<std::uint32_t>(micro_newton_metres));
    };
    add_var(od, 0x6077, "Torque actual value", kI16, kRO, 0).pdo_mappable();
    add_var(od, 0x607F, "Max profile velocity", kU32, kRW, kMaxSpeedRpm)
        .range(1, kU32Max)
        .at_most(od, 0x6080, 0)
        .pdo_mappable()
        .persistent();
    auto max_motor_speed = add_var(od, 0x6080, "Max motor speed", kU32, kRW, kMaxSpeedRpm)
                               .range(1, kMaxSpeedRpm)
                               .pdo_mappable()
                               .persistent();
    max_motor_speed.rule([&od](std::span<const std::uint8_t> value) {
        const bool brushless = od.get_as<std::uint16_t>(0x6402, 0) == 10;
        const std::int64_t pole_pairs = brushless ? od.get_as<std::uint8_t>(0x3001, 3) : 1;
        return decode<std::uint32_t>(value) > kMaxSpeedRpm / pole_pairs ? AbortCode::ValueTooHigh
                                                                        : AbortCode::None;
    });
    const auto acceleration = [&od](std::uint16_t index, const char* name) {
        add_var(od, index, name, kU32, kRW, 10'000)
            .range(1, kU32Max)
            .at_most(od, 0x60C5, 0)
            .pdo_mappable()
            .persistent();
    };
    acceleration(0x6083, "Profile acceleration");
    acceleration(0x6084, "Profile deceleration");
    acceleration(0x6085, "Quick stop deceleration");
    // 2.3, tables 103 and 105: rpm or 0.001 rpm; rpm/s.
    only_in_power_disable(add_var(od, 0x60A9, "SI unit velocity", kU32, kRW, 0x00B4'4700)
                              .one_of({0x00B4'4700, 0xFDB4'4700})
                              .persistent(),
                          config);
    only_in_power_disable(add_var(od, 0x60AA, "SI unit acceleration", kU32, kRW, 0x00C0'0300)
                              .one_of({0x00C0'0300})
                              .persistent(),
                          config);
    add_var(od, 0x60B1, "Velocity offset", kI32, kRW, 0).pdo_mappable();
    add_var(od, 0x60C5, "Max acceleration", kU32, kRW, kU32Max)
        .range(1, kU32Max)
        .pdo_mappable()
        .persistent();
}

// 6.2.76 - 6.2.81
void add_io_and_motor_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    od.add_object(0x60E5, "Additional velocity actual values", kArray);
    add_entry(od, 0x60E5, 1, "Velocity actual value sensor 1", kI32, kRO, 0).pdo_mappable();
    add_entry(od, 0x60E5, 2, "Velocity actual value sensor 2", kI32, kRO, 0).pdo_mappable();
    add_entry(od, 0x60E5, 9, "Velocity actual value averaged sensor 1", kI32, kRO, 0)
        .pdo_mappable();
    add_entry(od, 0x60E5, 10, "Velocity actual value averaged sensor 2", kI32, kRO, 0)
        .pdo_mappable();
    add_var(od, 0x60FD, "Digital inputs", kU32, kRO, 0).pdo_mappable();
    od.add_object(0x60FE, "Digital outputs", kArray);
    add_entry(od, 0x60FE, 1, "Physical outputs", kU32, kRW, 0).pdo_mappable();
    add_var(od, 0x60FF, "Target velocity", kI32, kRW, 0).pdo_mappable();
    only_in_power_disable(
        add_var(od, 0x6402, "Motor type", kU16, kRW, 10).one_of({1, 10}).persistent(), config);
    add_var(od, 0x6502, "Supported drive modes", kU32, kRO, 0x0006'0000).pdo_mappable();
}

} // namespace

void add_profile_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    add_device_control_objects(od);
    add_velocity_and_profile_objects(od, config);
    add_io_and_motor_objects(od, config);
}

} // namespace eposp::drives::escon2
