#include "sample_device.hpp"

#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/node.hpp"

#include <cstdint>

namespace eposp::device {
namespace {

using namespace canopen;

void add_values_of_every_type(ObjectDictionary& od) {
    constexpr std::uint16_t kIndex = 0x2000;
    od.add_object(kIndex, "Test values", ObjectCode::Record);
    const auto add = [&](std::uint8_t sub, std::string name, DataType type, Bytes value) {
        od.add_sub(kIndex, sub, std::move(name), type, Access::ReadWrite, std::move(value));
    };
    add(1, "Boolean", DataType::Boolean, encode(true));
    add(2, "Integer8", DataType::Integer8, encode<std::int8_t>(-5));
    add(3, "Integer16", DataType::Integer16, encode<std::int16_t>(-1000));
    add(4, "Integer32", DataType::Integer32, encode<std::int32_t>(-100'000));
    add(5, "Integer64", DataType::Integer64, encode<std::int64_t>(-5'000'000'000));
    add(6, "Unsigned8", DataType::Unsigned8, encode<std::uint8_t>(200));
    add(7, "Unsigned16", DataType::Unsigned16, encode<std::uint16_t>(60'000));
    add(8, "Unsigned32", DataType::Unsigned32, encode<std::uint32_t>(0xDEAD'BEEF));
    add(9, "Unsigned64", DataType::Unsigned64, encode<std::uint64_t>(0x0123'4567'89AB'CDEF));
    add(10, "Real32", DataType::Real32, encode(1.5F));
    add(11, "Real64", DataType::Real64, encode(-2.25));
}

void add_device_objects(ObjectDictionary& od) {
    od.add_variable(0x1008, "Manufacturer device name", DataType::VisibleString, Access::Const,
                    encode_string("eposp sample I/O module"));
    od.add_variable(0x1009, "Manufacturer hardware version", DataType::VisibleString, Access::Const,
                    encode_string("1.0"));
    od.add_variable(0x100A, "Manufacturer software version", DataType::VisibleString, Access::Const,
                    encode_string("eposp"));
    add_values_of_every_type(od);
    od.add_variable(0x2001, "Serial data", DataType::OctetString, Access::ReadWrite,
                    Bytes{0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88, 0x99});
    od.add_variable(0x2002, "Configuration block", DataType::Domain, Access::ReadWrite,
                    Bytes(20, 0xA5));
    od.add_variable(0x2003, "Command", DataType::Unsigned32, Access::WriteOnly,
                    encode<std::uint32_t>(0));
    // CiA 401: two 8-bit input and output groups, mappable into the PDOs.
    od.add_object(0x6000, "Read input 8-bit", ObjectCode::Array);
    od.add_object(0x6200, "Write output 8-bit", ObjectCode::Array);
    for (std::uint8_t group = 1; group <= 2; ++group) {
        od.add_sub(0x6000, group, "Input group " + std::to_string(group), DataType::Unsigned8,
                   Access::ReadOnly, encode<std::uint8_t>(0))
            .pdo_mappable = true;
        od.add_sub(0x6200, group, "Output group " + std::to_string(group), DataType::Unsigned8,
                   Access::ReadWrite, encode<std::uint8_t>(0))
            .pdo_mappable = true;
    }
}

NodeConfig sample_config() {
    NodeConfig config;
    config.node_id = static_cast<NodeId>(kSampleNodeId);
    config.device_type = 0x0003'0191; // CiA 401, digital inputs and outputs
    config.identity = {.vendor_id = 0x0000'00FB,
                       .product_code = 0x0401,
                       .revision_number = 0x0001'0000,
                       .serial_number = 1};
    // TPDO1 carries the inputs on change, RPDO1 sets the outputs.
    PdoObjectsConfig pdos = cia301_pdo_defaults(config.node_id, 2, 2);
    pdos.tpdos[0].cob_id = 0x4000'0180 + kSampleNodeId;
    pdos.tpdos[0].mapping = {0x6000'0108, 0x6000'0208};
    pdos.rpdos[0].cob_id = 0x200 + kSampleNodeId;
    pdos.rpdos[0].mapping = {0x6200'0108, 0x6200'0208};
    config.pdos = pdos;
    return config;
}

DeviceInfo sample_info() {
    DeviceInfo info;
    info.file.file_name = "sample-device.eds";
    info.file.description = "eposp sample I/O module";
    info.file.creation_time = "12:00PM";
    info.file.creation_date = "11-22-2026";
    info.file.created_by = "eposp";
    info.vendor_name = "eposp";
    info.vendor_number = 0xFB;
    info.product_name = "eposp sample I/O module";
    info.product_number = 0x0401;
    info.revision_number = 0x0001'0000;
    info.baud_rates_kbit = {125, 250, 500, 1000};
    return info;
}

/// The dictionary after a node added its communication objects to the device's.
template <typename Use>
auto with_sample_node(Use use) {
    core::EventLoop loop;
    can::VirtualBus bus(loop);
    const auto port = bus.connect("sample");
    ObjectDictionary od;
    add_device_objects(od);
    const Node node(loop, *port, od, sample_config());
    return use(static_cast<const ObjectDictionary&>(od));
}

} // namespace

std::string sample_device_eds() {
    return with_sample_node(
        [](const ObjectDictionary& od) { return export_eds(od, sample_info()); });
}

SampleDeviceEntries sample_device_entries() {
    return with_sample_node([](const ObjectDictionary& od) {
        SampleDeviceEntries entries;
        for (const auto& [index, object] : od.objects()) {
            for (const auto& [sub_index, sub] : object.subs) {
                ++entries.all;
                entries.readable += readable(sub.access) ? 1 : 0;
            }
        }
        return entries;
    });
}

} // namespace eposp::device
