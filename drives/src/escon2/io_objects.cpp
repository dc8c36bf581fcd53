// The input and output objects of the ESCON2 (firmware specification 6.2.26 - 6.2.54). The
// mapping rules of tables 59, 65 and 68 are write checks: a functionality is mapped once, the
// PWM functionalities only on digital inputs 1 and 2, nothing on the high-speed pins while
// sensor 2 uses them, and every set value or offset has one source [e]. A mapping that breaks
// them is refused with 0x06040043 "General parameter incompatibility" (table 111).
#include "object_areas.hpp"

#include <array>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <utility>

namespace eposp::drives::escon2 {
namespace {

using namespace canopen::od_types;
using canopen::AbortCode;
using canopen::decode;

constexpr std::uint8_t kNone = 255;
constexpr std::uint8_t kDigitalInputs = 8;
constexpr std::uint8_t kFirstHighSpeedInput = 5;
constexpr std::uint8_t kHighSpeedOutput = 3;
constexpr std::uint32_t kSensor2Encoder = 0x0000'0100; // table 47
constexpr std::uint32_t kSensor1Hall = 0x0000'0010;
constexpr std::int64_t kMaxRpm = 120'000; // "- 120'000 rpm … + 120'000 rpm"

// Table 59: every functionality of inputs 1 and 2 ([a] PWM only there) and of the others.
constexpr std::array<std::int64_t, 20> kInputs1And2 = {255, 37, 36, 33, 32, 29, 28, 27, 23, 22,
                                                       21,  20, 19, 18, 17, 16, 15, 14, 13, 12};
constexpr std::array<std::int64_t, 18> kOtherInputs = {255, 29, 28, 27, 23, 22, 21, 20, 19,
                                                       18,  17, 16, 15, 14, 13, 12, 1,  0};
// Table 65; [HsDigOut1 cannot carry the Hall frequencies].
constexpr std::array<std::int64_t, 8> kOutputs = {255, 33, 32, 26, 25, 18, 17, 16};
constexpr std::array<std::int64_t, 6> kHighSpeedOutputs = {255, 26, 25, 18, 17, 16};
constexpr std::array<std::int64_t, 7> kAnalogInputs = {255, 11, 10, 9, 8, 1, 0}; // table 68
constexpr std::array<std::int64_t, 9> kAnalogOutputs = {255, 13, 12, 11, 10, 9, 8, 1, 0}; // 70

bool sensor2_configured(const canopen::ObjectDictionary& od) {
    return (od.get_as<std::uint32_t>(0x3000, 1) & 0xFF00) == kSensor2Encoder;
}

/// Tables 59 and 68 [e]: which set value a functionality commands, and from which kind of
/// source (PWM, set-value switches, analog). Two sources of one set value exclude each other.
struct SetValueSource {
    char target; ///< 'v' velocity, 'V' velocity offset, 'c' current, 'C' current offset
    char kind;   ///< 'p' PWM, 's' switches, 'a' analog
    bool operator==(const SetValueSource&) const = default;
};

std::optional<SetValueSource> digital_source(std::uint8_t functionality) {
    switch (functionality) {
    case 32:
        return SetValueSource{'v', 'p'};
    case 33:
        return SetValueSource{'V', 'p'};
    case 36:
        return SetValueSource{'c', 'p'};
    case 37:
        return SetValueSource{'C', 'p'};
    case 12:
    case 13:
        return SetValueSource{'v', 's'};
    case 14:
    case 15:
        return SetValueSource{'c', 's'};
    default:
        return std::nullopt;
    }
}

std::optional<SetValueSource> analog_source(std::uint8_t functionality) {
    switch (functionality) {
    case 9:
        return SetValueSource{'v', 'a'};
    case 11:
        return SetValueSource{'V', 'a'};
    case 8:
        return SetValueSource{'c', 'a'};
    case 10:
        return SetValueSource{'C', 'a'};
    default:
        return std::nullopt;
    }
}

/// Whether `source`, written to `index`:`sub`, meets another source of the same set value on
/// any input (digital 0x3142, analog 0x3161).
bool second_source(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub,
                   const std::optional<SetValueSource>& source) {
    if (!source) {
        return false;
    }
    const auto conflicts = [&](std::uint16_t other_index, std::uint8_t other_sub, auto source_of) {
        if (other_index == index && other_sub == sub) {
            return false;
        }
        const auto other = source_of(od.get_as<std::uint8_t>(other_index, other_sub));
        return other && other->target == source->target && other->kind != source->kind;
    };
    for (std::uint8_t input = 1; input <= kDigitalInputs; ++input) {
        if (conflicts(0x3142, input, digital_source)) {
            return true;
        }
    }
    return conflicts(0x3161, 1, analog_source) || conflicts(0x3161, 2, analog_source);
}

/// "Each function can only be mapped once": `value` on another sub of `index`.
bool mapped_elsewhere(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub,
                      std::uint8_t value) {
    if (value == kNone) {
        return false;
    }
    for (const auto& [other, entry] : od.find(index)->subs) {
        if (other != 0 && other != sub && od.get_as<std::uint8_t>(index, other) == value) {
            return true;
        }
    }
    return false;
}

// 6.2.26 - 6.2.32
void add_digital_inputs(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    od.add_object(0x3141, "Digital input properties", kRecord);
    add_entry(od, 0x3141, 1, "Digital inputs logic state", kU16, kRO, 0).pdo_mappable();
    add_entry(od, 0x3141, 2, "Digital inputs polarity", kU16, kRW, 0).persistent();

    od.add_object(0x3142, "Configuration of digital inputs", kArray);
    constexpr std::array<std::int64_t, kDigitalInputs> kDefaults = {16,  17,  18,  19,
                                                                    255, 255, 255, 255};
    for (std::uint8_t input = 1; input <= kDigitalInputs; ++input) {
        const bool high_speed = input >= kFirstHighSpeedInput;
        const std::string name = high_speed
                                     ? fmt::format("High-speed digital input {} configuration",
                                                   input - kFirstHighSpeedInput + 1)
                                     : fmt::format("Digital input {} configuration", input);
        auto entry = add_entry(od, 0x3142, input, name, kU8, kRW, kDefaults[input - 1])
                         .one_of(input <= 2 ? std::span<const std::int64_t>(kInputs1And2)
                                            : std::span<const std::int64_t>(kOtherInputs))
                         .persistent();
        entry.rule([&od, input, high_speed](std::span<const std::uint8_t> value) {
            const auto written = decode<std::uint8_t>(value);
            const bool disabled = high_speed && written != kNone && sensor2_configured(od);
            return disabled || mapped_elsewhere(od, 0x3142, input, written) ||
                           second_source(od, 0x3142, input, digital_source(written))
                       ? AbortCode::ParameterIncompatibility
                       : AbortCode::None;
        });
    }
    add_var(od, 0x3143, "Digital inputs functionality", kU32, kRO, 0).pdo_mappable();

    const auto add_switch_values = [&od, &config](std::uint16_t index, const char* object,
                                                  const char* value, std::int64_t limit) {
        od.add_object(index, object, kArray);
        for (std::uint8_t sub = 1; sub <= 4; ++sub) {
            only_in_power_disable(add_entry(od, index, sub,
                                            fmt::format("Set {} value {}", value, sub - 1), kI32,
                                            kRW, 0)
                                      .range(-limit, limit)
                                      .persistent(),
                                  config);
        }
    };
    const std::int64_t max_current = hardware_data(config.hardware).output_current_limit.max;
    add_switch_values(0x3146, "Velocity set value switch parameter", "velocity", kMaxRpm);
    add_switch_values(0x3147, "Current set value switch parameter", "current", max_current);

    od.add_object(0x314B, "Digital input PWM frequencies", kArray);
    od.add_object(0x314C, "Digital input PWM duty cycles", kArray);
    for (std::uint8_t input = 1; input <= 2; ++input) {
        add_entry(od, 0x314B, input, fmt::format("Digital input {} PWM frequency", input), kU32,
                  kRO, 0)
            .pdo_mappable();
        add_entry(od, 0x314C, input, fmt::format("Digital input {} PWM duty cycle", input), kU16,
                  kRO, 0)
            .pdo_mappable();
    }
}

// 6.2.33 - 6.2.35: the Hall frequencies need the Hall sensor and only one of them at a time.
void add_digital_outputs(canopen::ObjectDictionary& od) {
    od.add_object(0x3150, "Digital outputs properties", kRecord);
    add_entry(od, 0x3150, 1, "Digital outputs logic state", kU16, kRO, 0).pdo_mappable();
    add_entry(od, 0x3150, 2, "Digital outputs polarity", kU16, kRW, 0).persistent();

    od.add_object(0x3151, "Configuration of digital outputs", kArray);
    struct Output {
        const char* name;
        std::int64_t default_value; // table 64
    };
    constexpr std::array<Output, 3> kOutputsTable = {
        Output{"Digital output 1 configuration", 16},
        {"Digital output 2 configuration", 17},
        {"High-speed digital output 1 configuration", 255}};
    for (std::uint8_t output = 1; output <= kOutputsTable.size(); ++output) {
        const bool high_speed = output == kHighSpeedOutput;
        auto entry = add_entry(od, 0x3151, output, kOutputsTable[output - 1].name, kU8, kRW,
                               kOutputsTable[output - 1].default_value)
                         .one_of(high_speed ? std::span<const std::int64_t>(kHighSpeedOutputs)
                                            : std::span<const std::int64_t>(kOutputs))
                         .persistent();
        entry.rule([&od, output, high_speed](std::span<const std::uint8_t> value) {
            const auto written = decode<std::uint8_t>(value);
            const bool frequency = written == 32 || written == 33;
            const std::uint8_t other_frequency = written == 32 ? 33 : 32;
            const bool refused =
                (high_speed && written != kNone && sensor2_configured(od)) ||
                mapped_elsewhere(od, 0x3151, output, written) ||
                (frequency && ((od.get_as<std::uint32_t>(0x3000, 1) & 0xFF) != kSensor1Hall ||
                               mapped_elsewhere(od, 0x3151, output, other_frequency)));
            return refused ? AbortCode::ParameterIncompatibility : AbortCode::None;
        });
    }
    add_var(od, 0x3152, "Digital outputs functionality", kU32, kRW, 0).pdo_mappable();
}

// 6.2.36 - 6.2.43
void add_analog_inputs_and_outputs(canopen::ObjectDictionary& od, const HardwareData& hardware) {
    od.add_object(0x3160, "Analog input properties", kArray);
    od.add_object(0x3161, "Configuration of analog inputs", kArray);
    od.add_object(0x3162, "Analog input general purpose", kArray);
    od.add_object(0x3163, "Analog input adjustment", kRecord);
    od.add_object(0x3164, "Analog input raw values", kArray);
    od.add_object(0x3170, "Analog output properties", kArray);
    od.add_object(0x3171, "Configuration of analog outputs", kArray);
    od.add_object(0x3172, "Analog output general purpose", kArray);
    for (std::uint8_t n = 1; n <= 2; ++n) {
        const std::int64_t default_function = n - 1; // tables 67, 69: general purpose A, B
        const char letter = n == 1 ? 'A' : 'B';
        add_entry(od, 0x3160, n, fmt::format("Analog input {} voltage", n), kI16, kRO, 0)
            .pdo_mappable();
        auto configuration =
            add_entry(od, 0x3161, n, fmt::format("Analog input {} configuration", n), kU8, kRW,
                      default_function)
                .one_of(kAnalogInputs)
                .persistent();
        configuration.rule([&od, n](std::span<const std::uint8_t> value) {
            const auto written = decode<std::uint8_t>(value);
            return mapped_elsewhere(od, 0x3161, n, written) ||
                           second_source(od, 0x3161, n, analog_source(written))
                       ? AbortCode::ParameterIncompatibility
                       : AbortCode::None;
        });
        add_entry(od, 0x3162, n, fmt::format("Analog input general purpose {}", letter), kI16, kRO,
                  0)
            .pdo_mappable();
        add_entry(od, 0x3163, static_cast<std::uint8_t>(2 * n - 1),
                  fmt::format("Analog input {} adjustment offset", n), kI32, kRW, 0)
            .range(-1'000, 1'000)
            .persistent();
        add_entry(od, 0x3163, static_cast<std::uint8_t>(2 * n),
                  fmt::format("Analog input {} adjustment gain factor", n), kU16, kRW, 10'000)
            .range(5'000, 20'000)
            .persistent();
        add_entry(od, 0x3164, n, fmt::format("Analog input {} raw value", n), kU16, kRO, 0)
            .pdo_mappable();
        add_entry(od, 0x3170, n, fmt::format("Analog output {} voltage", n), kI16, kRO, 0)
            .pdo_mappable();
        add_entry(od, 0x3171, n, fmt::format("Analog output {} configuration", n), kU8, kRW,
                  default_function)
            .one_of(kAnalogOutputs)
            .persistent();
        add_entry(od, 0x3172, n, fmt::format("Analog output general purpose {}", letter), kI16, kRW,
                  0)
            .range(hardware.analog_output_low, hardware.analog_output_high)
            .pdo_mappable()
            .persistent();
    }
}

/// A set-value or monitor scaling of two slope points (6.2.44 - 6.2.54), each point an input
/// (duty cycle, voltage) and an output (velocity, current, voltage), in the order of the subs.
struct Point {
    std::string name;
    std::int64_t default_value;
    std::int64_t low;
    std::int64_t high;
    bool ranged = true;
};

void add_scaling(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config,
                 std::uint16_t index, const char* object, std::initializer_list<Point> points) {
    od.add_object(index, object, kRecord);
    std::uint8_t sub = 1;
    for (const Point& point : points) {
        auto entry =
            add_entry(od, index, sub++, point.name, kI32, kRW, point.default_value).persistent();
        if (point.ranged) {
            entry.range(point.low, point.high);
        }
        only_in_power_disable(entry, config);
    }
}

// 6.2.44 - 6.2.51: PWM duty cycles in 0.1 % (100 … 900), voltages in the hardware's analog
// input range, velocities within ±120'000 rpm, currents within ± the largest output current
// limit of table 54.
void add_set_value_scalings(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    const HardwareData& hw = hardware_data(config.hardware);
    const std::int64_t amps = hw.output_current_limit.max;
    const std::int64_t low = hw.analog_input_low;
    const std::int64_t high = hw.analog_input_high;
    const auto pwm = [&](std::uint16_t index, const char* object, const char* what,
                         const char* unit, std::int64_t limit) {
        add_scaling(od, config, index, object,
                    {{fmt::format("{} first duty cycle", what), 100, 100, 900},
                     {fmt::format("{} first {}", what, unit), 0, -limit, limit},
                     {fmt::format("{} second duty cycle", what), 900, 100, 900},
                     {fmt::format("{} second {}", what, unit), 0, -limit, limit}});
    };
    const auto analog = [&](std::uint16_t index, const char* object, const char* what,
                            const char* unit, std::int64_t limit) {
        add_scaling(od, config, index, object,
                    {{fmt::format("{} first voltage", what), low, low, high},
                     {fmt::format("{} first {}", what, unit), 0, -limit, limit},
                     {fmt::format("{} second voltage", what), high, low, high},
                     {fmt::format("{} second {}", what, unit), 0, -limit, limit}});
    };
    pwm(0x3180, "Digital input PWM velocity set value scaling", "Velocity set value", "velocity",
        kMaxRpm);
    pwm(0x3181, "Digital input PWM velocity set value offset scaling", "Velocity set value offset",
        "velocity", kMaxRpm);
    pwm(0x3184, "Digital input PWM current set value scaling", "Current set value", "current",
        amps);
    pwm(0x3185, "Digital input PWM current set value offset scaling", "Current set value offset",
        "current", amps);
    analog(0x31B0, "Analog input velocity set value scaling", "Velocity set value", "velocity",
           kMaxRpm);
    analog(0x31B1, "Analog input velocity set value offset scaling", "Velocity set value offset",
           "velocity", kMaxRpm);
    analog(0x31B4, "Analog input current set value scaling", "Current set value", "current", amps);
    analog(0x31B5, "Analog input current set value offset scaling", "Current set value offset",
           "current", amps);
}

// 6.2.52 - 6.2.54: the monitored value has no range, the voltage the hardware's analog output
// range.
void add_monitor_scalings(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    const HardwareData& hw = hardware_data(config.hardware);
    const std::int64_t low = hw.analog_output_low;
    const std::int64_t high = hw.analog_output_high;
    const auto points = [&](std::string first_value, std::string first_voltage,
                            std::string second_value, std::string second_voltage) {
        return std::array<Point, 4>{Point{std::move(first_value), 0, 0, 0, false},
                                    Point{std::move(first_voltage), low, low, high},
                                    Point{std::move(second_value), 0, 0, 0, false},
                                    Point{std::move(second_voltage), high, low, high}};
    };
    const auto monitor = [&](std::uint16_t index, const char* object, const char* what,
                             const char* unit) {
        const auto p = points(fmt::format("{} actual first {}", what, unit),
                              fmt::format("{} actual first voltage", what),
                              fmt::format("{} actual second {}", what, unit),
                              fmt::format("{} actual second voltage", what));
        add_scaling(od, config, index, object, {p[0], p[1], p[2], p[3]});
    };
    monitor(0x31C1, "Analog output velocity scaling", "Velocity", "velocity");
    monitor(0x31C2, "Analog output current scaling", "Current", "current");
    const auto temperature = [&](const char* section) {
        return points(fmt::format("{} temperature first temperature", section),
                      fmt::format("{} temperature first voltage", section),
                      fmt::format("{} temperature second temperature", section),
                      fmt::format("{} temperature second voltage", section));
    };
    const auto logic = temperature("Logic section");
    const auto stage = temperature("Power stage");
    add_scaling(od, config, 0x31C3, "Analog output temperature scaling",
                {logic[0], logic[1], logic[2], logic[3], stage[0], stage[1], stage[2], stage[3]});
}

} // namespace

void add_io_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config) {
    add_digital_inputs(od, config);
    add_digital_outputs(od);
    add_analog_inputs_and_outputs(od, hardware_data(config.hardware));
    add_set_value_scalings(od, config);
    add_monitor_scalings(od, config);
}

} // namespace eposp::drives::escon2
