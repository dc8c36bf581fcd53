// The WSTRING functions that are cheap with the shared layout: LEN and the conversions to and
// from STRING. STRING characters are Latin-1 (CODESYS's default code page); a UTF-16 unit
// above 255 has no STRING character and becomes '?', as in CODESYS's WSTRING_TO_STRING.

#include "library_parts.hpp"
#include "string_arguments.hpp"

#include <algorithm>
#include <cstring>

namespace eposp::vm::stdlib {
namespace {

using S = Scalar;

std::uint16_t header_field(std::span<const std::uint8_t> bytes, std::size_t offset) {
    std::uint16_t value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

/// UTF-16 unit `i` of the WSTRING in `bytes` (read byte-wise: a WSTRING pointer need not be
/// aligned in VM memory).
std::uint16_t unit(std::span<const std::uint8_t> bytes, std::size_t i) {
    return header_field(bytes, kStringHeaderSize + 2 * i);
}

} // namespace

void register_wstring_functions(NativeRegistry& registry) {
    registry.add("LEN_WSTRING", {true, S::I32, {S::Ptr}}, [](NativeArgs& args) {
        const auto bytes = string_bytes(args, 0, CharWidth::Wide);
        if (!bytes.empty()) {
            args.set_result(static_cast<std::int32_t>(header_field(bytes, 2)));
        }
    });
    registry.add("WSTRING_TO_STRING", {false, S::Bool, {S::Ptr, S::Ptr}}, [](NativeArgs& args) {
        const auto source = string_bytes(args, 1, CharWidth::Wide);
        if (source.empty()) {
            return;
        }
        TextBuffer text;
        for (std::size_t i = 0; i < header_field(source, 2); ++i) {
            const auto u = unit(source, i);
            const char c = u <= 0xFF ? static_cast<char>(u) : '?';
            text.append({&c, 1});
        }
        store_string(args, 0, text.view());
    });
    registry.add("STRING_TO_WSTRING", {false, S::Bool, {S::Ptr, S::Ptr}}, [](NativeArgs& args) {
        const auto source = string_parameter(args, 1);
        const auto destination =
            source ? string_bytes(args, 0, CharWidth::Wide) : std::span<std::uint8_t>{};
        if (destination.empty()) {
            return;
        }
        // Copied first: the destination's units may overlap the source's bytes.
        TextBuffer text;
        text.append(*source);
        const auto length = std::min<std::size_t>(text.view().size(), header_field(destination, 0));
        for (std::size_t i = 0; i <= length; ++i) {
            const std::uint16_t u = i < length ? static_cast<unsigned char>(text.view()[i]) : 0;
            std::memcpy(destination.data() + kStringHeaderSize + 2 * i, &u, sizeof u);
        }
        const auto stored = static_cast<std::uint16_t>(length);
        std::memcpy(destination.data() + 2, &stored, sizeof stored);
    });
}

} // namespace eposp::vm::stdlib
