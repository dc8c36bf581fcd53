#pragma once

#include "eposp/vm/image.hpp"

#include <cstdint>
#include <optional>

// Where an instruction is in the source, the same for run-time errors and for the call sites a
// native function asks for (NativeArgs::call_site).

namespace eposp::vm::detail {

/// The line of `pou`'s source that `instruction` belongs to; 0 without a line table.
std::uint32_t line_at(const Pou& pou, std::uint32_t instruction);

/// In a body copied in place of a call, an instruction is the callee's, at its own line: moves
/// `pou` and `instruction` there. A callee without source (a native block's body) has none: its
/// call site stands, and the callee is returned.
std::optional<std::uint32_t> locate(const Image& image, std::uint32_t& pou,
                                    std::uint32_t& instruction);

/// The POU whose code holds `instruction`.
std::uint32_t pou_at(const Image& image, std::uint32_t instruction);

} // namespace eposp::vm::detail
