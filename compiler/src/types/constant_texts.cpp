// The constants of the string functions of table 29 (LEN, LEFT, RIGHT, MID, CONCAT, INSERT,
// DELETE, REPLACE, FIND) on STRING and WSTRING constants, computed by the VM's own functions
// (vm/stdlib/text_functions.hpp) on the texts the natives would read: a literal's characters,
// a CONSTANT's text cut at its declared length (convert()), a call's result cut at the capacity
// of the string code generation computes it into (the typing stage's, vm::stdlib::
// text_capacity).

#include "constant_folder.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "eposp/vm/stdlib/text_functions.hpp"

#include <algorithm>
#include <limits>

namespace eposp::compiler::types {

namespace {

namespace stdlib = vm::stdlib;

/// A length or position as the native takes it: code generation's as_dint, which saturates a
/// wider integer into DINT.
std::optional<std::int32_t> dint_argument(const Constant& constant) {
    constexpr std::int64_t kLow = std::numeric_limits<std::int32_t>::min();
    constexpr std::int64_t kHigh = std::numeric_limits<std::int32_t>::max();
    if (const auto* i = std::get_if<std::int64_t>(&constant)) {
        return static_cast<std::int32_t>(std::clamp(*i, kLow, kHigh));
    }
    if (const auto* u = std::get_if<std::uint64_t>(&constant)) {
        return static_cast<std::int32_t>(std::min(*u, static_cast<std::uint64_t>(kHigh)));
    }
    return std::nullopt;
}

/// The text `pieces` make, cut at `capacity` as when stored into a string of that capacity.
template <typename Char>
std::basic_string<Char> stored(const stdlib::TextPieces<Char>& pieces, std::uint32_t capacity) {
    std::basic_string<Char> text;
    for (const stdlib::Text<Char> piece : pieces) {
        text += piece.substr(0, capacity - text.size());
    }
    return text;
}

template <typename Char>
std::basic_string<Char> stored(stdlib::Text<Char> text, std::uint32_t capacity) {
    return std::basic_string<Char>(text.substr(0, capacity));
}

/// What the function `name` computes from `values`, the first `texts` of them texts of Char,
/// the others `numbers`: a count (LEN, FIND, as the native's DINT) or a text of `result`.
template <typename Char>
std::optional<Constant> fold(std::string_view name, const std::vector<Constant>& values,
                             std::size_t texts, const std::vector<std::int32_t>& numbers,
                             const sema::Type& result) {
    std::vector<stdlib::Text<Char>> in;
    for (std::size_t i = 0; i < texts; ++i) {
        const auto* text = std::get_if<std::basic_string<Char>>(&values[i]);
        if (text == nullptr) {
            return std::nullopt; // a type mismatch, reported as such
        }
        in.emplace_back(*text);
    }
    if (name == "LEN") {
        return std::int64_t{static_cast<std::int32_t>(in[0].size())};
    }
    if (name == "FIND") {
        return std::int64_t{stdlib::find_in(in[0], in[1])};
    }
    constexpr bool kWide = std::is_same_v<Char, char16_t>;
    if (result.kind != sema::TypeKind::String || result.wide != kWide) {
        return std::nullopt;
    }
    // Cut where the VM cuts it: at the capacity of the string it is computed into.
    const std::uint32_t capacity = std::min(result.capacity, stdlib::kMaxStringCapacity);
    if (name == "CONCAT") {
        // Folded left to right into the result, as code generation calls the binary native.
        std::basic_string<Char> text = stored(stdlib::concat_of(in[0], in[1]), capacity);
        for (std::size_t i = 2; i < in.size(); ++i) {
            text = stored(stdlib::concat_of<Char>(text, in[i]), capacity);
        }
        return text;
    }
    if (name == "LEFT") {
        return stored(stdlib::left_of(in[0], numbers[0]), capacity);
    }
    if (name == "RIGHT") {
        return stored(stdlib::right_of(in[0], numbers[0]), capacity);
    }
    if (name == "MID") {
        return stored(stdlib::mid_of(in[0], numbers[0], numbers[1]), capacity);
    }
    if (name == "INSERT") {
        return stored(stdlib::insert_of(in[0], in[1], numbers[0]), capacity);
    }
    if (name == "DELETE") {
        return stored(stdlib::replace_of(in[0], {}, numbers[0], numbers[1]), capacity);
    }
    if (name == "REPLACE") {
        return stored(stdlib::replace_of(in[0], in[1], numbers[0], numbers[1]), capacity);
    }
    return std::nullopt;
}

} // namespace

std::optional<Constant> ConstantFolder::text_function(std::string_view name,
                                                      const std::vector<Constant>& values,
                                                      const sema::Type& result) const {
    const stdlib::StandardFunction* function = stdlib::find_standard_function(name);
    if (function == nullptr || function->family != stdlib::Family::Text) {
        return std::nullopt;
    }
    // The texts, then the lengths and positions (all texts for CONCAT).
    const std::size_t texts =
        function->max_inputs == stdlib::kExtensible ? values.size() : function->texts;
    // The manifest's counts: the typing stage took the call as one of them.
    if (values.size() < std::max<std::size_t>(texts, function->min_inputs) ||
        values.size() > function->max_inputs || texts == 0) {
        return std::nullopt;
    }
    std::vector<std::int32_t> numbers;
    for (std::size_t i = texts; i < values.size(); ++i) {
        const auto number = dint_argument(values[i]);
        if (!number) {
            return std::nullopt;
        }
        numbers.push_back(*number);
    }
    const auto folded = std::holds_alternative<std::u16string>(values[0])
                            ? fold<char16_t>(name, values, texts, numbers, result)
                            : fold<char>(name, values, texts, numbers, result);
    if (!folded || function->text_result != stdlib::TextResult::Count) {
        return folded;
    }
    // LEN and FIND are INT: the native's DINT cut to INT (codegen's native_result).
    return convert(*folded, types_.elementary(ast::ElementaryType::Dint), result);
}

} // namespace eposp::compiler::types
