#pragma once

#include "eposp/can/frame.hpp"

#include <cstdint>

namespace eposp::can {

/// The arbitration field of `frame` read as a number, so that the frame with the lower value
/// wins bus arbitration (ISO 11898-1:2015, 10.4.2.3 and 10.8): the bits in wire order, base
/// identifier first, then RTR (standard) or SRR (extended), IDE, and for extended frames the
/// identifier extension and RTR. A dominant bit (0) wins over a recessive one, so a standard
/// data frame beats an extended frame with the same base identifier through RTR/SRR, a standard
/// remote frame beats it through IDE, and a data frame beats a remote frame with its identifier.
std::uint32_t arbitration_field(const Frame& frame);

/// True when `a` wins arbitration against `b`.
inline bool wins_arbitration(const Frame& a, const Frame& b) {
    return arbitration_field(a) < arbitration_field(b);
}

} // namespace eposp::can
