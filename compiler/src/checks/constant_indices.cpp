// E0409: an array index known when compiling lies inside the array's bounds; code generation
// then needs no run-time check for it.

#include "../types/constant_folder.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

void check_index(const PouUnderCheck& check, const ast::IndexExpression& node) {
    const sema::Type* type = check.program.type_of(*node.array);
    if (type == nullptr || type->kind != sema::TypeKind::Array || type->conformant ||
        node.indices.size() != type->dimensions.size()) {
        return; // not an array of fixed bounds, or an error of the typing stage
    }
    // Up to the first index that is not constant, as code generation folds them.
    for (std::size_t d = 0; d < node.indices.size(); ++d) {
        const auto folded = check.program.constants().fold_integer(*node.indices[d]);
        if (!folded) {
            return;
        }
        const sema::ArrayDimension& dimension = type->dimensions[d];
        if (*folded < dimension.lower ||
            *folded >= dimension.lower + static_cast<std::int64_t>(dimension.count)) {
            check.diagnostics.error(DiagnosticCode::E0409, node.indices[d]->range,
                                    fmt::format("index {} is outside {}", *folded, type->name));
            return;
        }
    }
}

} // namespace

void check_constant_indices(const PouUnderCheck& check) {
    for (const ast::Expression* expression : check.body.expressions()) {
        if (const auto* node = std::get_if<ast::IndexExpression>(&expression->node)) {
            check_index(check, *node);
        }
    }
}

} // namespace eposp::compiler::checks
