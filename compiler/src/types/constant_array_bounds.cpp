// The constants of LOWER_BOUND and UPPER_BOUND (6.5.3) of an array whose bounds its type fixes:
// the DINTs code generation writes for them (pou_conformant_arrays.cpp). The bounds of an
// ARRAY[*] parameter come with each call: no constant.

#include "constant_folder.hpp"

namespace eposp::compiler::types {

std::optional<Constant> ConstantFolder::bound_value(const ast::CallExpression& node,
                                                    bool upper) const {
    if (node.arguments.size() != 2) {
        return std::nullopt;
    }
    const sema::Type* array = program_.type_of(*node.arguments[0].value);
    const auto dimension = fold_integer(*node.arguments[1].value);
    if (array == nullptr || array->kind != sema::TypeKind::Array || array->conformant ||
        !dimension || *dimension < 1 ||
        *dimension > static_cast<std::int64_t>(array->dimensions.size())) {
        return std::nullopt;
    }
    const sema::ArrayDimension& bounds =
        array->dimensions[static_cast<std::size_t>(*dimension - 1)];
    const std::int64_t bound = upper ? bounds.lower + bounds.count - 1 : bounds.lower;
    return static_cast<std::int64_t>(static_cast<std::int32_t>(bound));
}

} // namespace eposp::compiler::types
