#pragma once

#include "eposp/vm/task_state.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace eposp::vm {

/// The EPOS P error codes the PLC runtime raises (EPOS P firmware specification 9.1, table 1).
namespace error_code {
inline constexpr std::uint16_t kInterpreter = 0x6181;    ///< a run-time error in the program
inline constexpr std::uint16_t kTimerTask = 0x6183;      ///< a cyclic task overran its period
inline constexpr std::uint16_t kInterruptTask = 0x6184;  ///< an event task re-triggered while busy
inline constexpr std::uint16_t kDataAccess = 0x6185;     ///< a bad data access (index, pointer)
inline constexpr std::uint16_t kRetainVariable = 0x6310; ///< retain data not saved or restored
} // namespace error_code

/// Where the runtime reports its errors; the device puts them into its error history 0x1003.
using ErrorSink = std::function<void(std::uint16_t code, std::string text)>;

/// The error code of a trap. Data Access Error 0x6185 is "data or program access exception":
/// an array index out of range, a NULL or dangling pointer. Everything else the interpreter
/// stops for is Interpreter Error 0x6181: division by zero, a value outside its subrange, the
/// watchdog, the call stack, and a failing host function (Native Code Error 0x6182 is the
/// EPOS P's compiled native code, which eposp does not have; its host functions are part of
/// the interpreter).
std::uint16_t error_code_of(Trap trap);

} // namespace eposp::vm
