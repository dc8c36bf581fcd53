#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>

namespace eposp::canopen {

inline constexpr std::uint16_t kCobIdSyncIndex = 0x1005;
inline constexpr std::uint16_t kCommunicationCyclePeriodIndex = 0x1006;
inline constexpr std::uint16_t kSynchronousWindowLengthIndex = 0x1007;
inline constexpr std::uint16_t kSyncCounterOverflowIndex = 0x1019;

/// Which SYNC objects a device has, and the ranges its manual gives them.
struct SyncObjectOptions {
    /// 0x1006 and 0x1019, and the generate bit of 0x1005 (an EPOS2 has none of them).
    bool producer = true;
    /// 0x1007 (an EPOS2 has none).
    bool window = true;
    /// The shortest non-zero 0x1006 in µs (EPOS P FW spec 10.6: 1000).
    std::uint32_t min_cycle_period_us = 0;
    /// The shortest non-zero 0x1007 in µs (EPOS P FW spec 10.7: 500).
    std::uint32_t min_window_length_us = 0;
};

/// The SYNC objects with their CiA 301 defaults and write rules (CiA 301 7.5.2,
/// 1005h/1006h/1007h/1019h):
/// - 0x1005 COB-ID SYNC (default 0x80; bit 30 generate, bit 29 29-bit identifier): an
///   identifier CiA 301 7.3.5 reserves, bits 11..28 set for an 11-bit identifier,
///   a new identifier while generating, or generate on a device without a producer: InvalidValue
///   (0x06090030).
/// - 0x1006 Communication Cycle Period (µs, 0 = no SYNC), 0x1007 Synchronous Window Length
///   (µs, 0 = no window): a non-zero value below the minimum: ValueTooLow (0x06090032).
/// - 0x1019 Synchronous Counter Overflow Value (0 = no counter, 2..240): while 0x1006 is non-zero
///   DeviceState (0x08000022); the reserved values 1 and 241..255: InvalidValue.
void add_sync_objects(ObjectDictionary& od, const SyncObjectOptions& options = {});
/// The write rules of add_sync_objects() on the SYNC objects `od` already has (e.g. from an
/// EDS), where they have no hook of their own (add_write_rule()).
void enforce_sync_rules(ObjectDictionary& od, const SyncObjectOptions& options = {});

} // namespace eposp::canopen
