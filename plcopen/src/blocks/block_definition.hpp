#pragma once

// What each file of blocks contributes to the library, and what the blocks share: BOOL fields,
// the AXIS_REF a block names, and declaring variables by their ST type.

#include "eposp/plcopen/block_interface.hpp"
#include "eposp/plcopen/motion_library.hpp"

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace eposp::plcopen::blocks {

struct BlockDefinition {
    BlockInterface interface;
    std::function<void(vm::NativeBlock& block, MotionLibrary& library)> body;
};

/// MC_Power, MC_Reset and the blocks that read an axis' state and actual values.
std::vector<BlockDefinition> axis_blocks();
/// MC_MoveAbsolute, MC_MoveRelative, MC_MoveAdditive, MC_MoveVelocity, MC_Halt, MC_Stop,
/// MC_Home.
std::vector<BlockDefinition> motion_blocks();
/// MC_ReadParameter, MC_WriteParameter and their BOOL forms, MC_ReadActualVelocity,
/// MC_ReadActualCurrent, MC_ReadActualTorque.
std::vector<BlockDefinition> parameter_blocks();
/// maxon's MU_* utility blocks: drive I/O, bits of objects, error histories.
std::vector<BlockDefinition> maxon_blocks();
/// maxon's CAN_* blocks: SDO and NMT to any node of either port.
std::vector<BlockDefinition> can_blocks();

/// A variable of `section` with its ST type (elementary, MC_BUFFER_MODE, MC_DIRECTION).
BlockVariable variable(Section section, std::string_view name, std::string_view type);
inline BlockVariable input(std::string_view name, std::string_view type) {
    return variable(Section::Input, name, type);
}
inline BlockVariable output(std::string_view name, std::string_view type) {
    return variable(Section::Output, name, type);
}
inline BlockVariable state(std::string_view name, std::string_view type) {
    return variable(Section::Var, name, type);
}
/// `Axis : AXIS_REF` as VAR_IN_OUT, always field 0.
BlockVariable axis_ref();
inline constexpr std::size_t kAxisField = 0;

inline bool flag(const vm::NativeBlock& block, std::size_t field) {
    return block.get<std::uint8_t>(field) != 0;
}
inline void set_flag(vm::NativeBlock& block, std::size_t field, bool value) {
    block.set<std::uint8_t>(field, value ? 1 : 0);
}

/// The driver of the axis the block's AXIS_REF names; null when AxisNo is above 31 or the axis
/// table assigns no slave to it (every block answers that with ErrorID 16#1001).
AxisDriver* referenced_axis(vm::NativeBlock& block, MotionLibrary& library);

/// The index of the variable `name` in `interface`, if it has one.
std::optional<std::size_t> find_field(const BlockInterface& interface, std::string_view name);
/// The same for a variable it must have (a programming error if not).
std::size_t field(const BlockInterface& interface, std::string_view name);

} // namespace eposp::plcopen::blocks
