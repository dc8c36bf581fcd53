#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/device/plc.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace eposp::device {

/// CiA 302-3 0x1F57 "Flash status identification", bits 1..7: what the last download (or the
/// power-up's load) left. 64 and up are manufacturer-specific.
enum class FlashStatus : std::uint8_t {
    Ok = 0,
    NoValidProgram = 1,
    DataFormatUnknown = 2, ///< not an EPOS P program image of this version (magic, version)
    DataFormatError = 3,   ///< a damaged image: checksum, length, structure (a truncated one)
    FlashWriteError = 5,   ///< the program file could not be written or removed
    FlashSecured = 7,      ///< refused while the program runs
    Unspecified = 63,      ///< the program file could not be read
    Incompatible = 64,     ///< a sound image this controller cannot run (link, RETAIN size, I/O)
};

/// Error history codes (EPOS P firmware specification table 1, and one of ours).
inline constexpr std::uint16_t kEepromError = 0x5530; ///< the non-volatile memory failed
/// eposp's addition to table 1: a program download or the stored program was refused.
inline constexpr std::uint16_t kProgramDownloadError = 0x6186;

/// The EPOS P's non-volatile program memory (CiA 302-3 program download): the program image as
/// it was downloaded to 0x1F50, kept in a file written atomically, and loaded into the PLC.
/// A download is verified completely (decoded, verified and linked on a scratch runtime) before
/// it replaces anything: a refused one leaves the old program loaded and stored, and says why in
/// flash_status() and in the error history.
class ProgramStore {
public:
    /// `file` empty: the program lives in memory only. `od` and `plc` must outlive the store.
    ProgramStore(canopen::ObjectDictionary& od, Plc& plc, std::filesystem::path file);

    /// At power-up: loads the stored program into the PLC (not started). A file that cannot be
    /// read, decoded or loaded leaves no program and is left alone; 0x1F57 and the error history
    /// say why.
    void power_up();
    /// 0x1F50 sub 1: replaces the program with `image` (the bytes of an `.epx`), which is then
    /// loaded and stopped. Refused while the program runs (DeviceState), for an image that is
    /// not sound or does not fit this controller (TransferOrStore), when the file cannot be
    /// written (HardwareError).
    canopen::AbortCode download(std::span<const std::uint8_t> image);
    /// 0x1F51 "clear program" and 0x1011 sub 2 "eras": forgets the program, in memory and in
    /// the file. Refused while it runs (DeviceState) or when the file cannot be removed.
    canopen::AbortCode clear();

    bool has_program() const { return !image_.empty(); }
    /// The stored image as downloaded; empty without a program.
    const std::vector<std::uint8_t>& image() const { return image_; }
    /// 0x1F56: the CRC-32 of the image's payload (its header's checksum); 0 without a program.
    std::uint32_t software_identification() const;
    /// 0x1F57: bit 0 "in progress" is never set (a download is checked when its last byte is
    /// in); bits 1..7 the FlashStatus.
    std::uint32_t flash_status() const { return static_cast<std::uint32_t>(status_) << 1; }
    /// Why the last download or power-up load was refused; empty after a success.
    const std::string& refusal() const { return refusal_; }

    /// The start mode of 0x1F51 "start program": cold after a download or a reset (0x1F51 = 2),
    /// so that a program never meets RETAIN values of another; warm otherwise (10.37).
    vm::StartMode start_mode() const {
        return cold_next_ ? vm::StartMode::Cold : vm::StartMode::Warm;
    }
    /// A download to 0x1F50 that ended before its last byte (the host went away, the transfer
    /// was aborted or timed out): the old program stays; 0x1F57 says "data format error" and the
    /// error history 0x6186, as for a truncated image.
    void interrupted(canopen::AbortCode reason);
    /// 0x1F51 "reset program": the next start through 0x1F51 is cold.
    void reset() { cold_next_ = true; }
    /// Told of every start of the program.
    void started() { cold_next_ = false; }

private:
    /// Says why in 0x1F57, refusal() and the error history (`error_code`).
    void refuse(FlashStatus status, std::string why, std::uint16_t error_code);

    canopen::ObjectDictionary& od_;
    Plc& plc_;
    std::filesystem::path file_;
    std::vector<std::uint8_t> image_;
    FlashStatus status_ = FlashStatus::NoValidProgram;
    std::string refusal_;
    bool cold_next_ = true;
};

} // namespace eposp::device
