#include "eposp/vm/marker_area.hpp"

#include "located_copy.hpp"

#include <fmt/format.h>

namespace eposp::vm {
namespace {

std::uint16_t task_number(std::size_t task) {
    return task < marker::kNoTask ? static_cast<std::uint16_t>(task) : marker::kNoTask;
}

} // namespace

std::optional<core::Error> MarkerArea::check_bindings(const Image& image) {
    for (const IoBinding& binding : image.bindings) {
        if (binding.area == IoArea::Memory &&
            binding.byte_address + detail::binding_size(binding) > marker::kSize) {
            return core::Error{
                fmt::format("%M{} is outside the marker area (bytes 0..{} of the EPOS P)",
                            binding.byte_address, marker::kSize - 1)};
        }
    }
    return std::nullopt;
}

void MarkerArea::clear() {
    bytes_.fill(0);
    set_word(marker::kLastErrorTask, marker::kNoTask);
    set_word(marker::kLastOverrunTask, marker::kNoTask);
}

void MarkerArea::record_error(std::uint16_t code, std::optional<std::size_t> task) {
    set_word(marker::kLastErrorCode, code);
    count(marker::kErrorCount);
    set_word(marker::kLastErrorTask, task ? task_number(*task) : marker::kNoTask);
}

void MarkerArea::record_overrun(std::size_t task) {
    set_word(marker::kLastOverrunTask, task_number(task));
    count(marker::kOverrunCount);
}

void MarkerArea::read_into(std::span<const IoBinding> bindings,
                           std::span<std::uint8_t> memory) const {
    for (const IoBinding& binding : bindings) {
        if (binding.area == IoArea::Memory) {
            detail::copy_into_variable(bytes_, binding, memory);
        }
    }
}

void MarkerArea::write_from(std::span<const IoBinding> bindings,
                            std::span<const std::uint8_t> memory) {
    for (const IoBinding& binding : bindings) {
        if (binding.area == IoArea::Memory &&
            binding.byte_address + detail::binding_size(binding) <= marker::kGeneralPurposeSize) {
            detail::copy_into_area(bytes_, binding, memory);
        }
    }
}

std::uint16_t MarkerArea::word(std::uint32_t at) const {
    return static_cast<std::uint16_t>(bytes_[at] | (bytes_[at + 1] << 8));
}

void MarkerArea::set_word(std::uint32_t at, std::uint16_t value) {
    bytes_[at] = static_cast<std::uint8_t>(value);
    bytes_[at + 1] = static_cast<std::uint8_t>(value >> 8);
}

void MarkerArea::count(std::uint32_t at) {
    if (word(at) != 0xFFFF) {
        set_word(at, static_cast<std::uint16_t>(word(at) + 1));
    }
}

} // namespace eposp::vm
