#pragma once

#include "eposp/canopen/entry_builder.hpp"

#include <cstdint>
#include <initializer_list>

namespace eposp::drives::epos2 {

/// A "Value Range" given as a list of codes (a table of chapter 8): every other value is refused
/// with 0x06090030 "value range of parameter exceeded" (EPOS2 FW spec table 4-12), those beyond
/// the list's smallest or largest code included; 0x06090031 / 0x06090032 ("too high / low")
/// belong to min ... max ranges. So the entry has no low and high limit (which the dictionary
/// would check first), and its EDS lists none.
canopen::Entry value_list(canopen::Entry entry, std::initializer_list<std::int64_t> values);

} // namespace eposp::drives::epos2
