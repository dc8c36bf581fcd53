// Variable-length arrays (IEC 61131-3 ed. 3, 6.5.3): a VAR_IN_OUT ARRAY[*] takes an array of any
// bounds. It is passed by a reference that carries the bounds along (sema::conformant_reference:
// the address, then lower bound and count per dimension), so an element access checks each index
// against the actual bounds with IdxDim. Arrays of fixed bounds are untouched by this.

#include "eposp/vm/verifier.hpp"
#include "pou_generator.hpp"

#include <fmt/format.h>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;

namespace {

/// Where the lower bound and count of dimension `d` (0-based) of an ARRAY[*] are.
Operand dimension_bounds(const Place& array, std::size_t d) {
    return shifted(array.operand,
                   sema::kConformantBoundsOffset +
                       sema::kConformantDimensionSize * static_cast<std::uint32_t>(d));
}

} // namespace

std::optional<Value> PouGenerator::in_out_argument(const Place& target, const sema::Field& field) {
    const sema::Type& formal = *field.type->element;
    if (!field.type->conformant) {
        if (!sema::same_type(*target.type, formal)) {
            program_.refused_by_checks(DiagnosticCode::E0302); // types/call_typing.cpp
            return std::nullopt;
        }
        return Value{address_of(target), field.type};
    }
    if (!sema::conforms(*target.type, formal)) {
        program_.refused_by_checks(DiagnosticCode::E0302); // types/call_typing.cpp
        return std::nullopt;
    }
    if (target.type->conformant) {
        return Value{target.operand, field.type}; // passed on with the bounds it came with
    }
    const Operand reference = temp(*field.type);
    emit(Opcode::Mov64, reference, address_of(target));
    std::vector<std::uint8_t> bounds;
    for (const sema::ArrayDimension& dimension : target.type->dimensions) {
        for (const std::int64_t value : {dimension.lower, std::int64_t{dimension.count}}) {
            const auto bytes = integer_bytes(value, 4);
            bounds.insert(bounds.end(), bytes.begin(), bytes.end());
        }
    }
    emit(Opcode::MovN, shifted(reference, sema::kConformantBoundsOffset),
         program_.constant(bounds, 4), Operand::imm(static_cast<std::uint32_t>(bounds.size())));
    return Value{reference, field.type};
}

std::optional<Place> PouGenerator::conformant_element(const Place& array,
                                                      const ast::IndexExpression& node) {
    const sema::Type& element = *array.type->element;
    const sema::Type& dint = types_.elementary(ast::ElementaryType::Dint);
    Operand linear{};
    for (std::size_t d = 0; d < node.indices.size(); ++d) {
        const Operand bounds = dimension_bounds(array, d);
        // The bounds are known only when running: any lower bound may be negative.
        const auto index = index_value(*node.indices[d], true, [&] {
            const sema::Type& lint = types_.elementary(ast::ElementaryType::Lint);
            const Operand lower = temp(lint);
            const Operand count = temp(lint);
            emit(Opcode::CvtI32I64, lower, bounds);
            emit(Opcode::CvtU32I64, count, shifted(bounds, 4));
            return std::pair(lower, count);
        });
        if (!index) {
            return std::nullopt;
        }
        const Operand term = temp(dint);
        emit(Opcode::IdxDim, term, bounds, index->operand);
        if (d == 0) {
            linear = term;
        } else {
            emit(Opcode::Mul32, linear, linear, shifted(bounds, 4));
            emit(Opcode::Add32, linear, linear, term);
        }
    }
    // IdxDim has checked every index; IdxAP adds the NULL check and the address arithmetic, with
    // a descriptor that admits any element of the largest array there can be.
    const std::uint16_t descriptor =
        array_descriptor({.count = vm::kMaxAreaSize / element.size, .element_size = element.size});
    const Operand pointer = temp(types_.reference(&element));
    emit(Opcode::IdxAP, pointer, array.operand, linear, descriptor);
    return Place{.kind = Place::Kind::Indirect,
                 .type = &element,
                 .operand = pointer,
                 .writable = array.writable};
}

std::optional<Value> PouGenerator::array_bound(const std::string& name,
                                               const ast::CallExpression& node,
                                               const Destination* dest) {
    if (node.arguments.size() != 2) {
        program_.refused_by_checks(DiagnosticCode::E0306); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    const auto array = place(*node.arguments[0].value);
    if (!array) {
        return std::nullopt;
    }
    const sema::Type& type = *array->type;
    if (type.kind != sema::TypeKind::Array) {
        program_.refused_by_checks(DiagnosticCode::E0305); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    const auto dimension = program_.typed().constants().fold_integer(*node.arguments[1].value);
    if (!dimension || *dimension < 1 ||
        *dimension > static_cast<std::int64_t>(type.dimensions.size())) {
        program_.refused_by_checks(DiagnosticCode::E0313); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    const auto d = static_cast<std::size_t>(*dimension - 1);
    const bool upper = name == "UPPER_BOUND";
    const sema::Type& dint = types_.elementary(ast::ElementaryType::Dint);
    if (!type.conformant) {
        const sema::ArrayDimension& bounds = type.dimensions[d];
        return Value{integer_constant(dint, upper ? bounds.lower + bounds.count - 1 : bounds.lower),
                     &dint};
    }
    const Operand bounds = dimension_bounds(*array, d);
    if (!upper) {
        return Value{bounds, &dint};
    }
    const Operand result = result_operand(dint, dest);
    emit(Opcode::Add32, result, bounds, shifted(bounds, 4));
    emit(Opcode::AddI32, result, result, Operand::imm(static_cast<std::uint32_t>(-1)));
    return Value{result, &dint};
}

} // namespace eposp::compiler::codegen
