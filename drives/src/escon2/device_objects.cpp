// The device objects of the ESCON2 (firmware specification 6.2.8 - 6.2.25 and 6.2.55 - 6.2.57):
// identity, supply, temperatures, axis configuration, motor data, sensors, controllers and the
// actual values. Cross-object rules of the manual are write checks; a value that breaks one is
// refused with 0x06040043 "General parameter incompatibility" (table 111).
#include "object_areas.hpp"

#include <array>
#include <fmt/format.h>

namespace eposp::drives::escon2 {
namespace {

using namespace canopen::od_types;
using canopen::AbortCode;
using canopen::decode;

constexpr std::uint16_t kMotorTypeIndex = 0x6402;
constexpr std::uint16_t kBrushedDcMotor = 1;           // table 108
constexpr std::uint32_t kSensor1Hall = 0x0000'0010;    // table 47
constexpr std::uint32_t kSensor2Encoder = 0x0000'0100; // table 47

bool brushed_dc(const canopen::ObjectDictionary& od) {
    return od.get_as<std::uint16_t>(kMotorTypeIndex, 0) == kBrushedDcMotor;
}

AbortCode compatible_if(bool condition) {
    return condition ? AbortCode::None : AbortCode::ParameterIncompatibility;
}

// 6.2.8, 6.2.9
void add_identity_and_memory(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    od.add_object(0x2100, "Additional identity", kRecord);
    add_entry(od, 0x2100, 1, "Serial number complete", kU64, kRO,
              static_cast<std::int64_t>(config.serial_number));
    od.add_object(0x210C, "Custom persistent memory", kArray);
    for (std::uint8_t sub = 1; sub <= 4; ++sub) {
        add_entry(od, 0x210C, sub, fmt::format("Custom persistent memory {}", sub), kU32, kRW, 0)
            .persistent();
    }
}

// 6.2.10 - 6.2.12: the undervoltage limit stays below the overvoltage limit by both hystereses
// (6.2.11.1, 6.2.11.2).
void add_supply_and_temperature(canopen::ObjectDictionary& od, const HardwareData& hardware) {
    od.add_object(0x2200, "Power supply", kRecord);
    add_entry(od, 0x2200, 1, "Power supply voltage", kU16, kRO, 0);
    od.add_object(0x2201, "Power supply supervision", kRecord);
    const std::int64_t gap = hardware.undervoltage_hysteresis + hardware.overvoltage_hysteresis;
    const auto& under = hardware.undervoltage_limit;
    auto undervoltage =
        add_entry(od, 0x2201, 1, "Power supply undervoltage limit", kU32, kRW, under.default_value)
            .range(under.min, under.max)
            .persistent();
    undervoltage.rule([&od, gap](std::span<const std::uint8_t> value) {
        return compatible_if(decode<std::uint32_t>(value) + gap <
                             od.get_as<std::uint32_t>(0x2201, 2));
    });
    const auto& over = hardware.overvoltage_limit;
    auto overvoltage =
        add_entry(od, 0x2201, 2, "Power supply overvoltage limit", kU32, kRW, over.default_value)
            .range(over.min, over.max)
            .persistent();
    overvoltage.rule([&od, gap](std::span<const std::uint8_t> value) {
        return compatible_if(decode<std::uint32_t>(value) >
                             od.get_as<std::uint32_t>(0x2201, 1) + gap);
    });
    od.add_object(0x2202, "Thermal protection", kRecord);
    add_entry(od, 0x2202, 1, "Temperature logic section", kI16, kRO, 0).pdo_mappable();
}

// 6.2.13, tables 47 - 52: the sensors, the control structure on them and the commutation
// sensors, which must suit the motor type.
void add_axis_configuration(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    od.add_object(0x3000, "Axis configuration", kRecord);
    const auto sensors = [&od] {
        return od.get_as<std::uint32_t>(0x3000, 1);
    };

    auto sensor_configuration =
        add_entry(od, 0x3000, 1, "Sensors configuration", kU32, kRW, 0x0000'0110)
            .one_of({0x000, 0x010, 0x100, 0x110})
            .persistent();
    sensor_configuration.rule([&od](std::span<const std::uint8_t> value) {
        return compatible_if(!brushed_dc(od) || (decode<std::uint32_t>(value) & 0xFF) == 0);
    });

    auto control_structure = add_entry(od, 0x3000, 2, "Control structure", kU32, kRW, 0x0002'0011)
                                 .one_of({0x0000'0001, 0x0001'0011, 0x0002'0011})
                                 .persistent();
    control_structure.rule([&od, sensors](std::span<const std::uint8_t> value) {
        switch (decode<std::uint32_t>(value)) {
        case 0x0001'0011:
            return compatible_if(!brushed_dc(od) && (sensors() & 0xFF) == kSensor1Hall);
        case 0x0002'0011:
            return compatible_if((sensors() & 0xFF00) == kSensor2Encoder);
        default:
            return AbortCode::None;
        }
    });

    auto commutation = add_entry(od, 0x3000, 3, "Commutation sensors", kU32, kRW, 0x0000'0012)
                           .one_of({0x00, 0x10, 0x12})
                           .persistent();
    commutation.rule([&od, sensors](std::span<const std::uint8_t> value) {
        const auto written = decode<std::uint32_t>(value);
        if (brushed_dc(od)) {
            return compatible_if(written == 0);
        }
        const bool hall = (sensors() & 0xFF) == kSensor1Hall;
        const bool encoder = (sensors() & 0xFF00) == kSensor2Encoder;
        return compatible_if((written == 0x10 && hall) || (written == 0x12 && hall && encoder));
    });

    auto miscellaneous = add_entry(od, 0x3000, 4, "Axis configuration miscellaneous", kU32, kRW, 0)
                             .one_of({0x000, 0x001, 0x100, 0x101, 0x200, 0x201, 0x300, 0x301})
                             .persistent();
    add_entry(od, 0x3000, 5, "Main sensor resolution", kU32, kRO, 0);
    for (auto entry : {sensor_configuration, control_structure, commutation, miscellaneous}) {
        only_in_power_disable(entry, config);
    }
}

// 6.2.14, 6.2.15
void add_motor_data(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    const HardwareData& hardware = hardware_data(config.hardware);
    od.add_object(0x3001, "Motor data", kRecord);
    const auto& nominal = hardware.nominal_current;
    add_entry(od, 0x3001, 1, "Nominal current", kU32, kRW, nominal.default_value)
        .range(nominal.min, nominal.max)
        .pdo_mappable()
        .persistent();
    const auto& limit = hardware.output_current_limit;
    add_entry(od, 0x3001, 2, "Output current limit", kU32, kRW, limit.default_value)
        .range(limit.min, limit.max)
        .pdo_mappable()
        .persistent();
    only_in_power_disable(
        add_entry(od, 0x3001, 3, "Number of pole pairs", kU8, kRW, 1).range(1, 255).persistent(),
        config);
    add_entry(od, 0x3001, 4, "Thermal time constant winding", kU16, kRW, 40)
        .range(1, 10'000)
        .persistent();
    only_in_power_disable(
        add_entry(od, 0x3001, 5, "Torque constant", kU32, kRW, 0).range(0, 10'000'000).persistent(),
        config);

    od.add_object(0x3002, "Electrical system parameters", kRecord);
    add_entry(od, 0x3002, 1, "Electrical resistance", kU32, kRW, 0).persistent();
    add_entry(od, 0x3002, 2, "Electrical inductance", kU16, kRW, 0).persistent();
}

// 6.2.16, 6.2.17, tables 55 - 57: reserved bits must stay 0.
void add_sensors(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    od.add_object(0x3010, "Digital incremental encoder S2", kRecord);
    only_in_power_disable(
        add_entry(od, 0x3010, 1, "Digital incremental encoder number of pulses", kU32, kRW, 500)
            .range(16, 2'500'000)
            .persistent(),
        config);
    only_in_power_disable(add_entry(od, 0x3010, 2, "Digital incremental encoder type", kU16, kRW, 0)
                              .one_of({0x000, 0x010, 0x200, 0x210})
                              .persistent(),
                          config);
    od.add_object(0x301A, "Digital Hall sensor S1", kRecord);
    only_in_power_disable(add_entry(od, 0x301A, 1, "Digital Hall sensor type", kU16, kRW, 0)
                              .one_of({0x00, 0x01, 0x10, 0x11})
                              .persistent(),
                          config);
    add_entry(od, 0x301A, 2, "Digital Hall sensor pattern", kU16, kRO, 0);
}

// 6.2.18, 6.2.19
void add_controller_parameters(canopen::ObjectDictionary& od) {
    od.add_object(0x30A0, "Current control parameter set", kRecord);
    add_entry(od, 0x30A0, 1, "Current controller P gain", kU32, kRW, 1'171'880)
        .pdo_mappable()
        .persistent();
    add_entry(od, 0x30A0, 2, "Current controller I gain", kU32, kRW, 3'906'250)
        .pdo_mappable()
        .persistent();
    od.add_object(0x30A2, "Velocity control parameter set", kRecord);
    add_entry(od, 0x30A2, 1, "Velocity controller P gain", kU32, kRW, 20'000)
        .pdo_mappable()
        .persistent();
    add_entry(od, 0x30A2, 2, "Velocity controller I gain", kU32, kRW, 500'000)
        .pdo_mappable()
        .persistent();
    add_entry(od, 0x30A2, 3, "Velocity controller FF velocity gain", kU32, kRW, 0)
        .pdo_mappable()
        .persistent();
    add_entry(od, 0x30A2, 4, "Velocity controller FF acceleration gain", kU32, kRW, 0)
        .pdo_mappable()
        .persistent();
    add_entry(od, 0x30A2, 5, "Velocity controller filter cut-off frequency", kU16, kRW, 600)
        .range(1, 10'000)
        .persistent();
}

// 6.2.20 - 6.2.25
void add_actual_and_target_values(canopen::ObjectDictionary& od) {
    add_var(od, 0x30D0, "Current demand value", kI32, kRO, 0).pdo_mappable();
    od.add_object(0x30D1, "Current actual values", kArray);
    add_entry(od, 0x30D1, 1, "Current actual value averaged", kI32, kRO, 0).pdo_mappable();
    add_entry(od, 0x30D1, 2, "Current actual value", kI32, kRO, 0).pdo_mappable();
    od.add_object(0x30D2, "Torque actual values", kArray);
    add_entry(od, 0x30D2, 1, "Torque actual value averaged", kI16, kRO, 0).pdo_mappable();
    od.add_object(0x30D3, "Velocity actual values", kArray);
    add_entry(od, 0x30D3, 1, "Velocity actual value averaged", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x30F0, "Target current", kI32, kRW, 0);
    add_var(od, 0x30F1, "Current offset", kI32, kRW, 0);
}

// 6.2.55 - 6.2.57
void add_protection_and_motor_control(canopen::ObjectDictionary& od, const HardwareData& hardware) {
    od.add_object(0x3200, "Thermal protection motor", kRecord);
    add_entry(od, 0x3200, 1, "I2t level motor", kU16, kRO, 0).pdo_mappable();
    od.add_object(0x3201, "Thermal protection power stage", kRecord);
    add_entry(od, 0x3201, 1, "I2t level power stage", kU16, kRO, 0).pdo_mappable();
    add_entry(od, 0x3201, 2, "Temperature power stage", kI16, kRO, 0).pdo_mappable();
    const auto& max_temperature = hardware.max_temperature_power_stage;
    add_entry(od, 0x3201, 3, "Max temperature power stage", kU16, kRW,
              max_temperature.default_value)
        .range(max_temperature.min, max_temperature.max)
        .persistent();
    od.add_object(0x3203, "Motor control", kRecord);
    add_entry(od, 0x3203, 1, "PWM duty cycle actual value", kU16, kRO, 0).pdo_mappable();
}

} // namespace

void add_device_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    const HardwareData& hardware = hardware_data(config.hardware);
    add_identity_and_memory(od, config);
    add_supply_and_temperature(od, hardware);
    add_axis_configuration(od, config);
    add_motor_data(od, config);
    add_sensors(od, config);
    add_controller_parameters(od);
    add_actual_and_target_values(od);
    add_protection_and_motor_control(od, hardware);
}

} // namespace eposp::drives::escon2
