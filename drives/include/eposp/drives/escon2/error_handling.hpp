#pragma once

#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/escon2/device_errors.hpp"

#include <cstdint>
#include <vector>

namespace eposp::drives::escon2 {

/// The error handling of ESCON2 FW spec 7.1 on the dictionary: each error or warning of table
/// 110 that occurs is entered in the error history 0x1003 (6.2.3: newest at sub 1, bit 31 marks
/// a warning), sets its bits in the error register 0x1001 (table 35) while active, and shows in
/// the error code 0x603F (6.2.58: a non-erasable error before an erasable one before a warning;
/// a warning only while active). The reaction (table 110 "f", "d", "w") is the caller's to carry
/// out with the device control.
class ErrorHandling {
public:
    explicit ErrorHandling(canopen::ObjectDictionary& od);

    /// `code` occurred. Returns whether it is new: an error or warning still active is not
    /// entered again. A code that table 110 does not list is a programming error
    /// (std::invalid_argument).
    bool raise(std::uint16_t code);
    /// The cause of an auto-clearing warning went away (e.g. 7.1.9, 7.1.30).
    void clear_warning(std::uint16_t code);
    /// Fault reset (transition 15): the errors that a controlword clears are gone; those that
    /// need a device reset and the warnings stay.
    void fault_reset();
    /// Table 8 "Clear warning": the warnings reset with the controlword (7.1.36).
    void clear_warnings();
    /// Power-on: nothing active (the history stays as the dictionary keeps it).
    void reset();

    bool warning_active() const { return !warnings_.empty(); }
    /// An error is active that a fault reset cannot clear (ErrorRecovery::ResetDevice).
    bool needs_device_reset() const;
    bool active(std::uint16_t code) const;

private:
    void publish();

    canopen::ObjectDictionary& od_;
    canopen::ErrorHistory history_;
    std::vector<std::uint16_t> errors_;   ///< active, in order of occurrence
    std::vector<std::uint16_t> warnings_; ///< active, in order of occurrence
};

} // namespace eposp::drives::escon2
