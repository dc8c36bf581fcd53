#pragma once

#include "eposp/compiler/ast/direct_address.hpp"
#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/compiler/sema/type.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace eposp::compiler::checks {

/// Why a variable of `type` cannot be located at `address` (E0420); nullopt when it fits or the
/// address is the unspecified `%I*`.
std::optional<std::string> location_mismatch(const ast::DirectAddress& address,
                                             const sema::Type& type);
/// The type of a direct address used in code (`%IW4`), by its size: BOOL, BYTE, WORD, DWORD or
/// LWORD.
ast::ElementaryType direct_address_type(ast::DirectAddress::Size size);
/// The bytes of one unit of `size` (byte addressing as CODESYS: %IW4 is the word at byte 8).
std::uint32_t direct_address_unit(ast::DirectAddress::Size size);

} // namespace eposp::compiler::checks
