// Initial values written as the image holds them (ed. 3, 6.5.1.3, 6.4.2): the constants the
// typing stage folded (constant_value.cpp, constant_operations.cpp).

#include "initial_constant.hpp"

#include "eposp/vm/stdlib/string_layout.hpp"

#include <cstring>
#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

template <typename T>
std::vector<std::uint8_t> bytes_of(T value) {
    std::vector<std::uint8_t> bytes(sizeof(T));
    std::memcpy(bytes.data(), &value, sizeof(T));
    return bytes;
}

} // namespace

std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size) {
    std::vector<std::uint8_t> bytes(size);
    const auto raw = static_cast<std::uint64_t>(value);
    for (std::uint32_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

std::variant<std::vector<std::uint8_t>, ConstantRefusal>
constant_bytes(const ast::Expression& expression, const sema::Type& type,
               const TypedProgram& program) {
    const ConstantFolder& constants = program.constants();
    const ConstantRefusal not_constant{
        DiagnosticCode::E0313, fmt::format("the initial value must be a constant {}", type.name)};
    const auto or_refused = [&](std::optional<std::vector<std::uint8_t>> bytes)
        -> std::variant<std::vector<std::uint8_t>, ConstantRefusal> {
        if (bytes) {
            return std::move(*bytes);
        }
        return not_constant;
    };
    if (type.kind == sema::TypeKind::String) {
        // The text the typing stage folded (a literal's, a CONSTANT's, a string function's),
        // cut at the capacity.
        const auto text = constants.typed_as(expression, type);
        const auto* narrow = text ? std::get_if<std::string>(&*text) : nullptr;
        const auto* wide = text ? std::get_if<std::u16string>(&*text) : nullptr;
        return or_refused(
            narrow != nullptr ? std::optional(vm::stdlib::string_image(type.capacity, *narrow))
            : wide != nullptr ? std::optional(vm::stdlib::wstring_image(type.capacity, *wide))
                              : std::nullopt);
    }
    if (type.kind == sema::TypeKind::Reference) {
        const ast::Literal* literal = constants.literal(expression);
        return or_refused(literal != nullptr && std::holds_alternative<ast::NullLiteral>(*literal)
                              ? std::optional(std::vector<std::uint8_t>(8, 0))
                              : std::nullopt);
    }
    const auto value = sema::is_scalar(type) ? constants.typed_as(expression, type) : std::nullopt;
    if (!value) {
        return not_constant;
    }
    // An integer is refused where it is not the number the expression means: out of the
    // type's range (`x : SINT := 100 + 100`), or wrapped on the way (`32767 + 1` in INT).
    if ((sema::is_integer(type) || sema::is_bit_string(type)) &&
        type.kind != sema::TypeKind::Enum &&
        (!constants.typed_fits(expression, type) || program.wraps(expression))) {
        return ConstantRefusal{DiagnosticCode::E0311,
                               fmt::format("the value does not fit in {}", type.name)};
    }
    return std::visit(
        [&](const auto& v) -> std::variant<std::vector<std::uint8_t>, ConstantRefusal> {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, bool>) {
                return integer_bytes(v ? 1 : 0, type.size);
            } else if constexpr (std::is_same_v<V, double>) {
                return type.size == 4 ? bytes_of(static_cast<float>(v)) : bytes_of(v);
            } else if constexpr (std::is_same_v<V, std::string> ||
                                 std::is_same_v<V, std::u16string>) {
                return not_constant;
            } else {
                return integer_bytes(static_cast<std::int64_t>(v), type.size);
            }
        },
        *value);
}

} // namespace eposp::compiler::types
