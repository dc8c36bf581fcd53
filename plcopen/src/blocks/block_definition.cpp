#include "block_definition.hpp"

#include <map>
#include <stdexcept>
#include <string>

namespace eposp::plcopen::blocks {

BlockVariable variable(Section section, std::string_view name, std::string_view type) {
    using S = vm::Scalar;
    static const std::map<std::string_view, S> kScalars{
        {"BOOL", S::Bool},          {"SINT", S::I8},          {"INT", S::I16},
        {"DINT", S::I32},           {"USINT", S::U8},         {"UINT", S::U16},
        {"UDINT", S::U32},          {"WORD", S::U16},         {"DWORD", S::U32},
        {"MC_BUFFER_MODE", S::I16}, {"MC_DIRECTION", S::I16},
    };
    const auto it = kScalars.find(type);
    if (it == kScalars.end()) {
        throw std::logic_error("a native block variable of type " + std::string(type));
    }
    return {section, name, type, it->second};
}

BlockVariable axis_ref() {
    return {Section::InOut, "Axis", "AXIS_REF", vm::Scalar::Ptr};
}

AxisDriver* referenced_axis(vm::NativeBlock& block, MotionLibrary& library) {
    const auto axis_ref = block.referenced(kAxisField, 1); // AXIS_REF.AxisNo : USINT
    if (axis_ref.empty() || axis_ref[0] >= kAxisCount) {
        return nullptr;
    }
    AxisDriver& axis = library.axis(axis_ref[0]);
    return axis.presence() == AxisPresence::Unassigned ? nullptr : &axis;
}

std::optional<std::size_t> find_field(const BlockInterface& interface, std::string_view name) {
    for (std::size_t i = 0; i < interface.variables.size(); ++i) {
        if (interface.variables[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

std::size_t field(const BlockInterface& interface, std::string_view name) {
    if (const auto index = find_field(interface, name)) {
        return *index;
    }
    throw std::logic_error("native block " + std::string(interface.name) + " has no " +
                           std::string(name));
}

} // namespace eposp::plcopen::blocks
