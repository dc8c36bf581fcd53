#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace eposp::vm {

/// One DS-405 process image object of the EPOS P (firmware specification 10.38-10.49): 16
/// entries (sub-indices 1..16) of one type, at a fixed place in the input or output image.
struct ProcessImageObject {
    std::uint16_t index = 0;
    Scalar type = Scalar::I8;
    std::uint32_t first_byte = 0; ///< byte of sub-index 1 in its image
};

inline constexpr std::uint8_t kEntriesPerObject = 16;

/// The input image in object order, each object's entries naturally aligned one after the
/// other: %IB0..15 = 0xA000, %IB16..31 = 0xA040, %IW16..31 = 0xA0C0, %IW32..47 = 0xA100,
/// %ID24..39 = 0xA1C0, %ID40..55 = 0xA200 (docs/runtime.md has the whole table).
inline constexpr std::array<ProcessImageObject, 6> kInputObjects{{
    {0xA000, Scalar::I8, 0},
    {0xA040, Scalar::U8, 16},
    {0xA0C0, Scalar::I16, 32},
    {0xA100, Scalar::U16, 64},
    {0xA1C0, Scalar::I32, 96},
    {0xA200, Scalar::U32, 160},
}};
/// The output image, laid out like the inputs with %Q addresses.
inline constexpr std::array<ProcessImageObject, 6> kOutputObjects{{
    {0xA400, Scalar::I8, 0},
    {0xA4C0, Scalar::U8, 16},
    {0xA540, Scalar::I16, 32},
    {0xA580, Scalar::U16, 64},
    {0xA640, Scalar::I32, 96},
    {0xA680, Scalar::U32, 160},
}};
/// Bytes of each of the input and output images.
inline constexpr std::uint32_t kProcessImageSize = 224;

struct ObjectEntry {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    bool operator==(const ObjectEntry&) const = default;
};

/// The object entry that holds byte `byte` of the input or output image.
std::optional<ObjectEntry> object_entry_of(IoArea area, std::uint32_t byte);

/// The %I and %Q areas of the controller: what the device (its PDOs, its SDO server) writes
/// into 0xA000.. and reads from 0xA400.., and what located variables (`AT %IW40`) see. Inputs
/// are copied into the program's variables before a task runs, so the task works on one
/// consistent snapshot; outputs are published after the task's cycle.
class ProcessImage {
public:
    std::span<std::uint8_t> inputs() { return inputs_; }
    std::span<const std::uint8_t> outputs() const { return outputs_; }
    std::span<std::uint8_t> outputs() { return outputs_; }

    /// The bytes of entry `sub_index` of object `index` (little-endian, sized by its type), in
    /// the input or output image; an error for anything that is not such an entry.
    core::Result<std::span<std::uint8_t>> entry(std::uint16_t index, std::uint8_t sub_index);

    /// Refuses an image with a %I or %Q binding outside the process image.
    static std::optional<core::Error> check_bindings(const Image& image);
    /// Inputs into the variables bound to them (%IX bits as BOOL 0/1); other areas' bindings
    /// are skipped. The bindings must have passed check_bindings: `bindings` is all of an
    /// image's or those of the task about to run.
    void read_inputs(std::span<const IoBinding> bindings, std::span<std::uint8_t> memory) const;
    /// The variables bound to outputs into the output image (%QX bits set or cleared).
    void write_outputs(std::span<const IoBinding> bindings, std::span<const std::uint8_t> memory);
    /// The outputs of these bindings to zero: the safe state of a faulted task.
    void clear_outputs(std::span<const IoBinding> bindings);
    /// Every output to zero: the safe state of a stopped program.
    void clear_outputs() { outputs_.fill(0); }

private:
    std::array<std::uint8_t, kProcessImageSize> inputs_{};
    std::array<std::uint8_t, kProcessImageSize> outputs_{};
};

} // namespace eposp::vm
