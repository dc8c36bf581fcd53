#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <vector>

namespace eposp::canopen {

inline constexpr std::uint16_t kErrorRegisterIndex = 0x1001;
inline constexpr std::uint16_t kPreDefinedErrorFieldIndex = 0x1003;

/// The bits of the error register 0x1001 (CiA 301 7.5.2, 1001h; EPOS2 FW spec table 8-70; EPOS P FW
/// spec table 2). Bit 6 is reserved (always 0).
namespace error_register {
inline constexpr std::uint8_t kGeneric = 0x01;
inline constexpr std::uint8_t kCurrent = 0x02;
inline constexpr std::uint8_t kVoltage = 0x04;
inline constexpr std::uint8_t kTemperature = 0x08;
inline constexpr std::uint8_t kCommunication = 0x10;
inline constexpr std::uint8_t kDeviceProfile = 0x20;
inline constexpr std::uint8_t kManufacturer = 0x80; ///< "Motion error" on the EPOS2
} // namespace error_register

/// Entries in 0x1003 as the manuals give them.
inline constexpr std::uint8_t kEpos2ErrorHistoryEntries = 5;  ///< EPOS2 FW spec 8.2.3
inline constexpr std::uint8_t kEposPErrorHistoryEntries = 16; ///< EPOS P FW spec 10.4

/// 0x1001 Error Register (UNSIGNED8, ro) and 0x1003 Pre-defined Error Field (CiA 301 7.5.2,
/// 1001h/1003h; EPOS2 FW spec 8.2.2/8.2.3) with `capacity` entries (1..254), UNSIGNED32 ro.
/// Sub-index 0 of 0x1003 is the number of errors recorded: writing 0 empties the history, any other
/// value is refused with InvalidValue (0x06090030). Objects `od` has already (e.g. from an EDS)
/// are kept, and get that rule where they have no write hook of their own.
void add_error_objects(ObjectDictionary& od, std::uint8_t capacity);

/// When 0x1001 bit 0 is set.
enum class GenericErrorBit {
    WithEveryError, ///< whenever any bit is set (CiA 301 7.5.2.2)
    FromTheTable,   ///< only as the device's error table gives it (EPOS2 FW spec table 4-11)
};

/// The device's view of 0x1001 and 0x1003; the values live in the dictionary.
class ErrorHistory {
public:
    explicit ErrorHistory(ObjectDictionary& od,
                          GenericErrorBit generic_bit = GenericErrorBit::WithEveryError)
        : od_(od), generic_bit_(generic_bit) {}

    /// A new entry at sub-index 1; the older ones move down and the oldest beyond the capacity
    /// is dropped. An entry is the error code in bits 15..0 and additional information above
    /// (0 on the EPOS2; warning, port and node-ID on the EPOS P, FW spec table 4).
    void record(std::uint32_t entry);
    void clear();
    /// Newest first.
    std::vector<std::uint32_t> entries() const;

    std::uint8_t error_register() const;
    /// `bits`, with the generic error bit whenever any bit is set unless FromTheTable.
    void set_error_register(std::uint8_t bits);

private:
    ObjectDictionary& od_;
    GenericErrorBit generic_bit_;
};

} // namespace eposp::canopen
