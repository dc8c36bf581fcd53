#include "eposp/canopen/eds_export.hpp"

#include "eds_value.hpp"

#include <array>
#include <fmt/format.h>

namespace eposp::canopen {
namespace {

enum class ObjectList { Mandatory, Optional, Manufacturer };

// CiA 306 4.6.1: 0x1000, 0x1001 and 0x1018 are mandatory, 0x2000..0x5FFF manufacturer-specific,
// the rest (other communication and profile objects, data types) optional.
ObjectList list_of(std::uint16_t index) {
    if (index == 0x1000 || index == 0x1001 || index == 0x1018) {
        return ObjectList::Mandatory;
    }
    if (index >= 0x2000 && index <= 0x5FFF) {
        return ObjectList::Manufacturer;
    }
    return ObjectList::Optional;
}

// A value of an INI line cannot break the line.
std::string one_line(std::string_view text) {
    std::string line(text);
    for (char& c : line) {
        c = (c == '\r' || c == '\n') ? ' ' : c;
    }
    return line;
}

class EdsWriter {
public:
    void section(std::string_view name) {
        if (!text_.empty()) {
            text_ += '\n';
        }
        text_ += fmt::format("[{}]\n", name);
    }
    void key(std::string_view key, std::string_view value) {
        text_ += fmt::format("{}={}\n", key, one_line(value));
    }
    void key(std::string_view key, std::uint64_t value) {
        this->key(key, fmt::format("{}", value));
    }
    void hex(std::string_view key, std::uint32_t value) {
        this->key(key, fmt::format("0x{:08X}", value));
    }
    std::string take() { return std::move(text_); }

private:
    std::string text_;
};

std::size_t count_objects(const ObjectDictionary& dictionary, std::uint16_t first,
                          std::uint16_t last) {
    std::size_t count = 0;
    for (const auto& [index, object] : dictionary.objects()) {
        count += (index >= first && index <= last) ? 1 : 0;
    }
    return count;
}

void write_file_info(EdsWriter& out, const EdsFileInfo& file) {
    out.section("FileInfo");
    out.key("FileName", file.file_name);
    out.key("FileVersion", file.file_version);
    out.key("FileRevision", file.file_revision);
    out.key("EDSVersion", file.eds_version);
    out.key("Description", file.description);
    out.key("CreationTime", file.creation_time);
    out.key("CreationDate", file.creation_date);
    out.key("CreatedBy", file.created_by);
    out.key("ModificationTime", file.modification_time);
    out.key("ModificationDate", file.modification_date);
    out.key("ModifiedBy", file.modified_by);
}

void write_device_info(EdsWriter& out, const DeviceInfo& info, const ObjectDictionary& dictionary) {
    out.section("DeviceInfo");
    out.key("VendorName", info.vendor_name);
    out.hex("VendorNumber", info.vendor_number);
    out.key("ProductName", info.product_name);
    out.hex("ProductNumber", info.product_number);
    out.hex("RevisionNumber", info.revision_number);
    out.key("OrderCode", info.order_code);
    for (const std::uint16_t rate : kEdsBaudRatesKbit) {
        out.key(fmt::format("BaudRate_{}", rate), info.baud_rates_kbit.contains(rate) ? 1 : 0);
    }
    out.key("SimpleBootUpMaster", info.simple_boot_up_master ? 1 : 0);
    out.key("SimpleBootUpSlave", info.simple_boot_up_slave ? 1 : 0);
    out.key("Granularity", info.granularity);
    out.key("DynamicChannelsSupported", info.dynamic_channels_supported);
    out.key("GroupMessaging", info.group_messaging ? 1 : 0);
    // CiA 301 7.5.2.35/37: RPDO communication parameters at 0x1400.., TPDO ones at 0x1800..
    out.key("NrOfRxPDO", count_objects(dictionary, 0x1400, 0x15FF));
    out.key("NrOfTxPDO", count_objects(dictionary, 0x1800, 0x19FF));
    out.key("LSS_Supported", info.lss_supported ? 1 : 0);

    out.section("DummyUsage");
    for (std::uint16_t type = 0x0001; type <= 0x0007; ++type) {
        out.key(fmt::format("Dummy{:04X}", type), info.dummy_usage.contains(type) ? 1 : 0);
    }
    if (!info.file.comments.empty()) {
        out.section("Comments");
        out.key("Lines", info.file.comments.size());
        for (std::size_t i = 0; i < info.file.comments.size(); ++i) {
            out.key(fmt::format("Line{}", i + 1), info.file.comments[i]);
        }
    }
}

void write_object_list(EdsWriter& out, const ObjectDictionary& dictionary, ObjectList list,
                       std::string_view name) {
    std::vector<std::uint16_t> indices;
    for (const auto& [index, object] : dictionary.objects()) {
        if (list_of(index) == list) {
            indices.push_back(index);
        }
    }
    out.section(name);
    out.key("SupportedObjects", indices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        out.key(fmt::format("{}", i + 1), fmt::format("0x{:04X}", indices[i]));
    }
}

void write_commissioning(EdsWriter& out, const DeviceCommissioning& commissioning) {
    out.section("DeviceComissioning");
    out.key("NodeID", fmt::format("0x{:02X}", commissioning.node_id));
    out.key("NodeName", commissioning.node_name);
    out.key("Baudrate", commissioning.baudrate_kbit);
    out.key("NetNumber", commissioning.net_number);
    out.key("NetworkName", commissioning.network_name);
    out.key("CANopenManager", commissioning.canopen_manager ? 1 : 0);
}

// CiA 306 4.6.3: the keys of one value, in the order the standard lists them; a DCF adds the
// configured value where it is not the default.
void write_value_keys(EdsWriter& out, const ObjectDictionary& dictionary, std::uint16_t index,
                      std::uint8_t sub_index, const SubObject& sub, bool configured) {
    out.key("DataType", fmt::format("0x{:04X}", static_cast<std::uint16_t>(sub.type)));
    if (sub.low_limit) {
        out.key("LowLimit", format_eds_value(sub.type, *sub.low_limit));
    }
    if (sub.high_limit) {
        out.key("HighLimit", format_eds_value(sub.type, *sub.high_limit));
    }
    out.key("AccessType", to_string(sub.access));
    out.key("DefaultValue", format_eds_value(sub.type, sub.default_value));
    out.key("PDOMapping", sub.pdo_mappable ? 1 : 0);
    if (configured && readable(sub.access) && writable(sub.access)) {
        if (const Bytes value = dictionary.get(index, sub_index); value != sub.default_value) {
            out.key("ParameterValue", format_eds_value(sub.type, value));
        }
    }
}

void write_object(EdsWriter& out, const ObjectDictionary& dictionary, const Object& object,
                  bool configured) {
    const std::string section = fmt::format("{:04X}", object.index);
    out.section(section);
    out.key("ParameterName", object.name);
    out.key("ObjectType", fmt::format("0x{:X}", static_cast<unsigned>(object.code)));
    if (object.code != ObjectCode::Array && object.code != ObjectCode::Record) {
        if (const auto it = object.subs.find(0); it != object.subs.end()) {
            write_value_keys(out, dictionary, object.index, 0, it->second, configured);
        }
        return;
    }
    out.key("SubNumber", fmt::format("0x{:X}", object.subs.size()));
    for (const auto& [sub_index, sub] : object.subs) {
        out.section(fmt::format("{}sub{:X}", section, sub_index));
        out.key("ParameterName", sub.name);
        out.key("ObjectType", fmt::format("0x{:X}", static_cast<unsigned>(ObjectCode::Var)));
        write_value_keys(out, dictionary, object.index, sub_index, sub, configured);
    }
}

std::string write_document(const ObjectDictionary& dictionary, const DeviceInfo& info,
                           const DeviceCommissioning* commissioning) {
    EdsWriter out;
    write_file_info(out, info.file);
    write_device_info(out, info, dictionary);
    if (commissioning) {
        write_commissioning(out, *commissioning);
    }
    write_object_list(out, dictionary, ObjectList::Mandatory, "MandatoryObjects");
    write_object_list(out, dictionary, ObjectList::Optional, "OptionalObjects");
    write_object_list(out, dictionary, ObjectList::Manufacturer, "ManufacturerObjects");
    for (const auto& [index, object] : dictionary.objects()) {
        write_object(out, dictionary, object, commissioning != nullptr);
    }
    return out.take();
}

} // namespace

std::string export_eds(const ObjectDictionary& dictionary, const DeviceInfo& info) {
    return write_document(dictionary, info, nullptr);
}

std::string export_dcf(const ObjectDictionary& dictionary, const DeviceInfo& info,
                       const DeviceCommissioning& commissioning) {
    return write_document(dictionary, info, &commissioning);
}

} // namespace eposp::canopen
