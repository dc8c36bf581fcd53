#include "program_store.hpp"

#include "eposp/core/durable_file.hpp"
#include "eposp/device/error_entry.hpp"
#include "eposp/vm/image_format.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr std::array<std::uint8_t, 4> kImageMagic{'E', 'P', 'X', 'I'}; // image_format.hpp

std::uint32_t little_endian_u32(std::span<const std::uint8_t> bytes) {
    return std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 | std::uint32_t{bytes[2]} << 16 |
           std::uint32_t{bytes[3]} << 24;
}

// CiA 302-3 0x1F57: an image read_image refused is "data format unknown" when it is no EPOS P
// image of this version at all, "data format error" when it is one, damaged or cut short.
FlashStatus refused_image_status(std::span<const std::uint8_t> image) {
    if (image.size() < kImageMagic.size() ||
        !std::equal(kImageMagic.begin(), kImageMagic.end(), image.begin())) {
        return FlashStatus::DataFormatUnknown;
    }
    constexpr std::size_t kVersionEnd = 6;
    if (image.size() >= kVersionEnd && (image[4] | image[5] << 8) != vm::kImageVersion) {
        return FlashStatus::DataFormatUnknown;
    }
    return FlashStatus::DataFormatError;
}

} // namespace

ProgramStore::ProgramStore(canopen::ObjectDictionary& od, Plc& plc, std::filesystem::path file)
    : od_(od), plc_(plc), file_(std::move(file)) {}

std::uint32_t ProgramStore::software_identification() const {
    constexpr std::size_t kChecksumAt = 12; // image_format.hpp: the header's CRC-32
    return image_.empty() ? 0 : little_endian_u32(std::span(image_).subspan(kChecksumAt, 4));
}

void ProgramStore::refuse(FlashStatus status, std::string why, std::uint16_t error_code) {
    status_ = status;
    refusal_ = std::move(why);
    record_error(od_, {.code = error_code, .port = 0, .node = 0, .warning = false});
}

void ProgramStore::interrupted(canopen::AbortCode reason) {
    refuse(FlashStatus::DataFormatError,
           fmt::format("the download ended before its last byte: 0x{:08X} {}",
                       static_cast<std::uint32_t>(reason), canopen::describe(reason)),
           kProgramDownloadError);
}

void ProgramStore::power_up() {
    if (file_.empty()) {
        return;
    }
    auto stored = core::read_whole_file(file_);
    if (!stored) {
        refuse(FlashStatus::Unspecified,
               fmt::format("stored program {}: {}", file_.string(), stored.error()), kEepromError);
        return;
    }
    if (!*stored) {
        return; // nothing stored: no program
    }
    auto image = vm::read_image(**stored);
    if (!image) {
        refuse(refused_image_status(**stored),
               fmt::format("stored program {}: {}", file_.string(), image.error()),
               kProgramDownloadError);
        return;
    }
    if (auto error = plc_.load(std::move(*image))) {
        refuse(FlashStatus::Incompatible,
               fmt::format("stored program {}: {}", file_.string(), error->message),
               kProgramDownloadError);
        return;
    }
    image_ = std::move(**stored);
    status_ = FlashStatus::Ok;
    cold_next_ = false; // 10.37: a warm start keeps the values from before power down
}

canopen::AbortCode ProgramStore::download(std::span<const std::uint8_t> bytes) {
    // CiA 302-3: a running program is not replaced; the tool stops it first (0x1F51 = 0).
    if (plc_.runtime().state() == vm::ProgramState::Running) {
        status_ = FlashStatus::FlashSecured;
        refusal_ = "the program runs: stop it (0x1F51 = 0) before a download";
        return canopen::AbortCode::DeviceState;
    }
    auto image = vm::read_image(bytes);
    if (!image) {
        refuse(refused_image_status(bytes), image.error(), kProgramDownloadError);
        return canopen::AbortCode::TransferOrStore;
    }
    if (auto error = plc_.verify(*image)) {
        refuse(FlashStatus::Incompatible, error->message, kProgramDownloadError);
        return canopen::AbortCode::TransferOrStore;
    }
    if (!file_.empty()) {
        if (auto error = core::write_file_durably(file_, bytes)) {
            refuse(FlashStatus::FlashWriteError,
                   fmt::format("program file {}: {}", file_.string(), error->message),
                   kEepromError);
            return canopen::AbortCode::HardwareError;
        }
    }
    if (auto error = plc_.load(std::move(*image))) { // verified: only a bug gets here
        refuse(FlashStatus::Incompatible, error->message, kProgramDownloadError);
        return canopen::AbortCode::TransferOrStore;
    }
    image_.assign(bytes.begin(), bytes.end());
    status_ = FlashStatus::Ok;
    refusal_.clear();
    cold_next_ = true;
    return canopen::AbortCode::None;
}

canopen::AbortCode ProgramStore::clear() {
    if (plc_.runtime().state() == vm::ProgramState::Running) {
        return canopen::AbortCode::DeviceState;
    }
    if (!file_.empty()) {
        if (auto error = core::remove_file_durably(file_)) {
            refuse(FlashStatus::FlashWriteError,
                   fmt::format("program file {}: {}", file_.string(), error->message),
                   kEepromError);
            return canopen::AbortCode::HardwareError;
        }
    }
    plc_.runtime().unload();
    image_.clear();
    status_ = FlashStatus::NoValidProgram;
    refusal_.clear();
    cold_next_ = true;
    return canopen::AbortCode::None;
}

} // namespace eposp::device
