// Subrange types (IEC 61131-3 ed. 3, 6.4.4.4): a value stored into a subrange variable must lie
// within its bounds. A constant inside them is stored as it is (the checks stage refuses one
// outside, checks/constant_subranges.cpp); any other value is checked by a Range<I> instruction
// before it is stored, unless it comes from a variable or a function result whose own subrange
// lies inside the target's. Values computed from subranges (`p + 1`) have the
// base type: only a checked conversion gives a value the subrange type again.

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using vm::Operand;

std::optional<Value> PouGenerator::subrange_value(const ast::Expression& expression,
                                                  const sema::Type& want) {
    const sema::Type& base = types_.unranged(want);
    if (const auto constant = program_.typed().constants().fold_integer(expression);
        constant && want.range->contains(*constant)) {
        const auto value = value_as(expression, base);
        return value ? std::optional(Value{value->operand, &want}) : std::nullopt;
    }
    auto value = eval(expression, &base);
    if (!value) {
        return std::nullopt;
    }
    if (const sema::Type* declared = declared_subrange(expression);
        declared != nullptr && sema::converts_implicitly(*declared, want)) {
        value->type = declared; // checked when it was stored
    }
    return value_as(*value, want, nullptr);
}

const sema::Type* PouGenerator::declared_subrange(const ast::Expression& expression) {
    const ast::Expression* named = &expression;
    const auto* call = std::get_if<ast::CallExpression>(&expression.node);
    if (call != nullptr) {
        named = call->callee.get();
    }
    const auto* name = std::get_if<ast::NameExpression>(&named->node);
    const sema::Symbol* symbol = name != nullptr ? model_.resolved(name->name) : nullptr;
    const sema::Type* type = nullptr;
    if (symbol == nullptr) {
        return nullptr;
    }
    if (call == nullptr && symbol->kind == sema::SymbolKind::Variable) {
        const auto place = variable(*symbol);
        type = place ? place->type : nullptr;
    } else if (call != nullptr && symbol->kind == sema::SymbolKind::Pou &&
               symbol->pou->kind == ast::PouKind::Function && symbol->pou->return_type) {
        type = types_.frame(*symbol->pou)->fields.front().type; // the result, at offset 0
    }
    return type != nullptr && type->range ? type : nullptr;
}

Value PouGenerator::checked(const Value& value, const sema::Type& want) {
    const sema::Type& base = types_.unranged(want);
    const bool proven = value.type->range && want.range->contains(*value.type->range);
    const Value converted =
        *convert(Value{value.operand, &types_.unranged(*value.type)}, base, nullptr);
    if (!proven) {
        std::vector<std::uint8_t> bounds = integer_bytes(want.range->lower, want.size);
        const auto upper = integer_bytes(want.range->upper, want.size);
        bounds.insert(bounds.end(), upper.begin(), upper.end());
        emit(op("Range", want), converted.operand, program_.constant(bounds, want.align));
    }
    return Value{converted.operand, &want};
}

void PouGenerator::step_back_into_range(Operand control, const sema::Type& type, Operand step) {
    // After the last iteration the control variable is one step past the limit; IEC leaves
    // its value then to the implementation (7.3.3.4.2), and a subrange keeps the last one.
    const sema::Type& counter = types_.unranged(type);
    const vm::Label outside = builder_.label();
    const vm::Label inside = builder_.label();
    const std::string_view suffix = type_suffix(sema::scalar_of(counter));
    builder_.jump(program_.opcodes().get("JLt", suffix), outside, control,
                  integer_constant(counter, type.range->lower));
    builder_.jump(program_.opcodes().get("JLe", suffix), inside, control,
                  integer_constant(counter, type.range->upper));
    bind(outside);
    emit(op_width("Sub", counter), control, control, step);
    bind(inside);
}

} // namespace eposp::compiler::codegen
