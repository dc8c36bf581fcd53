// EPOS P firmware specification 10.38 - 10.49: the DS-405 process image, 16 entries per type
// each way. The objects are where vm::ProcessImage puts them (vm/process_image.hpp).
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/vm/process_image.hpp"
#include "object_areas.hpp"

#include <fmt/format.h>
#include <string_view>

namespace eposp::device::dictionary {
namespace {

using namespace canopen::od_types;

canopen::DataType data_type(vm::Scalar type) {
    switch (type) {
    case vm::Scalar::I8:
        return kI8;
    case vm::Scalar::U8:
        return kU8;
    case vm::Scalar::I16:
        return kI16;
    case vm::Scalar::U16:
        return kU16;
    case vm::Scalar::I32:
        return kI32;
    default:
        return kU32;
    }
}

std::string_view type_name(vm::Scalar type) {
    switch (type) {
    case vm::Scalar::I8:
        return "INT8";
    case vm::Scalar::U8:
        return "UINT8";
    case vm::Scalar::I16:
        return "INT16";
    case vm::Scalar::U16:
        return "UINT16";
    case vm::Scalar::I32:
        return "INT32";
    default:
        return "UINT32";
    }
}

void add_channels(canopen::ObjectDictionary& od, const vm::ProcessImageObject& object,
                  std::string_view direction) {
    const std::string_view type = type_name(object.type);
    od.add_object(object.index, fmt::format("Process {} {}", direction, type), kArray);
    for (std::uint8_t sub = 1; sub <= vm::kEntriesPerObject; ++sub) {
        add_entry(od, object.index, sub, fmt::format("Process {} {} - {}", direction, type, sub),
                  data_type(object.type), kRW, 0)
            .pdo_mappable();
    }
}

} // namespace

void add_process_image_objects(canopen::ObjectDictionary& od) {
    for (const vm::ProcessImageObject& object : vm::kInputObjects) {
        add_channels(od, object, "Input");
    }
    for (const vm::ProcessImageObject& object : vm::kOutputObjects) {
        add_channels(od, object, "Output");
    }
}

} // namespace eposp::device::dictionary
