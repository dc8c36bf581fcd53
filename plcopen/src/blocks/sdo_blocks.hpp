#pragma once

// Blocks that read or write one object by SDO: the parameter blocks, the maxon utility blocks.
// A reader is an Enable block that keeps one read in flight and shows the last value with
// Valid; a writer is an Execute block that writes once, reading the object first when it needs
// its size or its other bits.

#include "block_definition.hpp"

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace eposp::plcopen::blocks {

/// An object of the drive (or, for AxisNo 255 where allowed, of the EPOS P itself).
struct DriveObject {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    std::uint8_t size = 4; ///< 0: only the drive knows, read it first
    bool is_signed = false;
    bool writable = true;
};

/// The axis number that stands for the EPOS P itself in the error blocks.
inline constexpr std::uint8_t kControllerAxis = 255;

/// `reply`'s value as a DINT, sign-extended from its size if `is_signed`.
std::int32_t decode(const SdoReply& reply, bool is_signed);

struct ReaderSpec {
    std::string_view name;
    std::vector<BlockVariable> inputs{}; ///< after Axis and Enable
    BlockVariable value;                 ///< the output, after Valid, Busy, Error, ErrorID
    /// The object the inputs name; nullopt is the error `invalid`.
    std::function<std::optional<DriveObject>(vm::NativeBlock& block)> object;
    ErrorId invalid = ErrorId::InvalidParameter;
    /// The output from the value read (a bit of it, say).
    std::function<std::int32_t(vm::NativeBlock& block, std::int32_t read)> convert{};
    bool controller_too = false; ///< AxisNo 255 reads the EPOS P's own dictionary
};
BlockDefinition reader(ReaderSpec spec);

struct WriterSpec {
    std::string_view name;
    std::vector<BlockVariable> inputs{}; ///< after Axis and Execute
    std::function<std::optional<DriveObject>(vm::NativeBlock& block)> object;
    ErrorId invalid = ErrorId::InvalidParameter;
    /// Read the object before writing it (always, not only when its size is unknown).
    bool read_first = false;
    /// The value to write, from the inputs and what the read gave (if there was one).
    std::function<std::uint32_t(vm::NativeBlock& block, const SdoReply* read)> value{};
};
BlockDefinition writer(WriterSpec spec);

} // namespace eposp::plcopen::blocks
