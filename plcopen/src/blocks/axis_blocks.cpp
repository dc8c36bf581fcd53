// MC_Power, MC_Reset and the blocks that read an axis (PLCopen Motion Control Part 1, 3.2, 3.13,
// 3.15 - 3.21). Enable blocks give their values while Enable is TRUE, with Valid.

#include "block_definition.hpp"
#include "execute_block.hpp"

namespace eposp::plcopen::blocks {

namespace {

BlockDefinition power() {
    BlockInterface declared{"MC_Power",
                            {axis_ref(), input("Enable", "BOOL"), output("Status", "BOOL"),
                             output("Valid", "BOOL"), output("Error", "BOOL"),
                             output("ErrorID", "WORD")}};
    enum : std::size_t { kEnable = 1, kStatus, kValid, kError, kErrorId };
    return {std::move(declared), [](vm::NativeBlock& block, MotionLibrary& library) {
                const bool enable = flag(block, kEnable);
                AxisDriver* axis = referenced_axis(block, library);
                ErrorId error = ErrorId::None;
                if (axis == nullptr) {
                    error = enable ? ErrorId::UnknownAxis : ErrorId::None;
                } else {
                    axis->request_power(enable);
                    if (enable && axis->state() == AxisState::ErrorStop) {
                        error = axis->axis_error();
                    }
                }
                set_flag(block, kStatus, axis != nullptr && axis->powered());
                set_flag(block, kValid, enable && error == ErrorId::None);
                set_flag(block, kError, error != ErrorId::None);
                block.set<std::uint16_t>(kErrorId, static_cast<std::uint16_t>(error));
            }};
}

BlockDefinition reset() {
    std::vector<BlockVariable> variables{axis_ref(), input("Execute", "BOOL")};
    const auto outputs = execute_outputs("Done", false);
    variables.insert(variables.end(), outputs.begin(), outputs.end());
    BlockInterface declared{"MC_Reset", std::move(variables)};
    ExecuteBlock body(declared, [](AxisDriver& axis, vm::NativeBlock&) { return axis.reset(); });
    return {std::move(declared), [body](vm::NativeBlock& block, MotionLibrary& library) {
                body(block, library);
            }};
}

/// An Enable block reading the axis' state or actual values from its driver: `Valid`, `Error`,
/// `ErrorID` and its values.
BlockDefinition axis_reader(std::string_view name, std::vector<BlockVariable> values,
                            std::function<void(vm::NativeBlock&, AxisDriver&)> read) {
    std::vector<BlockVariable> variables{axis_ref(), input("Enable", "BOOL"),
                                         output("Valid", "BOOL"), output("Error", "BOOL"),
                                         output("ErrorID", "WORD")};
    variables.insert(variables.end(), values.begin(), values.end());
    enum : std::size_t { kEnable = 1, kValid, kError, kErrorId, kFirstValue };
    const std::size_t value_count = values.size();
    return {BlockInterface{name, std::move(variables)},
            [read = std::move(read), value_count](vm::NativeBlock& block, MotionLibrary& library) {
                AxisDriver* axis = referenced_axis(block, library);
                const bool enable = flag(block, kEnable);
                const bool valid = enable && axis != nullptr;
                set_flag(block, kValid, valid);
                set_flag(block, kError, enable && axis == nullptr);
                block.set<std::uint16_t>(kErrorId,
                                         static_cast<std::uint16_t>(enable && axis == nullptr
                                                                        ? ErrorId::UnknownAxis
                                                                        : ErrorId::None));
                if (valid) {
                    axis->poll();
                    read(block, *axis);
                } else {
                    for (std::size_t i = 0; i < value_count; ++i) {
                        block.clear(kFirstValue + i);
                    }
                }
            }};
}

BlockDefinition read_status() {
    constexpr std::string_view kStates[] = {"Disabled",       "Standstill",       "Homing",
                                            "DiscreteMotion", "ContinuousMotion", "Stopping",
                                            "ErrorStop"};
    std::vector<BlockVariable> values;
    for (const std::string_view state_name : kStates) {
        values.push_back(output(state_name, "BOOL"));
    }
    return axis_reader(
        "MC_ReadStatus", std::move(values), [](vm::NativeBlock& block, AxisDriver& axis) {
            for (std::uint8_t state = 0; state < 7; ++state) {
                set_flag(block, 5 + state, static_cast<AxisState>(state) == axis.state());
            }
        });
}

} // namespace

std::vector<BlockDefinition> axis_blocks() {
    std::vector<BlockDefinition> definitions{power(), reset(), read_status()};
    definitions.push_back(axis_reader("MC_ReadAxisState", {output("State", "USINT")},
                                      [](vm::NativeBlock& block, AxisDriver& axis) {
                                          block.set<std::uint8_t>(
                                              5, static_cast<std::uint8_t>(axis.state()));
                                      }));
    // The drive's error code (its error history 0x1003 sub 1) when it faulted, else the ErrorID
    // that stopped the axis.
    definitions.push_back(axis_reader("MC_ReadAxisError", {output("AxisErrorID", "WORD")},
                                      [](vm::NativeBlock& block, AxisDriver& axis) {
                                          const auto code =
                                              axis.axis_error() == ErrorId::DriveFault
                                                  ? axis.drive_error_code()
                                                  : static_cast<std::uint16_t>(axis.axis_error());
                                          block.set<std::uint16_t>(5, code);
                                      }));
    definitions.push_back(axis_reader("MC_ReadActualPosition", {output("Position", "DINT")},
                                      [](vm::NativeBlock& block, AxisDriver& axis) {
                                          block.set<std::int32_t>(5, axis.actual_position());
                                      }));
    return definitions;
}

} // namespace eposp::plcopen::blocks
