// W0406: a string literal longer than the STRING[n] or WSTRING[n] it is stored into loses its
// end; the program runs with the cut string, which is rarely what was meant.

#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {

void check_string_cuts(const ProgramUnderCheck& check) {
    for (const types::Store& store : check.program.stores()) {
        const auto* literal = std::get_if<ast::LiteralExpression>(&store.value->node);
        const auto* text =
            literal != nullptr ? std::get_if<ast::StringLiteral>(&literal->value) : nullptr;
        const sema::Type& target = *store.into;
        if (!check.includes(store.pou) || text == nullptr ||
            target.kind != sema::TypeKind::String) {
            continue;
        }
        const auto* narrow = std::get_if<std::string>(&text->value);
        if (target.wide != (narrow == nullptr)) {
            continue; // a type mismatch, reported as such
        }
        const std::size_t length =
            narrow != nullptr ? narrow->size() : std::get<std::u16string>(text->value).size();
        if (length > target.capacity) {
            check.diagnostics.warning(DiagnosticCode::W0406, store.value->range,
                                      fmt::format("this string of {} characters is cut to the {} "
                                                  "of {}",
                                                  length, target.capacity, target.name));
        }
    }
}

} // namespace eposp::compiler::checks
