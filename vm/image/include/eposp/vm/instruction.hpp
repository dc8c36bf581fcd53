#pragma once

#include "eposp/vm/opcodes.hpp"

#include <cstdint>
#include <optional>

namespace eposp::vm {

/// The areas a memory operand can be relative to. The interpreter keeps one pointer per base,
/// so resolving any operand is the same load-and-add whatever its base.
enum class Base : std::uint8_t {
    Static = 0, ///< globals, program and FB instances, constants, strings
    Frame = 1,  ///< the current function frame on the task stack
    Self = 2,   ///< the instance of the FB or program whose body runs
    Out = 3,    ///< the next frame: where a caller puts the arguments of its next call
};

inline constexpr std::uint32_t kBaseShift = 30;
inline constexpr std::uint32_t kOffsetMask = (1U << kBaseShift) - 1;

/// A memory operand as stored in an instruction field: base in the top two bits, byte offset
/// below.
struct Operand {
    std::uint32_t raw = 0;

    static constexpr Operand at(Base base, std::uint32_t offset) {
        return {(static_cast<std::uint32_t>(base) << kBaseShift) | (offset & kOffsetMask)};
    }
    static constexpr Operand global(std::uint32_t offset) { return at(Base::Static, offset); }
    static constexpr Operand local(std::uint32_t offset) { return at(Base::Frame, offset); }
    static constexpr Operand self(std::uint32_t offset) { return at(Base::Self, offset); }
    static constexpr Operand out(std::uint32_t offset) { return at(Base::Out, offset); }
    /// A raw field value: an immediate, a size, a POU or import index.
    static constexpr Operand imm(std::uint32_t value) { return {value}; }

    constexpr Base base() const { return static_cast<Base>(raw >> kBaseShift); }
    constexpr std::uint32_t offset() const { return raw & kOffsetMask; }
};

/// One instruction: 16 bytes, little-endian in the image.
struct Instruction {
    Opcode opcode = Opcode::Nop;
    std::uint16_t aux = 0; ///< array descriptor index for the indexed forms
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint32_t c = 0;

    bool operator==(const Instruction&) const = default;
};
static_assert(sizeof(Instruction) == 16);

inline constexpr std::uint32_t kInstructionSize = 16;

/// The branch target of an instruction that has one (a field of kind Target), else nullopt.
std::optional<std::uint32_t> branch_target(const Instruction& ins);

} // namespace eposp::vm
