// W0406: a constant text longer than the STRING[n] or WSTRING[n] it is stored into loses its end
// (a literal, or a text the typing stage folded: a CONSTANT's, a string function's); the
// program runs with the cut string, which is rarely what was meant.

#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {

namespace {

/// The length of the constant text `value` is, if it is one of the kind `target` holds (a type
/// mismatch is reported as such).
std::optional<std::size_t> text_length(const ast::Expression& value, const sema::Type& target,
                                       const types::TypedProgram& program) {
    const types::Constant* constant = program.constant_of(value);
    if (const auto* narrow = constant != nullptr ? std::get_if<std::string>(constant) : nullptr) {
        return target.wide ? std::nullopt : std::optional(narrow->size());
    }
    const auto* wide = constant != nullptr ? std::get_if<std::u16string>(constant) : nullptr;
    return wide != nullptr && target.wide ? std::optional(wide->size()) : std::nullopt;
}

} // namespace

void check_string_cuts(const ProgramUnderCheck& check) {
    for (const types::Store& store : check.program.stores()) {
        const sema::Type& target = *store.into;
        if (!check.includes(store.pou) || target.kind != sema::TypeKind::String) {
            continue;
        }
        const auto length = text_length(*store.value, target, check.program);
        if (length && *length > target.capacity) {
            check.diagnostics.warning(DiagnosticCode::W0406, store.value->range,
                                      fmt::format("this string of {} characters is cut to the {} "
                                                  "of {}",
                                                  *length, target.capacity, target.name));
        }
    }
}

} // namespace eposp::compiler::checks
