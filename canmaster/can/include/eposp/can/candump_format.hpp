#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/core/result.hpp"

#include <string>
#include <string_view>

namespace eposp::can {

/// One line of a `candump -L` log: `(1436509052.249713) can0 123#DEADBEEF`.
struct CandumpRecord {
    TraceTime time;             ///< recorded with microsecond resolution
    std::string interface_name; ///< e.g. `can0`
    Frame frame;

    friend bool operator==(const CandumpRecord&, const CandumpRecord&) = default;
};

/// A frame in can-utils' compact form, as `candump -L` writes it and `cansend` reads it:
/// `123#DEADBEEF` (standard id: 3 hex digits), `12345678#00` (extended: 8 digits), `123#` (no
/// data), `123#R` / `123#R4` (remote, DLC shown when not 0), and error frames as 8 digits that
/// include CAN_ERR_FLAG 0x20000000 followed by their data bytes. Hex is uppercase.
std::string format_candump_frame(const Frame& frame);

/// Reads a frame written as format_candump_frame() describes, also accepting lowercase hex and
/// `.` between data bytes as cansend does. CAN FD (`##`) is refused.
core::Result<Frame> parse_candump_frame(std::string_view text);

/// `(%010ld.%06ld) <interface> <frame>` without a line end; the time is truncated to µs.
std::string format_candump_line(const CandumpRecord& record);

/// Reads one log line (a trailing `\r` or `\n` is allowed, as is the ` R`/` T` direction field
/// that newer candump versions append with -x, which is ignored). Any malformed line yields an
/// error that says what is wrong; no input makes it crash.
core::Result<CandumpRecord> parse_candump_line(std::string_view line);

} // namespace eposp::can
