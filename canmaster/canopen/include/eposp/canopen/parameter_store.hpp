#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace eposp::canopen {

/// What load_stored_values() found. Anything but Applied and NoneStored means the stored
/// values were refused and the defaults apply: the caller reports it (an EMCY, an error
/// history entry), since a device that silently lost its configuration is a hazard.
enum class StoredValuesStatus {
    Applied,        ///< a valid store of this dictionary's layout was applied
    NoneStored,     ///< nothing stored (never saved, or restored to defaults): defaults apply
    Corrupt,        ///< the file is damaged or unreadable: defaults apply
    LayoutMismatch, ///< the file belongs to another dictionary layout: defaults apply
};

struct StoredValuesReport {
    StoredValuesStatus status = StoredValuesStatus::NoneStored;
    std::string detail; ///< why a store was refused, naming the file
    bool refused() const {
        return status == StoredValuesStatus::Corrupt ||
               status == StoredValuesStatus::LayoutMismatch;
    }
};

/// The non-volatile memory behind 0x1010 "Store parameters" and 0x1011 "Restore default
/// parameters" (CiA 301 7.5.2.13/14): the values of every `persistent` sub-object of a
/// dictionary, in one file with a CRC-32 and the identity of the dictionary layout.
class ParameterStore {
public:
    ParameterStore(ObjectDictionary& dictionary, std::filesystem::path file);

    /// 0x1010 "save": writes every persistent value, atomically (temporary file, fsync,
    /// rename). CiA 301 7.5.2.13: a failed store is HardwareError.
    AbortCode save();
    /// 0x1011 "load": forgets the stored values, so that the defaults apply from the next reset
    /// or power-up on (CiA 301 7.5.2.14; EPOS2 firmware specification 8.2.9). The current
    /// values are left alone. A failure is HardwareError.
    AbortCode restore_defaults();
    /// EPOS2 firmware specification 8.2.9, 0x1011 sub 5: the next save() stores the COB-IDs of
    /// RPDO1..4 and TPDO1..4 calculated from `node_id` as the predefined connection set has them
    /// (CiA 301 7.3.5), so they take effect after saving and restarting the node.
    void restore_pdo_cob_ids_at_next_save(NodeId node_id);

    /// At power-up and at a reset application: sets every value to its default, then applies
    /// the stored values if the file is valid and of this layout. Listeners are not told (as
    /// for ObjectDictionary::reset_to_defaults()).
    StoredValuesReport load_stored_values();

    /// A CRC-32 over index, sub-index and data type of every persistent sub-object: a store
    /// made for another layout is not applied.
    std::uint32_t layout_id() const;
    const std::filesystem::path& file() const { return file_; }

private:
    Bytes value_to_store(std::uint16_t index, std::uint8_t sub_index, const SubObject& sub) const;

    ObjectDictionary& dictionary_;
    std::filesystem::path file_;
    std::optional<NodeId> pdo_cob_id_node_;
};

} // namespace eposp::canopen
