#include "eposp/vm/process_image.hpp"

#include "located_copy.hpp"

#include <fmt/format.h>

namespace eposp::vm {
namespace {

std::span<const ProcessImageObject> objects_of(IoArea area) {
    return area == IoArea::Input ? std::span<const ProcessImageObject>(kInputObjects)
                                 : std::span<const ProcessImageObject>(kOutputObjects);
}

bool in_process_image(const IoBinding& binding) {
    return binding.area != IoArea::Memory;
}

} // namespace

std::optional<ObjectEntry> object_entry_of(IoArea area, std::uint32_t byte) {
    if (area == IoArea::Memory) {
        return std::nullopt;
    }
    for (const ProcessImageObject& object : objects_of(area)) {
        const std::uint32_t size = scalar_size(object.type);
        if (byte >= object.first_byte && byte < object.first_byte + kEntriesPerObject * size) {
            return ObjectEntry{object.index,
                               static_cast<std::uint8_t>((byte - object.first_byte) / size + 1)};
        }
    }
    return std::nullopt;
}

core::Result<std::span<std::uint8_t>> ProcessImage::entry(std::uint16_t index,
                                                          std::uint8_t sub_index) {
    for (const IoArea area : {IoArea::Input, IoArea::Output}) {
        for (const ProcessImageObject& object : objects_of(area)) {
            if (object.index != index) {
                continue;
            }
            if (sub_index < 1 || sub_index > kEntriesPerObject) {
                return core::Error{fmt::format("0x{:04X} has no sub-index {}", index, sub_index)};
            }
            const std::uint32_t size = scalar_size(object.type);
            auto& bytes = area == IoArea::Input ? inputs_ : outputs_;
            return std::span<std::uint8_t>(bytes).subspan(
                object.first_byte + (sub_index - 1U) * size, size);
        }
    }
    return core::Error{fmt::format("0x{:04X} is not a process image object", index)};
}

std::optional<core::Error> ProcessImage::check_bindings(const Image& image) {
    for (const IoBinding& binding : image.bindings) {
        if (binding.type == Scalar::Bool && binding.bit > 7) {
            return core::Error{fmt::format("bit {} of a byte does not exist", binding.bit)};
        }
        if (in_process_image(binding) &&
            binding.byte_address + detail::binding_size(binding) > kProcessImageSize) {
            return core::Error{
                fmt::format("%{}{} is outside the process image (bytes 0..{} of the EPOS P)",
                            binding.area == IoArea::Input ? 'I' : 'Q', binding.byte_address,
                            kProcessImageSize - 1)};
        }
    }
    return std::nullopt;
}

void ProcessImage::read_inputs(std::span<const IoBinding> bindings,
                               std::span<std::uint8_t> memory) const {
    for (const IoBinding& binding : bindings) {
        if (binding.area == IoArea::Input) {
            detail::copy_into_variable(inputs_, binding, memory);
        }
    }
}

void ProcessImage::write_outputs(std::span<const IoBinding> bindings,
                                 std::span<const std::uint8_t> memory) {
    for (const IoBinding& binding : bindings) {
        if (binding.area == IoArea::Output) {
            detail::copy_into_area(outputs_, binding, memory);
        }
    }
}

void ProcessImage::clear_outputs(std::span<const IoBinding> bindings) {
    for (const IoBinding& binding : bindings) {
        if (binding.area == IoArea::Output) {
            detail::clear_in_area(outputs_, binding);
        }
    }
}

} // namespace eposp::vm
