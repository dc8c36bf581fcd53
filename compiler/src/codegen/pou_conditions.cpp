// Conditions of IF, WHILE, REPEAT and CASE compiled to compare-and-branch instructions
// (IEC 61131-3 ed. 3, 7.3.3.3): `IF a < b THEN` is one JLe to the ELSE part, `IF (x AND m) <> 0
// THEN` one JNTst.

#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using Op = ast::BinaryOperator;

namespace {

bool is_comparison(Op op) {
    return op == Op::Less || op == Op::Greater || op == Op::LessEqual || op == Op::GreaterEqual ||
           op == Op::Equal || op == Op::NotEqual;
}

Op negated(Op op) {
    switch (op) {
    case Op::Less:
        return Op::GreaterEqual;
    case Op::Greater:
        return Op::LessEqual;
    case Op::LessEqual:
        return Op::Greater;
    case Op::GreaterEqual:
        return Op::Less;
    case Op::Equal:
        return Op::NotEqual;
    default:
        return Op::Equal;
    }
}

} // namespace

std::optional<PouGenerator::BitTest> PouGenerator::bit_test(const ast::Expression& condition,
                                                            bool& matched) {
    matched = false;
    const auto* comparison = std::get_if<ast::BinaryExpression>(&condition.node);
    if (comparison == nullptr || (comparison->op != Op::Equal && comparison->op != Op::NotEqual)) {
        return std::nullopt;
    }
    const auto and_of = [](const ast::Expression& side) {
        const auto* binary = std::get_if<ast::BinaryExpression>(&side.node);
        return binary != nullptr && binary->op == Op::And ? &side : nullptr;
    };
    const bool zero_right = small_literal(*comparison->right) == 0;
    const ast::Expression* masked = zero_right ? and_of(*comparison->left)
                                    : small_literal(*comparison->left) == 0
                                        ? and_of(*comparison->right)
                                        : nullptr;
    if (masked == nullptr) {
        return std::nullopt;
    }
    matched = true;
    const auto& mask = std::get<ast::BinaryExpression>(masked->node);
    const sema::Type* type = program_.typed().operands_of(*masked);
    if (type == nullptr || (!sema::is_integer(*type) && !sema::is_bit_string(*type))) {
        // `(a AND b) = 0` on BOOL does not type (types/operator_typing.cpp).
        program_.refused_by_checks(DiagnosticCode::E0303);
        return std::nullopt;
    }
    const auto pair = operands(*mask.left, *mask.right, *type);
    if (!pair) {
        return std::nullopt; // reported
    }
    const auto& [x, y] = *pair;
    return BitTest{x, y, comparison->op == Op::NotEqual};
}

bool PouGenerator::branch_on_bits(const ast::Expression& condition, bool when, vm::Label target) {
    bool matched = false;
    const auto test = bit_test(condition, matched);
    if (test) {
        const bool jump_if_set = test->set == when;
        builder_.jump(op_width(jump_if_set ? "JTst" : "JNTst", *test->x.type), target,
                      test->x.operand, test->y.operand);
    }
    return matched;
}

std::optional<Value> PouGenerator::condition_value(const ast::Expression& condition) {
    const sema::Type& boolean = types_.elementary(ast::ElementaryType::Bool);
    bool matched = false;
    const auto test = bit_test(condition, matched);
    if (!matched) {
        return value_as(condition, boolean);
    }
    if (!test) {
        return std::nullopt;
    }
    const sema::Type& type = *test->x.type;
    const vm::Operand bits = temp(type);
    emit(op_width("And", type), bits, test->x.operand, test->y.operand);
    const std::vector<std::uint8_t> zero(type.size, 0);
    const vm::Operand result = temp(boolean);
    emit(op_width(test->set ? "Ne" : "Eq", type), result, bits,
         program_.constant(zero, type.align));
    return Value{result, &boolean};
}

void PouGenerator::branch(const ast::Expression& condition, bool when, vm::Label target) {
    const sema::Type& boolean = types_.elementary(ast::ElementaryType::Bool);
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&condition.node);
        unary != nullptr && unary->op == ast::UnaryOperator::Not) {
        const auto* operand = unary->operand.get();
        // NOT on BOOL only: NOT of a bit string is a value, not a condition.
        if (!std::holds_alternative<ast::LiteralExpression>(operand->node)) {
            branch(*operand, !when, target);
            return;
        }
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&condition.node);
    // AND / OR as jumps, when skipping the right side cannot skip a call's side effects.
    if (binary != nullptr && (binary->op == Op::And || binary->op == Op::Or) &&
        !contains_call(*binary->right)) {
        // A condition is BOOL, so AND and OR here are logical (a bit string is reported as
        // not BOOL by the sides).
        const bool conjunction = binary->op == Op::And;
        if (conjunction != when) {
            // AND jumping when false / OR jumping when true: either side decides.
            branch(*binary->left, when, target);
            branch(*binary->right, when, target);
        } else {
            const vm::Label skip = builder_.label();
            branch(*binary->left, !when, skip);
            branch(*binary->right, when, target);
            bind(skip);
        }
        return;
    }
    if (binary != nullptr && branch_on_bits(condition, when, target)) {
        return;
    }
    const sema::Type* compared = binary != nullptr && is_comparison(binary->op)
                                     ? program_.typed().operands_of(condition)
                                     : nullptr;
    if (compared != nullptr) {
        const auto pair = operands(*binary->left, *binary->right, *compared);
        if (!pair) {
            return;
        }
        const auto& [left, right] = *pair;
        const sema::Type& type = *left.type;
        const bool real = sema::is_real(type);
        if (sema::is_scalar(type) && !(real && !when)) {
            // With NaN a negated float comparison is not the opposite one: only direct forms.
            const Op op = when ? binary->op : negated(binary->op);
            const bool swap = op == Op::Greater || op == Op::GreaterEqual;
            const Value& a = swap ? right : left;
            const Value& b = swap ? left : right;
            std::string_view suffix = type_suffix(sema::scalar_of(type));
            if (suffix == "Bool") {
                suffix = "U8";
            }
            vm::Opcode opcode{};
            if (op == Op::Equal) {
                opcode = op_width("JEq", type);
            } else if (op == Op::NotEqual) {
                opcode = op_width("JNe", type);
            } else if (op == Op::Less || op == Op::Greater) {
                opcode = program_.opcodes().get("JLt", suffix);
            } else {
                opcode = program_.opcodes().get("JLe", suffix);
            }
            builder_.jump(opcode, target, a.operand, b.operand);
            return;
        }
        const auto value = apply(binary->op, left, right, nullptr);
        if (value) {
            builder_.jump(when ? vm::Opcode::Jt : vm::Opcode::Jf, target, value->operand);
        }
        return;
    }
    std::optional<Value> value;
    if (std::holds_alternative<ast::IndexExpression>(condition.node)) {
        // An element of a BOOL array is tested where it is: `IF flags[i] THEN` is one JfX.
        const auto where = place(condition);
        if (!where) {
            return;
        }
        if (where->kind == Place::Kind::Element && where->type == &boolean) {
            builder_.jump(when ? vm::Opcode::JtX : vm::Opcode::JfX, target, where->operand,
                          where->index, where->array);
            return;
        }
        value = value_as(load(*where), boolean);
    } else {
        value = value_as(condition, boolean);
    }
    if (value) {
        builder_.jump(when ? vm::Opcode::Jt : vm::Opcode::Jf, target, value->operand);
    }
}

} // namespace eposp::compiler::codegen
