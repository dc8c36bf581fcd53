#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace eposp::vm {

/// What restoring the retain variables found.
enum class RetainOutcome {
    Restored,     ///< the stored values are back in memory
    NoStore,      ///< nothing stored yet: a first start, not an error
    Corrupt,      ///< damaged file: Retain Variable Error 0x6310, cold start
    OtherProgram, ///< stored by a program with another retain layout: 0x6310, cold start
};

struct RetainRestore {
    RetainOutcome outcome = RetainOutcome::NoStore;
    std::string reason; ///< why the store was refused (Corrupt, OtherProgram)
};

/// The non-volatile memory of the RETAIN variables (IEC 61131-3 ed. 3, 6.5.6; EPOS P firmware
/// specification 0110h notes): the bytes of the image's retain ranges, stored with the
/// program's retain identity and a CRC-32 through core::write_file_durably, so that a power
/// loss at any instant leaves either the previous or the new values, never a mix. A store of
/// another program's layout is refused rather than restored into the wrong variables.
class RetainStore {
public:
    /// `capacity`: bytes of retain data the controller holds.
    RetainStore(std::filesystem::path file, std::uint32_t capacity);

    /// Refuses a program that declares more retain data than the capacity (at load time).
    std::optional<core::Error> check_capacity(const Image& image) const;
    /// Writes the retain ranges of `memory` (laid out as `image` says).
    std::optional<core::Error> save(const Image& image, std::span<const std::uint8_t> memory) const;
    /// Copies the stored values into `memory` when the store is intact and of this program's
    /// layout; otherwise leaves `memory` untouched and says why.
    RetainRestore restore(const Image& image, std::span<std::uint8_t> memory) const;

    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::uint32_t capacity_;
};

/// Bytes of retain data the image declares.
std::uint32_t retain_size(const Image& image);
/// A CRC-32 over everything that gives retained bytes their meaning: the retain ranges and the
/// symbols and types of static data. Code changes keep it; a changed variable layout does not.
std::uint32_t retain_identity(const Image& image);

} // namespace eposp::vm
