// The blocks that command motion (PLCopen Motion Control Part 1, 3.3 - 3.12). Positions are
// quadcounts, velocities rpm, accelerations rpm/s, as the drive counts them.

#include "block_definition.hpp"
#include "execute_block.hpp"

namespace eposp::plcopen::blocks {

namespace {

using Kind = MotionCommand::Kind;

BlockInterface interface(std::string_view name, std::vector<BlockVariable> inputs,
                         std::string_view done = "Done") {
    std::vector<BlockVariable> variables{axis_ref(), input("Execute", "BOOL")};
    variables.insert(variables.end(), inputs.begin(), inputs.end());
    const auto outputs = execute_outputs(done, true);
    variables.insert(variables.end(), outputs.begin(), outputs.end());
    return {name, std::move(variables)};
}

/// The inputs of a block, read by name once per definition.
class Inputs {
public:
    explicit Inputs(const BlockInterface& interface) : interface_(interface) {}
    std::size_t operator[](std::string_view name) const { return field(interface_, name); }

private:
    BlockInterface interface_;
};

BlockDefinition move_block(std::string_view name, std::string_view target, Kind kind) {
    std::vector<BlockVariable> inputs{input(target, "DINT"), input("Velocity", "DINT"),
                                      input("Acceleration", "DINT"), input("Deceleration", "DINT")};
    // A linear axis (the EPOS2 has no modulo axes) reaches a position one way only: Direction
    // is checked, not used.
    if (kind == Kind::MoveAbsolute) {
        inputs.push_back(input("Direction", "MC_DIRECTION"));
    }
    inputs.push_back(input("BufferMode", "MC_BUFFER_MODE"));
    BlockInterface declared = interface(name, inputs);
    const Inputs in(declared);
    ExecuteBlock body(declared, [in, target, kind](AxisDriver& axis, vm::NativeBlock& block) {
        if (kind == Kind::MoveAbsolute) {
            const auto direction = block.get<std::int16_t>(in["Direction"]);
            if (direction < static_cast<std::int16_t>(Direction::Positive) ||
                direction > static_cast<std::int16_t>(Direction::Current)) {
                return Submitted{.error = ErrorId::InvalidInput};
            }
        }
        const MotionCommand command{.kind = kind,
                                    .position = block.get<std::int32_t>(in[target]),
                                    .velocity = block.get<std::int32_t>(in["Velocity"]),
                                    .acceleration = block.get<std::int32_t>(in["Acceleration"]),
                                    .deceleration = block.get<std::int32_t>(in["Deceleration"])};
        if (command.velocity <= 0 || command.acceleration <= 0 || command.deceleration <= 0) {
            return Submitted{.error = ErrorId::InvalidInput};
        }
        return axis.submit(command,
                           static_cast<BufferMode>(block.get<std::int16_t>(in["BufferMode"])));
    });
    return {std::move(declared), [body](vm::NativeBlock& block, MotionLibrary& library) {
                body(block, library);
            }};
}

BlockDefinition move_velocity() {
    BlockInterface declared = interface(
        "MC_MoveVelocity",
        {input("Velocity", "DINT"), input("Acceleration", "DINT"), input("Deceleration", "DINT"),
         input("Direction", "MC_DIRECTION"), input("BufferMode", "MC_BUFFER_MODE")},
        "InVelocity");
    const Inputs in(declared);
    ExecuteBlock body(declared, [in](AxisDriver& axis, vm::NativeBlock& block) {
        const std::int32_t velocity = block.get<std::int32_t>(in["Velocity"]);
        const auto direction = static_cast<Direction>(block.get<std::int16_t>(in["Direction"]));
        MotionCommand command{.kind = Kind::MoveVelocity,
                              .velocity = velocity,
                              .acceleration = block.get<std::int32_t>(in["Acceleration"]),
                              .deceleration = block.get<std::int32_t>(in["Deceleration"])};
        // Velocity 0 is a valid command: the axis ramps down and stays in ContinuousMotion.
        if (velocity < 0 || command.acceleration <= 0 || command.deceleration <= 0 ||
            (direction != Direction::Positive && direction != Direction::Negative)) {
            return Submitted{.error = ErrorId::InvalidInput};
        }
        if (direction == Direction::Negative) {
            command.velocity = -velocity;
        }
        return axis.submit(command,
                           static_cast<BufferMode>(block.get<std::int16_t>(in["BufferMode"])));
    });
    return {std::move(declared), [body](vm::NativeBlock& block, MotionLibrary& library) {
                body(block, library);
            }};
}

BlockDefinition halt_or_stop(std::string_view name, Kind kind) {
    std::vector<BlockVariable> inputs{input("Deceleration", "DINT")};
    if (kind == Kind::Halt) {
        inputs.push_back(input("BufferMode", "MC_BUFFER_MODE"));
    }
    BlockInterface declared = interface(name, inputs);
    const Inputs in(declared);
    ExecuteBlock body(
        declared,
        [in, kind](AxisDriver& axis, vm::NativeBlock& block) {
            const MotionCommand command{
                .kind = kind, .deceleration = block.get<std::int32_t>(in["Deceleration"])};
            if (command.deceleration <= 0) {
                return Submitted{.error = ErrorId::InvalidInput};
            }
            const auto mode =
                kind == Kind::Halt
                    ? static_cast<BufferMode>(block.get<std::int16_t>(in["BufferMode"]))
                    : BufferMode::Aborting;
            return axis.submit(command, mode);
        },
        kind == Kind::Stop);
    return {std::move(declared), [body](vm::NativeBlock& block, MotionLibrary& library) {
                body(block, library);
            }};
}

BlockDefinition home() {
    BlockInterface declared =
        interface("MC_Home", {input("Position", "DINT"), input("HomingMethod", "SINT"),
                              input("BufferMode", "MC_BUFFER_MODE")});
    const Inputs in(declared);
    ExecuteBlock body(declared, [in](AxisDriver& axis, vm::NativeBlock& block) {
        const MotionCommand command{.kind = Kind::Home,
                                    .position = block.get<std::int32_t>(in["Position"]),
                                    .homing_method = block.get<std::int8_t>(in["HomingMethod"])};
        return axis.submit(command,
                           static_cast<BufferMode>(block.get<std::int16_t>(in["BufferMode"])));
    });
    return {std::move(declared), [body](vm::NativeBlock& block, MotionLibrary& library) {
                body(block, library);
            }};
}

} // namespace

std::vector<BlockDefinition> motion_blocks() {
    return {move_block("MC_MoveAbsolute", "Position", Kind::MoveAbsolute),
            move_block("MC_MoveRelative", "Distance", Kind::MoveRelative),
            move_block("MC_MoveAdditive", "Distance", Kind::MoveAdditive),
            move_velocity(),
            halt_or_stop("MC_Halt", Kind::Halt),
            halt_or_stop("MC_Stop", Kind::Stop),
            home()};
}

} // namespace eposp::plcopen::blocks
