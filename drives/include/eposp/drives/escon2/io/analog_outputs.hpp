#pragma once

#include "eposp/drives/escon2/io/two_point_scaling.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec table 70: the functionalities of an analog output (0x3171).
enum class AnalogOutputFunction : std::uint8_t {
    GeneralPurposeA = 0,
    GeneralPurposeB = 1,
    VelocityActual = 8,
    VelocityActualAveraged = 9,
    CurrentActual = 10,
    CurrentActualAveraged = 11,
    TemperatureLogicSection = 12,
    TemperaturePowerStage = 13,
    None = 255,
};

/// The functionality of a 0x3171 value, or none for a reserved code.
std::optional<AnalogOutputFunction> analog_output_function_from_code(std::uint8_t code);

inline constexpr unsigned kAnalogOutputCount = 2;

/// 0x31C1 - 0x31C3 as lines from the monitored value (velocity units, A, °C) to volts, with
/// the Module's defaults: every first and second value 0, so "invalid scaling settings ...
/// will output the voltage configured in ... first voltage" (6.2.52 - 6.2.54).
struct AnalogOutputScalings {
    TwoPointScaling velocity{
        .first_input = 0, .first_value = -4, .second_input = 0, .second_value = 4};
    TwoPointScaling current{
        .first_input = 0, .first_value = -4, .second_input = 0, .second_value = 4};
    TwoPointScaling logic_section_temperature{
        .first_input = 0, .first_value = -4, .second_input = 0, .second_value = 4};
    TwoPointScaling power_stage_temperature{
        .first_input = 0, .first_value = -4, .second_input = 0, .second_value = 4};
};

/// 0x3171 sub 1 / 2 (defaults table 69) and the scalings.
struct AnalogOutputConfiguration {
    std::array<AnalogOutputFunction, kAnalogOutputCount> functions{
        AnalogOutputFunction::GeneralPurposeA, AnalogOutputFunction::GeneralPurposeB};
    AnalogOutputScalings scalings;
};

/// What the outputs monitor, from the drive: 0x606C / 0x30D3 sub 1 (velocity units), 0x30D1
/// sub 2 / 1 (A), 0x2202 sub 1 / 0x3201 sub 2 (°C).
struct MonitoredValues {
    double velocity = 0;
    double velocity_averaged = 0;
    double current = 0;
    double current_averaged = 0;
    double logic_section_temperature = 25;
    double power_stage_temperature = 25;
};

/// The two analog outputs (4.4, 6.2.41 - 6.2.43, 6.2.52 - 6.2.54): a monitored value through its
/// scaling, refreshed by each update (50 kHz on the device, 4.4.1), or the general purpose
/// voltage, which takes effect when written; both limited to the variant's output range
/// (table 71).
class AnalogOutputs {
public:
    /// `low` / `high`: the output range in V (table 71: ±4 V, Nano 0 - 3.3 V).
    AnalogOutputs(double low = -4, double high = 4);

    void configure(const AnalogOutputConfiguration& config);
    const AnalogOutputConfiguration& configuration() const { return config_; }

    /// 0x3172 sub 1 / 2 written (V): shown on the output configured general purpose A / B.
    void write_general_purpose(AnalogOutputFunction which, double volts);
    /// The monitored values now: recomputes the monitoring outputs.
    void update(const MonitoredValues& values);

    /// 0x3170 sub `output` (1 or 2): the voltage at the pin, V; 0 when unconfigured.
    double voltage(unsigned output) const;

private:
    double limited(double volts) const;
    double monitored(AnalogOutputFunction function) const;

    double low_;
    double high_;
    AnalogOutputConfiguration config_;
    std::array<double, 2> general_purpose_{};
    MonitoredValues values_;
};

} // namespace eposp::drives::escon2
