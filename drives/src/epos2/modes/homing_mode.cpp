#include "homing_mode.hpp"

namespace eposp::drives::epos2 {

void HomingMode::start(double, std::int64_t position, bool) {
    services_.homing.reset(static_cast<double>(position));
}

void HomingMode::on_controlword(const ControlwordChange& change) {
    motion::HomingProcedure& homing = services_.homing;
    if ((change.rising & kNewSetpointBit) != 0 && change.enabled) {
        homing.start(change.now, parameters(), change.last_demand);
    }
    if ((change.falling & kNewSetpointBit) != 0) {
        homing.interrupt(change.now);
    }
    if (((change.rising | change.falling) & kHaltBit) != 0) {
        homing.set_halt(change.now, (change.controlword & kHaltBit) != 0);
    }
}

ModeDemand HomingMode::demand(const ModeInputs& inputs) {
    const plant::SwitchStates switches = services_.switches();
    const motion::HomingStep step =
        services_.homing.update(inputs.now, {.position = inputs.position,
                                             .negative_limit = switches.negative_limit,
                                             .positive_limit = switches.positive_limit,
                                             .home_switch = switches.home,
                                             .index_position = inputs.index_position,
                                             .current = inputs.current});
    return {.motion = step.demand, .position_offset = step.position_offset};
}

std::uint16_t HomingMode::statusword_bits(double now, bool) const {
    return services_.homing.statusword_bits(now);
}

void HomingMode::drive_disabled(double now) {
    if (services_.homing.in_progress()) {
        services_.homing.drive_disabled(now);
    }
}

motion::HomingParameters HomingMode::parameters() const {
    const auto& od = services_.objects;
    motion::HomingParameters parameters;
    parameters.method = motion::to_homing_method(od.get_as<std::int8_t>(0x6098, 0))
                            .value_or(motion::HomingMethod::ActualPosition);
    parameters.switch_search_speed =
        services_.velocity_to_counts(od.get_as<std::uint32_t>(0x6099, 1));
    parameters.zero_search_speed =
        services_.velocity_to_counts(od.get_as<std::uint32_t>(0x6099, 2));
    parameters.acceleration = services_.rpm_to_counts(od.get_as<std::uint32_t>(0x609A, 0));
    parameters.shape = static_cast<motion::RampShape>(od.get_as<std::int16_t>(0x6086, 0));
    parameters.home_offset = od.get_as<std::int32_t>(0x607C, 0);
    parameters.home_position = od.get_as<std::int32_t>(0x2081, 0);
    parameters.current_threshold = od.get_as<std::uint16_t>(0x2080, 0) / 1000.0;
    parameters.counts_per_turn = static_cast<std::int64_t>(services_.counts_per_turn);
    return parameters;
}

} // namespace eposp::drives::epos2
