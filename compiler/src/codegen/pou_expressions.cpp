// Expressions of IEC 61131-3 ed. 3, 7.3.2 (table 71): variables, literals, operators.

#include "../types/expression_typer.hpp"
#include "constant_declarations.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

#include <algorithm>

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;
using vm::Opcode;
using vm::Operand;

namespace {

/// Whether `expression` holds a call that `counts` (a predicate on the call node); the
/// arguments of a call that does not count are looked into.
template <typename Counts>
bool has_call(const ast::Expression& expression, const Counts& counts) {
    const auto any = [&](const ast::Expression& inner) {
        return has_call(inner, counts);
    };
    return std::visit(
        [&](const auto& node) -> bool {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::CallExpression>) {
                return counts(node) ||
                       std::any_of(node.arguments.begin(), node.arguments.end(),
                                   [&](const ast::Argument& a) { return any(*a.value); });
            } else if constexpr (std::is_same_v<T, ast::MemberExpression> ||
                                 std::is_same_v<T, ast::BitAccessExpression>) {
                return any(*node.object);
            } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                return any(*node.array) ||
                       std::any_of(node.indices.begin(), node.indices.end(),
                                   [&](const auto& index) { return any(*index); });
            } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                return any(*node.reference);
            } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                return any(*node.target);
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                return any(*node.operand);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                return any(*node.left) || any(*node.right);
            } else {
                return false;
            }
        },
        expression.node);
}

} // namespace

bool PouGenerator::contains_call(const ast::Expression& expression) {
    return has_call(expression, [](const ast::CallExpression&) { return true; });
}

bool PouGenerator::may_write_variables(const ast::Expression& expression) const {
    return has_call(expression, [this](const ast::CallExpression& call) {
        const auto* name = std::get_if<ast::NameExpression>(&call.callee->node);
        const sema::Symbol* symbol = name != nullptr ? model_.resolved(name->name) : nullptr;
        return symbol == nullptr || symbol->kind != sema::SymbolKind::StandardFunction;
    });
}

bool PouGenerator::names_program(const ast::Expression& expression) const {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    const sema::Symbol* symbol = name != nullptr ? model_.resolved(name->name) : nullptr;
    return symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
           symbol->pou->kind == ast::PouKind::Program;
}

Operand PouGenerator::result_operand(const sema::Type& type, const Destination* dest) {
    return dest != nullptr && dest->type == &type ? dest->operand : temp(type);
}

// --- Places ----------------------------------------------------------------------------------

std::optional<Place> PouGenerator::place(const ast::Expression& expression) {
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = model_.resolved(name->name);
        if (symbol == nullptr) {
            return std::nullopt; // reported by the resolver
        }
        return variable(*symbol);
    }
    if (const auto* node = std::get_if<ast::MemberExpression>(&expression.node)) {
        auto object = place(*node->object);
        if (!object) {
            return std::nullopt;
        }
        const sema::Type& type = *object->type;
        const sema::Field* field =
            type.kind == sema::TypeKind::Struct || type.kind == sema::TypeKind::Instance
                ? type.field(node->member.name)
                : nullptr;
        if (field == nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0206); // types/operand_typing.cpp
            return std::nullopt;
        }
        // A PROGRAM reached by its name shows all its variables (CODESYS); VAR CONSTANT are
        // read only.
        if (names_program(*node->object)) {
            if (field->section == ast::VarSectionKind::InOut ||
                field->section == ast::VarSectionKind::Temp || field->declaration == nullptr) {
                program_.refused_by_checks(DiagnosticCode::E0212); // types/operand_typing.cpp
                return std::nullopt;
            }
            Place result = member(*object, field->offset, *field->type);
            result.writable = !is_constant(*type.pou, field->declaration);
            return result;
        }
        if (type.kind == sema::TypeKind::Instance &&
            (field->section == ast::VarSectionKind::Var ||
             field->section == ast::VarSectionKind::InOut)) {
            // 6.5.2.2: only inputs and outputs of an instance are visible outside it.
            program_.refused_by_checks(DiagnosticCode::E0212); // types/operand_typing.cpp
            return std::nullopt;
        }
        Place result = member(*object, field->offset, *field->type);
        if (type.kind == sema::TypeKind::Instance &&
            field->section == ast::VarSectionKind::Output) {
            result.writable = false;
        }
        return result;
    }
    if (const auto* node = std::get_if<ast::IndexExpression>(&expression.node)) {
        return index(*node);
    }
    if (const auto* node = std::get_if<ast::DirectAddressExpression>(&expression.node)) {
        return program_.direct_variable(node->address);
    }
    if (const auto* node = std::get_if<ast::DereferenceExpression>(&expression.node)) {
        const auto pointer = eval(*node->reference, nullptr);
        if (!pointer) {
            return std::nullopt;
        }
        if (pointer->type->kind != sema::TypeKind::Reference || pointer->type->element == nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0304); // types/expression_typer.cpp
            return std::nullopt;
        }
        return Place{.kind = Place::Kind::Indirect,
                     .type = pointer->type->element,
                     .operand = pointer->operand};
    }
    program_.refused_by_checks(
        DiagnosticCode::E0315); // types/statement_typing.cpp, call_typing.cpp
    return std::nullopt;
}

Operand PouGenerator::dint_operand(const Value& value) {
    const sema::Type& dint = types_.elementary(E::Dint);
    if (value.type == &dint) {
        return value.operand;
    }
    const vm::Opcode convert = program_.opcodes().get(
        "Cvt", std::string(type_suffix(sema::scalar_of(*value.type))) + "I32");
    const ValueCache::Key key{ValueCache::Kind::Convert, value.operand.raw,
                              static_cast<std::uint32_t>(convert), 0};
    if (const auto hit = cache_.find(key)) {
        return *hit;
    }
    const Operand converted = temp(dint);
    emit(convert, converted, value.operand);
    cache_.add(key, converted, 4, {{value.operand, value.type->size}});
    return converted;
}

std::optional<PouGenerator::ElementIndex>
PouGenerator::displaced_index(const ast::Expression& index, std::int64_t lower) {
    const auto* sum = std::get_if<ast::BinaryExpression>(&index.node);
    if (sum == nullptr ||
        (sum->op != ast::BinaryOperator::Add && sum->op != ast::BinaryOperator::Subtract)) {
        return std::nullopt;
    }
    const bool add = sum->op == ast::BinaryOperator::Add;
    auto constant = small_literal(*sum->right);
    const ast::Expression* variable = sum->left.get();
    if (!constant && add) {
        constant = small_literal(*sum->left);
        variable = sum->right.get();
    }
    const auto* name = std::get_if<ast::NameExpression>(&variable->node);
    const sema::Symbol* symbol = name ? model_.resolved(name->name) : nullptr;
    if (!constant || symbol == nullptr || symbol->kind != sema::SymbolKind::Variable) {
        return std::nullopt;
    }
    const auto where = place(*variable);
    if (!where || where->kind != Place::Kind::Direct ||
        where->type != &types_.elementary(E::Dint)) {
        return std::nullopt;
    }
    // The bound moves by the constant modulo 2^32, as the wrapping DINT sum would.
    const std::int64_t moved = lower - (add ? std::int64_t{*constant} : -std::int64_t{*constant});
    return ElementIndex{where->operand,
                        static_cast<std::int32_t>(static_cast<std::uint32_t>(moved)), 4};
}

std::optional<PouGenerator::ElementIndex>
PouGenerator::element_index(const ast::Expression& index, std::int64_t lower, std::uint32_t count) {
    if (auto displaced = displaced_index(index, lower)) {
        return displaced;
    }
    const auto value = integer_index(index);
    if (!value) {
        return std::nullopt;
    }
    const auto bound = static_cast<std::int32_t>(lower);
    if (wide_index(*value->type, lower < 0)) {
        const sema::Type& lint = types_.elementary(E::Lint);
        return ElementIndex{
            dint_index(*value, integer_constant(lint, lower), integer_constant(lint, count)), bound,
            4};
    }
    // An INT indexes as it is; a UDINT has the DINT's bits, so the modular check is the same
    // where no index is negative.
    if (value->type->kind != sema::TypeKind::Enum) {
        switch (sema::scalar_of(*value->type)) {
        case vm::Scalar::I16:
            return ElementIndex{value->operand, bound, 2};
        case vm::Scalar::I32:
        case vm::Scalar::U32:
            return ElementIndex{value->operand, bound, 4};
        default:
            break;
        }
    }
    return ElementIndex{dint_operand(*value), bound, 4};
}

std::optional<Place> PouGenerator::index(const ast::IndexExpression& node) {
    auto array = place(*node.array);
    if (!array) {
        return std::nullopt;
    }
    const sema::Type& type = *array->type;
    if (type.kind != sema::TypeKind::Array) {
        program_.refused_by_checks(DiagnosticCode::E0308); // types/operand_typing.cpp
        return std::nullopt;
    }
    if (node.indices.size() != type.dimensions.size()) {
        program_.refused_by_checks(DiagnosticCode::E0308); // types/operand_typing.cpp
        return std::nullopt;
    }
    if (type.conformant) {
        return conformant_element(*array, node);
    }
    const sema::Type& element = *type.element;
    const sema::Type& dint = types_.elementary(E::Dint);
    // Constant indices cost nothing at run time; the checks stage refused those outside the
    // bounds (E0409), which would otherwise be checked at run time like any other.
    std::int64_t constant = 0;
    bool all_constant = true;
    for (std::size_t d = 0; d < node.indices.size(); ++d) {
        const auto folded = program_.typed().constants().fold_integer(*node.indices[d]);
        const auto& dimension = type.dimensions[d];
        if (!folded || *folded < dimension.lower ||
            *folded >= dimension.lower + static_cast<std::int64_t>(dimension.count)) {
            all_constant = false;
            break;
        }
        constant = constant * dimension.count + (*folded - dimension.lower);
    }
    if (all_constant) {
        return member(*array, static_cast<std::uint32_t>(constant) * element.size, element);
    }
    std::uint32_t count = 1;
    for (const auto& dimension : type.dimensions) {
        count *= dimension.count;
    }
    const bool one = type.dimensions.size() == 1;
    std::optional<ElementIndex> single;
    if (one) {
        single =
            element_index(*node.indices[0], type.dimensions[0].lower, type.dimensions[0].count);
        if (!single) {
            return std::nullopt;
        }
    }
    // More dimensions: the linear index, sum of (i_d - lower_d) * stride_d, as a DINT. Each
    // index is checked against its own dimension (IdxDim with constant bounds): m[0, 5] of an
    // ARRAY[0..2, 0..2] is out of range, not m[1, 2].
    Operand linear = one ? single->operand : Operand{};
    for (std::size_t d = 0; !one && d < node.indices.size(); ++d) {
        const auto& dimension = type.dimensions[d];
        const auto value = index_value(*node.indices[d], dimension.lower < 0, [&] {
            const sema::Type& lint = types_.elementary(E::Lint);
            return std::pair(integer_constant(lint, dimension.lower),
                             integer_constant(lint, dimension.count));
        });
        if (!value) {
            return std::nullopt;
        }
        const Operand term = temp(dint);
        emit(Opcode::IdxDim, term, dimension_constant(dimension.lower, dimension.count),
             value->operand);
        if (d == 0) {
            linear = term;
        } else {
            emit(Opcode::Mul32, linear, linear, integer_constant(dint, dimension.count));
            emit(Opcode::Add32, linear, linear, term);
        }
    }
    const std::uint16_t descriptor =
        one ? array_descriptor({.lower = single->lower,
                                .count = count,
                                .element_size = element.size,
                                .index_size = single->size})
            : array_descriptor({.count = count, .element_size = element.size});
    if (array->kind == Place::Kind::Direct) {
        return Place{.kind = Place::Kind::Element,
                     .type = &element,
                     .operand = array->operand,
                     .index = linear,
                     .array = descriptor,
                     .writable = array->writable};
    }
    const Operand pointer = temp(types_.reference(&element));
    emit(Opcode::IdxAP, pointer, address_of(*array), linear, descriptor);
    return Place{.kind = Place::Kind::Indirect,
                 .type = &element,
                 .operand = pointer,
                 .writable = array->writable};
}

std::optional<Value> PouGenerator::integer_index(const ast::Expression& expression) {
    const auto value = eval(expression, &types_.elementary(E::Dint));
    if (value && !sema::is_integer(*value->type) && value->type->kind != sema::TypeKind::Enum) {
        program_.refused_by_checks(DiagnosticCode::E0307); // types/operand_typing.cpp
        return std::nullopt;
    }
    return value;
}

std::optional<Value>
PouGenerator::index_value(const ast::Expression& expression, bool negative_lower,
                          const std::function<std::pair<Operand, Operand>()>& bounds) {
    const auto value = integer_index(expression);
    if (!value) {
        return std::nullopt;
    }
    if (wide_index(*value->type, negative_lower)) {
        const auto [lower, count] = bounds();
        return Value{dint_index(*value, lower, count), &types_.elementary(E::Dint)};
    }
    return Value{dint_operand(*value), &types_.elementary(E::Dint)};
}

std::optional<Value> PouGenerator::bit_word(const ast::BitAccessExpression& node) {
    const auto word = eval(*node.object, nullptr);
    if (!word) {
        return std::nullopt;
    }
    if (!sema::is_bit_string(*word->type) && !sema::is_integer(*word->type)) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/expression_typer.cpp
        return std::nullopt;
    }
    if (node.bit >= word->type->size * 8) {
        program_.refused_by_checks(DiagnosticCode::E0105); // types/expression_typer.cpp
        return std::nullopt;
    }
    return word;
}

Operand PouGenerator::bit_mask(const sema::Type& type, std::uint32_t bit, bool inverted) {
    const std::uint64_t mask = std::uint64_t{1} << bit;
    return integer_constant(type, static_cast<std::int64_t>(inverted ? ~mask : mask));
}

// --- Values ----------------------------------------------------------------------------------

std::optional<Value> PouGenerator::eval(const ast::Expression& expression, const sema::Type* hint,
                                        const Destination* dest) {
    auto value = evaluate(expression, hint, dest);
    if (!value) {
        return value;
    }
    // Types are the typing stage's: code generation takes them from it and derives none (a
    // literal too: typing gives it its context's type, literal()). A subrange's value is of its
    // base type, and a value made straight in its destination (that operand) has the
    // destination's type: a STRING result written into the variable it is stored in has that
    // variable's capacity, which code generation chooses, where typing gives the expression
    // its own (CONCAT's, TO_STRING's) wherever it is used.
    const sema::Type* typed = program_.typed().type_of(expression);
    const bool same = typed != nullptr && value_type(*value->type) == value_type(*typed);
    const bool in_destination =
        dest != nullptr && value->type == dest->type && value->operand.raw == dest->operand.raw;
    if (!same && !in_destination) {
        program_.disagrees_with_typing(expression.range, *value->type, typed);
        return std::nullopt;
    }
    return value;
}

const sema::Type* PouGenerator::value_type(const sema::Type& type) {
    const sema::Type& declared = type.renames != nullptr ? *type.renames : type;
    return declared.range ? &types_.unranged(declared) : &declared;
}

std::optional<Value> PouGenerator::evaluate(const ast::Expression& expression,
                                            const sema::Type* hint, const Destination* dest) {
    if (std::holds_alternative<ast::LiteralExpression>(expression.node)) {
        return literal(expression);
    }
    if (const sema::Symbol* symbol = model_.enum_value(expression)) {
        const sema::Type* type = types_.enumeration_of(*symbol);
        const auto value = types_.enumerator(*symbol);
        if (type == nullptr || !value) {
            return std::nullopt;
        }
        return Value{integer_constant(*type, *value), type};
    }
    if (const auto* node = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = model_.resolved(node->name);
        if (symbol == nullptr) {
            return std::nullopt;
        }
        if (symbol->kind != sema::SymbolKind::Variable &&
            !(symbol->kind == sema::SymbolKind::Pou && symbol->pou == &pou_)) {
            program_.refused_by_checks(DiagnosticCode::E0204); // types/operand_typing.cpp
            return std::nullopt;
        }
    }
    if (std::holds_alternative<ast::NameExpression>(expression.node) ||
        std::holds_alternative<ast::DirectAddressExpression>(expression.node) ||
        std::holds_alternative<ast::MemberExpression>(expression.node) ||
        std::holds_alternative<ast::IndexExpression>(expression.node) ||
        std::holds_alternative<ast::DereferenceExpression>(expression.node)) {
        const auto where = place(expression);
        return where ? std::optional(load(*where, dest)) : std::nullopt;
    }
    if (const auto* node = std::get_if<ast::ReferenceExpression>(&expression.node)) {
        const auto target = place(*node->target);
        if (!target) {
            return std::nullopt;
        }
        return Value{address_of(*target), &types_.reference(target->type)};
    }
    if (std::holds_alternative<ast::CallExpression>(expression.node)) {
        return function_value(call(expression, hint, dest));
    }
    if (std::holds_alternative<ast::UnaryExpression>(expression.node) ||
        std::holds_alternative<ast::BinaryExpression>(expression.node)) {
        auto value = operand_value(expression, hint, dest);
        if (value && value->iec != nullptr) {
            // Computed wider than its type (see binary): cut to the type here.
            const sema::Type& type = *value->iec;
            value->iec = nullptr;
            value = convert(*value, type, dest);
        }
        return value;
    }
    if (const auto* node = std::get_if<ast::BitAccessExpression>(&expression.node)) {
        const auto word = bit_word(*node);
        if (!word) {
            return std::nullopt;
        }
        // 6.5.1.2 partial access: the bit is `(word AND 2#1 << n) <> 0`.
        const sema::Type& type = *word->type;
        const Operand masked = temp(type);
        emit(op_width("And", type), masked, word->operand, bit_mask(type, node->bit, false));
        const sema::Type& boolean = types_.elementary(E::Bool);
        const Operand result = result_operand(boolean, dest);
        emit(
            program_.opcodes().get("Cvt", std::string(type_suffix(sema::scalar_of(type))) + "Bool"),
            result, masked);
        return Value{result, &boolean};
    }
    program_.refused_by_checks(DiagnosticCode::E0504); // every kind of expression is above
    return std::nullopt;
}

std::optional<Value> PouGenerator::literal(const ast::Expression& expression) {
    // The typing stage's type, its context's for an untyped number, a text or NULL: an integer
    // as the operation that takes it computes, a text at the capacity of the STRING it goes to
    // (one copy to store it), NULL as the reference it goes to.
    const sema::Type* type = program_.typed().type_of(expression);
    if (type == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0311); // types/operand_typing.cpp
        return std::nullopt;
    }
    auto bytes = program_.constant_value(expression, *type);
    if (!bytes) {
        // constant_value() reported it (types/operand_typing.cpp refuses such literals)
        return std::nullopt;
    }
    return Value{program_.constant(*bytes, std::max<std::uint32_t>(type->align, 1)), type};
}

std::optional<Value> PouGenerator::convert(const Value& value, const sema::Type& want,
                                           const Destination* dest) {
    if (value.type == &want || !sema::is_scalar(want) || !sema::is_scalar(*value.type)) {
        return value; // strings keep their own capacity: they are assigned by their header
    }
    const vm::Scalar from = sema::scalar_of(*value.type);
    const vm::Scalar to = sema::scalar_of(want);
    if (from == to || (from == vm::Scalar::Ptr && to == vm::Scalar::Ptr)) {
        return Value{value.operand, &want};
    }
    const Operand result = result_operand(want, dest);
    emit(program_.opcodes().get("Cvt",
                                std::string(type_suffix(from)) + std::string(type_suffix(to))),
         result, value.operand);
    return Value{result, &want};
}

std::optional<Value> PouGenerator::function_value(const std::optional<Value>& called) {
    if (called && called->type == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0309); // types/expression_typer.cpp
        return std::nullopt;
    }
    return called;
}

std::optional<Value> PouGenerator::value_as(const ast::Expression& expression,
                                            const sema::Type& want, const Destination* dest) {
    if (want.range) {
        return subrange_value(expression, want);
    }
    const auto value = eval(expression, &want, dest);
    return value ? value_as(*value, want, dest) : std::nullopt;
}

std::optional<Value> PouGenerator::value_as(const Value& value, const sema::Type& want,
                                            const Destination* dest) {
    if (!sema::converts_implicitly(*value.type, want)) {
        program_.refused_by_checks(DiagnosticCode::E0301); // types/expression_typer.cpp
        return std::nullopt;
    }
    if (want.range) {
        return checked(value, want);
    }
    return convert(value, want, dest);
}

std::optional<std::int32_t> PouGenerator::small_literal(const ast::Expression& expression) {
    if (!types::is_context_literal(expression)) {
        return std::nullopt;
    }
    const auto value = program_.typed().constants().fold_integer(expression);
    if (!value || *value < INT32_MIN || *value > INT32_MAX) {
        return std::nullopt;
    }
    return static_cast<std::int32_t>(*value);
}

std::optional<std::pair<Value, Value>> PouGenerator::operands(const ast::Expression& left,
                                                              const ast::Expression& right,
                                                              const sema::Type& type) {
    // A literal typed by its context (types::is_context_literal) is evaluated after the other
    // side (literals have no side effects).
    std::optional<Value> l;
    std::optional<Value> r;
    if (types::is_context_literal(left) && !types::is_context_literal(right)) {
        r = operand_as(right, type);
        l = r ? operand_as(left, type) : std::nullopt;
    } else {
        l = before(right, [&] { return operand_as(left, type); });
        r = l ? operand_as(right, type) : std::nullopt;
    }
    if (!l || !r) {
        return std::nullopt;
    }
    return std::pair(*l, *r);
}

std::optional<Value> PouGenerator::operand_as(const ast::Expression& expression,
                                              const sema::Type& type) {
    // A literal is laid out as `type` at once, a constant rather than a conversion.
    const auto value = operand_value(expression, &type);
    return value ? convert(*value, type, nullptr) : std::nullopt;
}

std::optional<Value> PouGenerator::unary(const ast::Expression& expression,
                                         const ast::UnaryExpression& node, const sema::Type* hint,
                                         const Destination* dest) {
    if (node.op == ast::UnaryOperator::Plus) {
        return eval(*node.operand, hint, dest);
    }
    if (node.op == ast::UnaryOperator::Negate) {
        // Computed in DINT where the typing stage holds a small integer there (operands_of),
        // and held so, as binary() holds its result, while it feeds another operation.
        const sema::Type* computed = program_.typed().operands_of(expression);
        const sema::Type* typed = program_.typed().type_of(expression);
        const auto value =
            computed != nullptr ? operand_as(*node.operand, *computed) : eval(*node.operand, hint);
        if (!value) {
            return std::nullopt;
        }
        const sema::Type& type = *value->type;
        if (!sema::is_numeric(type) && !(sema::is_time_like(type) && type.elementary <= E::Ltime)) {
            program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
            return std::nullopt;
        }
        const sema::Type* iec = typed != nullptr && typed != &type ? typed : nullptr;
        const Operand result = result_operand(type, iec == nullptr ? dest : nullptr);
        emit(op_width("Neg", type), result, value->operand);
        return Value{result, &type, iec};
    }
    const auto value = eval(*node.operand, hint);
    if (!value) {
        return std::nullopt;
    }
    const sema::Type& type = *value->type;
    const Operand result = result_operand(type, dest);
    if (sema::is_bool(type)) {
        emit(Opcode::NotB, result, value->operand);
    } else if (sema::is_bit_string(type) || sema::is_integer(type)) {
        emit(op_width("Not", type), result, value->operand);
    } else {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    return Value{result, &type};
}

std::optional<Value> PouGenerator::compare(ast::BinaryOperator op, const Value& left,
                                           const Value& right, const Destination* dest) {
    const sema::Type& boolean = types_.elementary(E::Bool);
    const sema::Type& type = *left.type;
    if (type.kind == sema::TypeKind::String) {
        using Operation = vm::stdlib::Operation;
        static constexpr std::pair<ast::BinaryOperator, Operation> kOperations[] = {
            {ast::BinaryOperator::Less, Operation::Less},
            {ast::BinaryOperator::Greater, Operation::Greater},
            {ast::BinaryOperator::LessEqual, Operation::LessEqual},
            {ast::BinaryOperator::GreaterEqual, Operation::GreaterEqual},
            {ast::BinaryOperator::Equal, Operation::Equal},
            {ast::BinaryOperator::NotEqual, Operation::NotEqual}};
        for (const auto& [candidate, operation] : kOperations) {
            if (candidate == op) {
                const auto native =
                    vm::stdlib::text_comparison_binding(operation, sema::char_width(type));
                call_native(native.name, native.signature, {left, right});
                return native_result(native.signature, boolean, dest);
            }
        }
    }
    if (!sema::is_scalar(type)) {
        return std::nullopt;
    }
    const Operand result = result_operand(boolean, dest);
    const bool swap = op == ast::BinaryOperator::Greater || op == ast::BinaryOperator::GreaterEqual;
    const Value& a = swap ? right : left;
    const Value& b = swap ? left : right;
    std::string_view suffix = type_suffix(sema::scalar_of(type));
    if (suffix == "Bool") {
        suffix = "U8";
    }
    switch (op) {
    case ast::BinaryOperator::Equal:
        emit(op_width("Eq", type), result, a.operand, b.operand);
        break;
    case ast::BinaryOperator::NotEqual:
        emit(op_width("Ne", type), result, a.operand, b.operand);
        break;
    case ast::BinaryOperator::Less:
    case ast::BinaryOperator::Greater:
        emit(program_.opcodes().get("Lt", suffix), result, a.operand, b.operand);
        break;
    default:
        emit(program_.opcodes().get("Le", suffix), result, a.operand, b.operand);
        break;
    }
    return Value{result, &boolean};
}

std::optional<Value> PouGenerator::operand_value(const ast::Expression& expression,
                                                 const sema::Type* hint, const Destination* dest) {
    if (const auto* node = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary(expression, *node, hint, dest);
    }
    if (const auto* node = std::get_if<ast::BinaryExpression>(&expression.node)) {
        return binary(expression, *node, hint, dest);
    }
    return eval(expression, hint, dest);
}

Operand PouGenerator::dimension_constant(std::int64_t lower, std::uint32_t count) {
    std::vector<std::uint8_t> bounds = integer_bytes(lower, 4);
    const auto count_bytes = integer_bytes(count, 4);
    bounds.insert(bounds.end(), count_bytes.begin(), count_bytes.end());
    return program_.constant(bounds, 4);
}

Operand PouGenerator::integer_constant(const sema::Type& type, std::int64_t value) {
    return program_.constant(integer_bytes(value, type.size), type.align);
}

std::optional<Value> PouGenerator::binary(const ast::Expression& expression,
                                          const ast::BinaryExpression& node, const sema::Type* hint,
                                          const Destination* dest) {
    using Op = ast::BinaryOperator;
    if (node.op == Op::Power) {
        // `**` is EXPT (table 24): computed in the real type the typing stage gives it, the
        // base's (was always in LREAL, which a REAL base's REAL result did not take).
        const sema::Type* real = program_.typed().type_of(expression);
        if (real == nullptr || !sema::is_real(*real)) {
            program_.refused_by_checks(DiagnosticCode::E0305); // types/operator_typing.cpp
            return std::nullopt;
        }
        const auto base = before(*node.right, [&] { return eval(*node.left, real); });
        const auto exponent = base ? eval(*node.right, real) : std::nullopt;
        if (!exponent) {
            return std::nullopt;
        }
        if (!sema::is_numeric(*base->type) || !sema::is_numeric(*exponent->type)) {
            program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
            return std::nullopt;
        }
        const auto native = vm::stdlib::native_binding(
            "EXPT", sema::scalar_of(*real) == vm::Scalar::F32 ? vm::stdlib::Variant::Base
                                                              : vm::stdlib::Variant::Wide);
        call_native(native.name, native.signature,
                    {*explicit_convert(*base, *real, nullptr),
                     *explicit_convert(*exponent, *real, nullptr)});
        return native_result(native.signature, *real, dest);
    }
    // The typing stage's type both operands are brought to; none for TIME * n (table 30), a
    // pointer moved by bytes and time arithmetic, whose operands keep their types and whose
    // result type is the typing stage's too.
    const sema::Type* computed = program_.typed().operands_of(expression);
    const sema::Type* typed = program_.typed().type_of(expression);
    if (typed == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    if (computed == nullptr) {
        const auto left = before(*node.right, [&] { return operand_value(*node.left, hint); });
        if (!left) {
            return std::nullopt;
        }
        if (node.op == Op::Multiply || node.op == Op::Divide) {
            return scale_time(node.op == Op::Multiply, *left, *node.right, *typed, dest);
        }
        if (typed->kind == sema::TypeKind::Reference) {
            return pointer_offset(node.op == Op::Add, *left, *node.right, dest);
        }
        const auto right = operand_value(*node.right, nullptr);
        return right ? time_arithmetic(node.op, *left, *right, *typed, dest) : std::nullopt;
    }
    const sema::Type& type = *computed;
    const bool comparison = node.op == Op::Less || node.op == Op::Greater ||
                            node.op == Op::LessEqual || node.op == Op::GreaterEqual ||
                            node.op == Op::Equal || node.op == Op::NotEqual;
    // An arithmetic result computed wider than its type is held so (Value::iec) while it
    // feeds another operation; eval() cuts it where it is stored.
    const sema::Type* iec = !comparison && typed != &type ? typed : nullptr;
    const bool bitwise = node.op == Op::And || node.op == Op::Or || node.op == Op::Xor;
    const auto immediate = (node.op == Op::Add || node.op == Op::Subtract) &&
                                   !types::is_context_literal(*node.left) &&
                                   (sema::is_integer(type) || sema::is_bit_string(type))
                               ? small_literal(*node.right)
                               : std::nullopt;
    if (immediate) {
        // A small constant right operand of + and - is the immediate of AddI.
        const auto l = operand_as(*node.left, type);
        if (!l) {
            return std::nullopt;
        }
        // value_or: GCC's -O2 cannot see that `immediate` is set in this branch.
        const std::int64_t constant = immediate.value_or(0);
        if (constant == 0) {
            return Value{l->operand, &type, iec}; // x + 0
        }
        const std::int64_t delta = node.op == Op::Add ? constant : -constant;
        const vm::Opcode add = op_width("AddI", type);
        const ValueCache::Key key{ValueCache::Kind::AddImmediate, l->operand.raw,
                                  static_cast<std::uint32_t>(delta),
                                  static_cast<std::uint32_t>(add)};
        const bool into_dest = dest != nullptr && dest->type == &type && iec == nullptr;
        if (const auto hit = into_dest ? std::nullopt : cache_.find(key)) {
            return Value{*hit, &type, iec}; // `a[j + 1]` after `a[j + 1]`
        }
        const Operand result = result_operand(type, into_dest ? dest : nullptr);
        emit(add, result, l->operand, Operand::imm(static_cast<std::uint32_t>(delta)));
        if (!into_dest) {
            cache_.add(key, result, type.size, {{l->operand, type.size}});
        }
        return Value{result, &type, iec};
    }
    const auto pair = operands(*node.left, *node.right, type);
    if (!pair) {
        return std::nullopt;
    }
    auto result = apply(node.op, pair->first, pair->second, iec == nullptr ? dest : nullptr);
    if (result && iec != nullptr && bitwise) {
        return convert(*result, *typed, dest); // the bits of its type
    }
    if (result && iec != nullptr) {
        result->iec = typed;
    }
    return result;
}

std::optional<Value> PouGenerator::pointer_offset(bool add, const Value& pointer,
                                                  const ast::Expression& bytes,
                                                  const Destination* dest) {
    const sema::Type& lint = types_.elementary(E::Lint);
    const Operand result = result_operand(
        *pointer.type, dest != nullptr && dest->type == pointer.type ? dest : nullptr);
    if (const auto constant = small_literal(bytes)) {
        const std::int32_t delta = add ? *constant : -*constant;
        emit(Opcode::AddI64, result, pointer.operand,
             Operand::imm(static_cast<std::uint32_t>(delta)));
        return Value{result, pointer.type};
    }
    const auto offset = eval(bytes, &lint);
    if (!offset) {
        return std::nullopt;
    }
    if (!sema::is_integer(*offset->type)) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    const auto wide = convert(*offset, lint, nullptr);
    emit(add ? Opcode::Add64 : Opcode::Sub64, result, pointer.operand, wide->operand);
    return Value{result, pointer.type};
}

std::optional<Value> PouGenerator::apply(ast::BinaryOperator oper, const Value& left,
                                         const Value& right, const Destination* dest) {
    using Op = ast::BinaryOperator;
    const sema::Type& type = *left.type;
    if (oper == Op::Less || oper == Op::Greater || oper == Op::LessEqual ||
        oper == Op::GreaterEqual || oper == Op::Equal || oper == Op::NotEqual) {
        if (auto result = compare(oper, left, right, dest)) {
            return result;
        }
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    if (oper == Op::And || oper == Op::Or || oper == Op::Xor) {
        // On integers too, as in conditions (pou_conditions.cpp) and as CODESYS allows.
        if (!sema::is_bool(type) && !sema::is_bit_string(type) && !sema::is_integer(type)) {
            program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
            return std::nullopt;
        }
        const Operand result = result_operand(type, dest);
        const char* family = oper == Op::And ? "And" : oper == Op::Or ? "Or" : "Xor";
        emit(op_width(family, type), result, left.operand, right.operand);
        return Value{result, &type};
    }
    if (!sema::is_numeric(type) && !sema::is_bit_string(type)) {
        // BYTE..LWORD count as unsigned integers of their width, as in CODESYS: libraries
        // (CRCs, hashes, OSCAT) add and multiply DWORDs. Times are time_arithmetic's, with the
        // typing stage's result type.
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    if (oper == Op::Modulo && !sema::is_integer(type) && !sema::is_bit_string(type)) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    const Operand result = result_operand(type, dest);
    switch (oper) {
    case Op::Add:
        emit(op_width("Add", type), result, left.operand, right.operand);
        break;
    case Op::Subtract:
        emit(op_width("Sub", type), result, left.operand, right.operand);
        break;
    case Op::Multiply:
        emit(op_width("Mul", type), result, left.operand, right.operand);
        break;
    case Op::Divide:
        emit(op("Div", type), result, left.operand, right.operand);
        break;
    default:
        emit(op("Mod", type), result, left.operand, right.operand);
        break;
    }
    return Value{result, &type};
}

} // namespace eposp::compiler::codegen
