#pragma once

#include "eposp/plcopen/error_ids.hpp"

#include <cstdint>

namespace eposp::plcopen {

/// PLCopen MC_BUFFER_MODE. Aborting and Buffered are exact (a buffered position move waits in
/// the drive's set-point buffer); the blending modes run as Buffered (the next move starts when
/// this one is done), since a CiA 402 drive in profile position mode cannot blend two moves
/// into one profile.
enum class BufferMode : std::int16_t {
    Aborting = 0,
    Buffered = 1,
    BlendingLow = 2,
    BlendingPrevious = 3,
    BlendingNext = 4,
    BlendingHigh = 5,
};

/// PLCopen MC_DIRECTION.
enum class Direction : std::int16_t {
    Positive = 1,
    ShortestWay = 2,
    Negative = 3,
    Current = 4,
};

/// One motion command of a block, in the drive's units: positions in quadcounts, velocities in
/// rpm, accelerations in rpm/s.
struct MotionCommand {
    enum class Kind : std::uint8_t {
        MoveAbsolute,
        MoveRelative, ///< `position` is a distance from the actual position
        MoveAdditive, ///< `position` is a distance from the last commanded target
        MoveVelocity, ///< `velocity` signed: its sign is the direction
        Halt,
        Stop,
        Home, ///< `homing_method` (0x6098), `position` the home position (0x2081)
    };
    Kind kind = Kind::MoveAbsolute;
    std::int32_t position = 0;
    std::int32_t velocity = 0;
    std::int32_t acceleration = 0;
    std::int32_t deceleration = 0;
    std::int8_t homing_method = 0;
};

/// Names one command of one axis for as long as its block asks about it; 0 is none.
using CommandId = std::uint32_t;

enum class CommandStatus : std::uint8_t {
    Unknown,  ///< no such command (or too long ago)
    Buffered, ///< waits for the command before it: Busy, not yet Active
    Active,   ///< the axis runs it: Busy and Active
    Done,
    Aborted, ///< another command took the axis over
    Failed,  ///< `error` says why
};

struct CommandReport {
    CommandStatus status = CommandStatus::Unknown;
    ErrorId error = ErrorId::None;
    /// MC_MoveVelocity: the drive runs at the commanded velocity (statusword bit 10).
    bool in_velocity = false;
};

/// What submitting a command gave: its id, or why it was refused.
struct Submitted {
    CommandId id = 0;
    ErrorId error = ErrorId::None;
};

} // namespace eposp::plcopen
