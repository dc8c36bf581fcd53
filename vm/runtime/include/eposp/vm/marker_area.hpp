#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace eposp::vm {

/// The marker area %M of the EPOS P (firmware 0110h: "general purpose and error information
/// sub-area"). The specification gives neither size nor layout; eposp's are documented in
/// docs/runtime.md. Byte addressing as for %I and %Q: %MW385 is the word at byte 770.
namespace marker {
inline constexpr std::uint32_t kSize = 1024;
/// %MB0..%MB767: general purpose, zero at every start, for the programs' own use.
inline constexpr std::uint32_t kGeneralPurposeSize = 768;
/// %MB768..%MB1023: error information, written by the runtime, read-only for programs.
inline constexpr std::uint32_t kLastErrorCode = 768;   ///< %MW384 UINT, 0 when none
inline constexpr std::uint32_t kErrorCount = 770;      ///< %MW385 UINT, saturates at 65535
inline constexpr std::uint32_t kLastErrorTask = 772;   ///< %MW386 UINT task number, or kNoTask
inline constexpr std::uint32_t kLastOverrunTask = 774; ///< %MW387 UINT task number, or kNoTask
inline constexpr std::uint32_t kOverrunCount = 776;    ///< %MW388 UINT, saturates at 65535
inline constexpr std::uint16_t kNoTask = 0xFFFF;
} // namespace marker

/// The bytes of the marker area and the copy of %M located variables in and out of it, like the
/// process image's inputs and outputs; the runtime records its errors in the error part.
class MarkerArea {
public:
    MarkerArea() { clear(); }

    std::span<const std::uint8_t> bytes() const { return bytes_; }
    std::span<std::uint8_t> general_purpose() {
        return std::span(bytes_).first(marker::kGeneralPurposeSize);
    }

    /// Refuses an image with a %M binding outside the marker area.
    static std::optional<core::Error> check_bindings(const Image& image);

    /// Everything to zero and no error recorded: the state at a start.
    void clear();
    /// An error the runtime raised; `task` is the table index of the task it concerns, if any.
    void record_error(std::uint16_t code, std::optional<std::size_t> task);
    /// A task overran (it also is an error: record_error is called as well).
    void record_overrun(std::size_t task);

    /// The markers into the %M variables of `bindings` (other areas skipped).
    void read_into(std::span<const IoBinding> bindings, std::span<std::uint8_t> memory) const;
    /// The %M variables of `bindings` into the general-purpose part; variables located in the
    /// error part are not copied back, so a program cannot overwrite the runtime's records.
    void write_from(std::span<const IoBinding> bindings, std::span<const std::uint8_t> memory);

private:
    std::uint16_t word(std::uint32_t at) const;
    void set_word(std::uint32_t at, std::uint16_t value);
    void count(std::uint32_t at);

    std::array<std::uint8_t, marker::kSize> bytes_{};
};

} // namespace eposp::vm
