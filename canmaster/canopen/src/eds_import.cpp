#include "eposp/canopen/eds_import.hpp"

#include "eds_value.hpp"
#include "ini_document.hpp"
#include "numeric_value.hpp"

#include <array>
#include <charconv>
#include <fmt/format.h>
#include <limits>
#include <map>

namespace eposp::canopen {
namespace {

using Section = IniDocument::Section;

// The sections that describe one object: [XXXX], [XXXXsubY], and for CompactSubObj the
// [XXXXName] and [XXXXValue] lists (CiA 306 4.5.2.3).
struct ObjectSections {
    const Section* main = nullptr;
    std::map<std::uint8_t, const Section*> subs;
    const Section* names = nullptr;
    const Section* values = nullptr;
};

std::optional<std::uint64_t> parse_hex(std::string_view text) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

std::optional<Access> parse_access(std::string_view text) {
    static constexpr std::array kAccesses = {Access::Const,          Access::ReadOnly,
                                             Access::WriteOnly,      Access::ReadWrite,
                                             Access::ReadWriteInput, Access::ReadWriteOutput};
    const std::string lower = to_lower(text);
    for (const Access access : kAccesses) {
        if (lower == to_string(access)) {
            return access;
        }
    }
    return std::nullopt;
}

// One value's description, read from a section before it goes into the dictionary.
struct ValueSpec {
    std::string name;
    DataType type = DataType::Unsigned8;
    Access access = Access::ReadOnly;
    bool pdo_mappable = false;
    Bytes default_value;
    std::optional<Bytes> low_limit;
    std::optional<Bytes> high_limit;
    std::optional<Bytes> value; ///< a DCF's ParameterValue

    void apply_to(SubObject& sub) const {
        sub.name = name;
        sub.type = type;
        sub.access = access;
        sub.pdo_mappable = pdo_mappable;
        sub.default_value = default_value;
        sub.low_limit = low_limit;
        sub.high_limit = high_limit;
        sub.value = value.value_or(default_value);
    }
};

// Reads the document into a dictionary. The first error is kept and ends the import: after
// fail() every reader returns a harmless value of the right shape, and the caller checks
// failed() before it uses what was read.
class EdsImporter {
public:
    EdsImporter(const IniDocument& document, std::optional<NodeId> node_id)
        : document_(document), node_id_(node_id) {}

    core::Result<ImportedEds> run() {
        ImportedEds imported;
        read_file_info(imported.device.file);
        read_device_info(imported.device);
        collect_object_sections();
        for (const auto& [index, line] : listed_objects()) {
            if (failed()) {
                break;
            }
            read_object(index, line, imported.dictionary);
        }
        if (failed()) {
            return core::Error{*error_};
        }
        return imported;
    }

private:
    bool failed() const { return error_.has_value(); }
    void fail(std::size_t line, std::string_view message) {
        if (!error_) {
            error_ = document_.error_at(line, message);
        }
    }

    std::string text(const Section* section, std::string_view key) const {
        const auto* entry = section ? section->find(key) : nullptr;
        return entry ? entry->value : std::string();
    }

    std::uint64_t number(const Section* section, std::string_view key, std::uint64_t fallback,
                         std::uint64_t max) {
        const auto* entry = section ? section->find(key) : nullptr;
        if (entry == nullptr || entry->value.empty()) {
            return fallback;
        }
        const auto value = parse_eds_unsigned(entry->value);
        if (!value || *value > max) {
            fail(entry->line,
                 fmt::format("{}={} is not a number from 0 to {}", entry->key, entry->value, max));
            return fallback;
        }
        return *value;
    }

    bool flag(const Section* section, std::string_view key) {
        return number(section, key, 0, 1) != 0;
    }

    void read_file_info(EdsFileInfo& file) {
        const Section* section = document_.find("FileInfo");
        file.file_name = text(section, "FileName");
        file.file_version = static_cast<std::uint8_t>(number(section, "FileVersion", 1, 0xFF));
        file.file_revision = static_cast<std::uint8_t>(number(section, "FileRevision", 0, 0xFF));
        if (section && section->find("EDSVersion")) {
            file.eds_version = text(section, "EDSVersion");
        }
        file.description = text(section, "Description");
        file.creation_time = text(section, "CreationTime");
        file.creation_date = text(section, "CreationDate");
        file.created_by = text(section, "CreatedBy");
        file.modification_time = text(section, "ModificationTime");
        file.modification_date = text(section, "ModificationDate");
        file.modified_by = text(section, "ModifiedBy");

        const Section* comments = document_.find("Comments");
        const auto lines = number(comments, "Lines", 0, 0xFFFF);
        for (std::uint64_t i = 1; i <= lines && !failed(); ++i) {
            file.comments.push_back(text(comments, fmt::format("Line{}", i)));
        }
    }

    void read_device_info(DeviceInfo& info) {
        constexpr std::uint64_t kU32 = std::numeric_limits<std::uint32_t>::max();
        const Section* section = document_.find("DeviceInfo");
        info.vendor_name = text(section, "VendorName");
        info.vendor_number = static_cast<std::uint32_t>(number(section, "VendorNumber", 0, kU32));
        info.product_name = text(section, "ProductName");
        info.product_number = static_cast<std::uint32_t>(number(section, "ProductNumber", 0, kU32));
        info.revision_number =
            static_cast<std::uint32_t>(number(section, "RevisionNumber", 0, kU32));
        info.order_code = text(section, "OrderCode");
        for (const std::uint16_t rate : kEdsBaudRatesKbit) {
            if (flag(section, fmt::format("BaudRate_{}", rate))) {
                info.baud_rates_kbit.insert(rate);
            }
        }
        info.simple_boot_up_master = flag(section, "SimpleBootUpMaster");
        info.simple_boot_up_slave = flag(section, "SimpleBootUpSlave");
        info.granularity = static_cast<std::uint8_t>(number(section, "Granularity", 8, 64));
        info.dynamic_channels_supported =
            static_cast<std::uint8_t>(number(section, "DynamicChannelsSupported", 0, 0xFF));
        info.group_messaging = flag(section, "GroupMessaging");
        info.lss_supported = flag(section, "LSS_Supported");

        const Section* dummies = document_.find("DummyUsage");
        for (std::uint16_t type = 0x0001; type <= 0x0007; ++type) {
            if (flag(dummies, fmt::format("Dummy{:04X}", type))) {
                info.dummy_usage.insert(type);
            }
        }
    }

    // Sorts the sections named after objects: "1018", "1018sub2", "2000Name", "2000Value".
    void collect_object_sections() {
        for (const Section& section : document_.sections()) {
            const std::string_view name = section.name;
            const auto index = name.size() >= 4 ? parse_hex(name.substr(0, 4)) : std::nullopt;
            if (!index) {
                continue; // [FileInfo], [DeviceInfo], tool-specific sections
            }
            ObjectSections& object = objects_[static_cast<std::uint16_t>(*index)];
            const std::string rest = to_lower(name.substr(4));
            if (rest.empty()) {
                object.main = &section;
            } else if (rest.starts_with("sub")) {
                const auto sub_index = parse_hex(std::string_view(rest).substr(3));
                if (!sub_index || *sub_index > 0xFF) {
                    fail(section.line,
                         fmt::format("[{}]: the sub-index is not 0 to FF in hex", section.name));
                    return;
                }
                const auto [it, inserted] =
                    object.subs.emplace(static_cast<std::uint8_t>(*sub_index), &section);
                if (!inserted) {
                    fail(section.line, fmt::format("[{}] repeats [{}] of line {}", section.name,
                                                   it->second->name, it->second->line));
                    return;
                }
            } else if (rest == "name") {
                object.names = &section;
            } else if (rest == "value") {
                object.values = &section;
            }
        }
    }

    // CiA 306 4.6.1: the objects are those the three lists name (SupportedObjects=n, 1..n).
    std::vector<std::pair<std::uint16_t, std::size_t>> listed_objects() {
        std::vector<std::pair<std::uint16_t, std::size_t>> listed;
        std::map<std::uint16_t, std::size_t> seen;
        for (const char* list : {"MandatoryObjects", "OptionalObjects", "ManufacturerObjects"}) {
            const Section* section = document_.find(list);
            const auto count = number(section, "SupportedObjects", 0, 0x10000);
            for (std::uint64_t i = 1; i <= count && !failed(); ++i) {
                const auto* entry = section->find(fmt::format("{}", i));
                if (entry == nullptr) {
                    fail(section->find("SupportedObjects")->line,
                         fmt::format("[{}] lists {} objects but has no entry {}", section->name,
                                     count, i));
                    break;
                }
                const auto index = parse_eds_unsigned(entry->value);
                if (!index || *index == 0 || *index > 0xFFFF) {
                    fail(entry->line, fmt::format("'{}' is not an object index", entry->value));
                    break;
                }
                const auto [it, inserted] = seen.emplace(*index, entry->line);
                if (!inserted) {
                    fail(entry->line, fmt::format("object {:04X} is listed again (line {})", *index,
                                                  it->second));
                    break;
                }
                listed.emplace_back(static_cast<std::uint16_t>(*index), entry->line);
            }
        }
        return listed;
    }

    Bytes value_of(const IniDocument::Entry& entry, DataType type) {
        auto value = parse_eds_value(type, entry.value, node_id_);
        if (!value) {
            fail(entry.line, fmt::format("{}: {}", entry.key, value.error()));
            return Bytes(fixed_size(type).value_or(0), 0);
        }
        return std::move(*value);
    }

    std::optional<Bytes> limit(const Section& section, std::string_view key, DataType type) {
        const auto* entry = section.find(key);
        if (entry == nullptr || entry->value.empty()) {
            return std::nullopt;
        }
        if (!is_numeric(type)) {
            fail(entry->line,
                 fmt::format("{} on a {}: only numbers have limits", entry->key, to_string(type)));
            return std::nullopt;
        }
        return value_of(*entry, type);
    }

    // The keys of one value (CiA 306 4.6.3); for a compact array, those of the object section
    // with the name and value its lists give.
    // `domain`: a DOMAIN object (ObjectType=0x2), whose DataType and AccessType CiA 306 lets
    // default to DOMAIN and rw.
    ValueSpec read_value(const Section& section, std::string name, bool domain = false) {
        ValueSpec spec;
        spec.name = std::move(name);
        const auto* type_entry = section.find("DataType");
        const auto* access_entry = section.find("AccessType");
        if (!domain && (type_entry == nullptr || access_entry == nullptr)) {
            fail(section.line, fmt::format("[{}] needs DataType and AccessType", section.name));
            return spec;
        }
        spec.type = DataType::Domain;
        if (type_entry != nullptr) {
            const auto type_index = parse_eds_unsigned(type_entry->value);
            const auto type = type_index && *type_index <= 0xFFFF
                                  ? data_type_from_index(static_cast<std::uint16_t>(*type_index))
                                  : std::nullopt;
            if (!type) {
                fail(type_entry->line,
                     fmt::format("DataType={} is not a static data type of CiA 301 (table 44)",
                                 type_entry->value));
                return spec;
            }
            spec.type = *type;
        }
        spec.access = Access::ReadWrite;
        if (access_entry != nullptr) {
            const auto access = parse_access(access_entry->value);
            if (!access) {
                fail(access_entry->line,
                     fmt::format("AccessType={} is none of const, ro, wo, rw, rwr, rww",
                                 access_entry->value));
                return spec;
            }
            spec.access = *access;
        }
        spec.pdo_mappable = flag(&section, "PDOMapping");
        const auto* default_entry = section.find("DefaultValue");
        spec.default_value = default_entry ? value_of(*default_entry, spec.type)
                                           : Bytes(fixed_size(spec.type).value_or(0), 0);
        if (const auto* parameter_value = section.find("ParameterValue")) {
            spec.value = value_of(*parameter_value, spec.type);
        }
        spec.low_limit = limit(section, "LowLimit", spec.type);
        spec.high_limit = limit(section, "HighLimit", spec.type);
        if (spec.low_limit && spec.high_limit && !failed() &&
            compare(*decode_numeric(spec.type, *spec.low_limit),
                    *decode_numeric(spec.type, *spec.high_limit)) ==
                std::partial_ordering::greater) {
            fail(section.find("HighLimit")->line, "HighLimit is below LowLimit");
        }
        return spec;
    }

    void read_object(std::uint16_t index, std::size_t list_line, ObjectDictionary& dictionary) {
        const ObjectSections& sections = objects_[index];
        if (sections.main == nullptr) {
            fail(list_line,
                 fmt::format("object {:04X} is listed but has no [{:04X}] section", index, index));
            return;
        }
        const Section& main = *sections.main;
        const auto* name = main.find("ParameterName");
        if (name == nullptr) {
            fail(main.line, fmt::format("[{}] has no ParameterName", main.name));
            return;
        }
        const auto code = number(&main, "ObjectType", 0x7, 0xFF);
        if (failed()) {
            return;
        }
        switch (static_cast<ObjectCode>(code)) {
        case ObjectCode::Var:
        case ObjectCode::Domain:
            read_variable(index, static_cast<ObjectCode>(code), main, name->value, dictionary);
            return;
        case ObjectCode::Array:
        case ObjectCode::Record:
            read_structure(index, static_cast<ObjectCode>(code), sections, name->value, dictionary);
            return;
        case ObjectCode::Null:
        case ObjectCode::DefType:
        case ObjectCode::DefStruct:
            return; // type definitions: no values; dummy mapping is [DummyUsage]'s business
        }
        fail(main.find("ObjectType")->line,
             fmt::format("ObjectType={} is none of 0x2, 0x5..0x9", main.find("ObjectType")->value));
    }

    void read_variable(std::uint16_t index, ObjectCode code, const Section& main,
                       const std::string& name, ObjectDictionary& dictionary) {
        if (const auto* compact = main.find("CompactSubObj");
            compact != nullptr && number(&main, "CompactSubObj", 0, 0xFE) != 0) {
            fail(compact->line, "CompactSubObj is for ARRAY objects (ObjectType=0x8)");
        }
        const ValueSpec spec = read_value(main, name, code == ObjectCode::Domain);
        if (failed()) {
            return;
        }
        SubObject& sub =
            dictionary.add_variable(index, name, spec.type, spec.access, spec.default_value);
        spec.apply_to(sub);
        dictionary.find(index)->code = code;
    }

    void read_structure(std::uint16_t index, ObjectCode code, const ObjectSections& sections,
                        const std::string& name, ObjectDictionary& dictionary) {
        const Section& main = *sections.main;
        if (sections.subs.empty() && main.find("CompactSubObj") != nullptr) {
            read_compact_array(index, code, sections, name, dictionary);
            return;
        }
        const auto sub_number = number(&main, "SubNumber", sections.subs.size(), 0x100);
        if (!failed() && sub_number != sections.subs.size()) {
            fail(main.find("SubNumber")->line,
                 fmt::format("SubNumber={} but [{}] has {} sub-index sections",
                             main.find("SubNumber")->value, main.name, sections.subs.size()));
        }
        std::map<std::uint8_t, ValueSpec> specs;
        for (const auto& [sub_index, section] : sections.subs) {
            const auto* sub_name = section->find("ParameterName");
            if (sub_name == nullptr) {
                fail(section->line, fmt::format("[{}] has no ParameterName", section->name));
            }
            if (failed()) {
                return;
            }
            specs.emplace(sub_index, read_value(*section, sub_name->value));
        }
        if (failed()) {
            return;
        }
        dictionary.add_object(index, name, code);
        for (const auto& [sub_index, spec] : specs) {
            if (sub_index != 0) {
                spec.apply_to(dictionary.add_sub(index, sub_index, spec.name, spec.type,
                                                 spec.access, spec.default_value));
            }
        }
        // Sub-index 0 as the file gives it (the error history's is rw, for example).
        if (const auto it = specs.find(0); it != specs.end()) {
            it->second.apply_to(*dictionary.find(index, 0));
        }
    }

    // CiA 306 4.5.2.3: an ARRAY whose sub-indices 1..n share the object's keys; [XXXXName] and
    // [XXXXValue] may give each its name and value.
    void read_compact_array(std::uint16_t index, ObjectCode code, const ObjectSections& sections,
                            const std::string& name, ObjectDictionary& dictionary) {
        const Section& main = *sections.main;
        const auto* compact = main.find("CompactSubObj");
        const auto count = number(&main, "CompactSubObj", 0, 0xFE);
        if (failed()) {
            return;
        }
        if (code != ObjectCode::Array) {
            fail(compact->line, "CompactSubObj is for ARRAY objects (ObjectType=0x8)");
            return;
        }
        const ValueSpec shared = read_value(main, name);
        std::vector<ValueSpec> specs;
        for (std::uint64_t sub_index = 1; sub_index <= count && !failed(); ++sub_index) {
            ValueSpec spec = shared;
            const std::string key = fmt::format("{}", sub_index);
            const auto* sub_name = sections.names ? sections.names->find(key) : nullptr;
            spec.name = sub_name ? sub_name->value : fmt::format("{}{}", name, sub_index);
            if (const auto* value = sections.values ? sections.values->find(key) : nullptr) {
                spec.value = value_of(*value, spec.type);
            }
            specs.push_back(std::move(spec));
        }
        if (failed()) {
            return;
        }
        dictionary.add_object(index, name, code);
        dictionary.find(index, 0)->name = "NrOfObjects";
        for (std::size_t i = 0; i < specs.size(); ++i) {
            const ValueSpec& spec = specs[i];
            spec.apply_to(dictionary.add_sub(index, static_cast<std::uint8_t>(i + 1), spec.name,
                                             spec.type, spec.access, spec.default_value));
        }
    }

    const IniDocument& document_;
    std::optional<NodeId> node_id_;
    std::map<std::uint16_t, ObjectSections> objects_;
    std::optional<std::string> error_;
};

} // namespace

core::Result<ImportedEds> import_eds(std::string_view text, std::string_view source_name,
                                     std::optional<NodeId> node_id) {
    const auto document = IniDocument::parse(text, source_name);
    if (!document) {
        return core::Error{document.error()};
    }
    return EdsImporter(*document, node_id).run();
}

} // namespace eposp::canopen
