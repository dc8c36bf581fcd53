#include "eposp/plcopen/motion_library.hpp"

#include "blocks/block_definition.hpp"

namespace eposp::plcopen {

namespace {

// AXIS_REF as the EPOS P's library has it: the axis number of the axis table 0x5280 + n.
constexpr std::string_view kTypes = R"ST(
TYPE
  AXIS_REF : STRUCT
    AxisNo : USINT;
  END_STRUCT;
  MC_BUFFER_MODE : (mcAborting, mcBuffered, mcBlendingLow, mcBlendingPrevious, mcBlendingNext,
                    mcBlendingHigh);
  MC_DIRECTION : (mcPositiveDirection := 1, mcShortestWay, mcNegativeDirection,
                  mcCurrentDirection);
END_TYPE
)ST";

/// Every block of the library, built once: its declaration and its body.
const std::vector<blocks::BlockDefinition>& all_blocks() {
    static const std::vector<blocks::BlockDefinition> definitions = [] {
        auto all = blocks::axis_blocks();
        for (auto* more : {&blocks::motion_blocks, &blocks::parameter_blocks, &blocks::maxon_blocks,
                           &blocks::can_blocks}) {
            for (auto& definition : more()) {
                all.push_back(std::move(definition));
            }
        }
        return all;
    }();
    return definitions;
}

} // namespace

MotionLibrary::MotionLibrary(AxisLink& link) : link_(link), requests_(link) {
    for (AxisNumber axis = 0; axis < kAxisCount; ++axis) {
        drivers_[axis] = std::make_unique<AxisDriver>(link_, axis);
    }
}

MotionLibrary::~MotionLibrary() = default;

std::string MotionLibrary::source() {
    std::string text(kTypes);
    for (const auto& definition : all_blocks()) {
        text += "\n" + definition.interface.declaration();
    }
    return text;
}

void MotionLibrary::register_blocks(vm::NativeRegistry& registry) {
    for (const auto& definition : all_blocks()) {
        registry.add_block(
            std::string(definition.interface.name), definition.interface.fields(),
            [this, &body = definition.body](vm::NativeBlock& block) { body(block, *this); });
    }
}

void MotionLibrary::poll() {
    for (const auto& driver : drivers_) {
        driver->poll();
    }
}

} // namespace eposp::plcopen
