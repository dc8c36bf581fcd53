#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"

#include <cstdint>
#include <functional>

namespace eposp::canopen {

/// The write access signatures of CiA 301 7.5.2.13/14 (EPOS2 firmware specification 8.2.8/9):
/// the ASCII letters "save" and "load", first letter in the lowest byte.
inline constexpr std::uint32_t kSaveSignature = 0x6576'6173;
inline constexpr std::uint32_t kLoadSignature = 0x6461'6F6C;
/// EPOS P firmware specification 10.10, table 9: "eras".
inline constexpr std::uint32_t kEraseSignature = 0x7361'7265;

struct StoreRestoreOptions {
    /// Asked before a restore; returns the code that refuses it, or None. The EPOS2 allows a
    /// restore only in "Power Disable" and pre-operational (8.2.9), the EPOS P not while its
    /// program runs. Empty: always allowed.
    std::function<AbortCode()> restore_permitted;
};

/// Adds 0x1010 "Store Parameters" with sub 1 "Save all Parameters" and 0x1011 "Restore Default
/// Parameters" with sub 1 "Restore all Default Parameters" (EPOS2 firmware specification
/// 8.2.8/8.2.9, EPOS P 10.9/10.10), both ARRAY of UNSIGNED32 rw. Writing "save" or "load"
/// calls `store`; any other value is refused with TransferOrStore. A read gives the capability
/// bits: 1 (the device saves on command / restores defaults).
void add_store_restore_objects(ObjectDictionary& dictionary, ParameterStore& store,
                               StoreRestoreOptions options = {});

/// Adds EPOS2 0x1011 sub 5 "Restore Default PDO COB-IDs" (EPOS2 firmware specification 8.2.9,
/// table 8-73): "load" makes the next save store the COB-IDs of PDOs 1..4 calculated from the
/// node-ID the function gives at that moment. Needs add_store_restore_objects() first.
void add_restore_pdo_cob_ids_object(ObjectDictionary& dictionary, ParameterStore& store,
                                    std::function<NodeId()> node_id,
                                    StoreRestoreOptions options = {});

/// Adds EPOS P 0x1011 sub 2 "Erase Application Program" (EPOS P firmware specification 10.10,
/// table 9): "eras" calls `erase` (which may refuse, e.g. while the program runs); any other value
/// is refused with TransferOrStore. Needs add_store_restore_objects() first.
void add_erase_program_object(ObjectDictionary& dictionary, std::function<AbortCode()> erase);

} // namespace eposp::canopen
