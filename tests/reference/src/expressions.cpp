// Expressions of IEC 61131-3 ed. 3, 7.3.2 (table 71), with the project's documented choices:
// SINT, INT, USINT and UINT are computed in DINT inside an expression and cut where stored;
// integers wrap at their type's width (docs/st-language.md).

#include "eposp/compiler/sema/symbol.hpp"
#include "evaluator.hpp"

#include <cmath>

namespace eposp::reference {

using compiler::sema::fold_case;
using E = ast::ElementaryType;

const sema::Type& Evaluator::elementary(E e) {
    return program_.types().elementary(e);
}

const sema::Type& Evaluator::working(const sema::Type& type) {
    const sema::Type& plain = program_.types().unranged(type);
    if (plain.kind == sema::TypeKind::Elementary && sema::is_integer(plain) && plain.size < 4) {
        return elementary(E::Dint);
    }
    return plain;
}

void Evaluator::fault(const std::string& what) {
    throw Fault(what + " in " + (frame_ != nullptr ? frame_->pou->name.name : std::string("?")) +
                " at line " + std::to_string(line_));
}

Value Evaluator::widen(const Value& value, const sema::Type& type) {
    switch (shape_of(type)) {
    case Shape::Integer:
        if (shape_of(*value.type) != Shape::Integer) {
            throw Unsupported("a real number where an integer is expected");
        }
        return integer(type, value.bits);
    case Shape::Real:
    case Shape::Lreal: {
        if (shape_of(*value.type) != Shape::Integer) {
            return real(type, value.real);
        }
        Value result;
        result.type = &type;
        const bool negative = signed_type(*value.type);
        // Straight to float for REAL: through double would round twice.
        result.real = type.elementary == E::Real
                          ? static_cast<double>(negative ? static_cast<float>(value.as_signed())
                                                         : static_cast<float>(value.bits))
                          : (negative ? static_cast<double>(value.as_signed())
                                      : static_cast<double>(value.bits));
        return result;
    }
    case Shape::String: {
        Value result = value;
        result.type = &type;
        return result;
    }
    default:
        return value;
    }
}

Value Evaluator::store(const Value& value, const sema::Type& type) {
    Value result;
    switch (shape_of(type)) {
    case Shape::Integer:
        result = widen(value, program_.types().unranged(type));
        result.type = &type;
        if (type.range && !type.range->contains(result.as_signed())) {
            fault("value out of subrange");
        }
        return result;
    case Shape::Real:
    case Shape::Lreal:
        result = widen(value, type);
        return result;
    case Shape::String:
        return text(type, value.text);
    default:
        result = value;
        result.type = &type;
        return result;
    }
}

Value Evaluator::constant(const types::Constant& value, const sema::Type& type) {
    return std::visit(
        [&](const auto& v) -> Value {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, bool>) {
                return integer(type, v ? 1 : 0);
            } else if constexpr (std::is_same_v<T, std::int64_t> ||
                                 std::is_same_v<T, std::uint64_t>) {
                if (shape_of(type) == Shape::Real || shape_of(type) == Shape::Lreal) {
                    return real(type, static_cast<double>(v));
                }
                return integer(type, static_cast<std::uint64_t>(v));
            } else if constexpr (std::is_same_v<T, double>) {
                return real(type, v);
            } else if constexpr (std::is_same_v<T, std::u16string>) {
                throw Unsupported("a WSTRING");
            } else {
                Value result;
                result.type = &type;
                result.text = v;
                return result;
            }
        },
        value);
}

Value* Evaluator::variable(const ast::Identifier& name) {
    const std::string key = fold_case(name.name);
    if (frame_ != nullptr) {
        if (const auto found = frame_->references.find(key); found != frame_->references.end()) {
            return found->second;
        }
        if (const auto found = frame_->locals.find(key); found != frame_->locals.end()) {
            return &found->second;
        }
        if (frame_->instance != nullptr) {
            if (Value* member = frame_->instance->member(key)) {
                return member;
            }
        }
    }
    if (const auto found = globals_.find(key); found != globals_.end()) {
        return &found->second;
    }
    if (const sema::Symbol* symbol = program_.model().resolved(name);
        symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
        symbol->pou->kind == ast::PouKind::Program) {
        return &instance_of(*symbol->pou);
    }
    throw Unsupported("the name " + name.name + " here");
}

Value& Evaluator::place(const ast::Expression& expression) {
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        return *variable(name->name);
    }
    if (const auto* member = std::get_if<ast::MemberExpression>(&expression.node)) {
        Value& object = place(*member->object);
        if (Value* found = object.member(fold_case(member->member.name))) {
            return *found;
        }
        throw Unsupported("the member " + member->member.name);
    }
    if (const auto* index = std::get_if<ast::IndexExpression>(&expression.node)) {
        // Indices first, in order, then the array (their calls cannot move it).
        std::vector<Value> indices;
        for (const ast::ExpressionPtr& each : index->indices) {
            indices.push_back(eval(*each));
        }
        Value& array = place(*index->array);
        std::size_t flat = 0;
        for (std::size_t d = 0; d < indices.size(); ++d) {
            const sema::ArrayDimension& bounds = array.type->dimensions.at(d);
            const Value& i = indices[d];
            // The whole index counts, whatever its width (a LINT beyond 32 bits is outside).
            const bool huge = !signed_type(*i.type) && i.as_signed() < 0;
            const std::int64_t at = i.as_signed();
            if (huge || at < bounds.lower ||
                at > bounds.lower + static_cast<std::int64_t>(bounds.count) - 1) {
                fault("array index out of range");
            }
            flat = flat * bounds.count + static_cast<std::size_t>(at - bounds.lower);
        }
        return array.elements.at(flat);
    }
    throw Unsupported("writing to this kind of expression");
}

Value Evaluator::eval(const ast::Expression& expression) {
    // Named constants, enumerators and literals take the typing stage's value; operators and
    // calls are computed here even where typing folded them, so that its folding is checked too
    // (and an INT operation it records cut to INT still feeds its parent in DINT, as computed).
    const bool computed = std::holds_alternative<ast::UnaryExpression>(expression.node) ||
                          std::holds_alternative<ast::BinaryExpression>(expression.node) ||
                          std::holds_alternative<ast::CallExpression>(expression.node);
    const sema::Type* type = program_.type_of(expression);
    if (type != nullptr && !computed) {
        if (const types::Constant* value = program_.constant_of(expression)) {
            return constant(*value, *type);
        }
    }
    return std::visit(
        [&](const auto& node) -> Value {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::NameExpression> ||
                          std::is_same_v<T, ast::MemberExpression> ||
                          std::is_same_v<T, ast::IndexExpression>) {
                return place(expression);
            } else if constexpr (std::is_same_v<T, ast::BitAccessExpression>) {
                const Value word = eval(*node.object);
                return integer(elementary(E::Bool), (word.bits >> node.bit) & 1U);
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                return call(expression, node);
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                return unary(expression, node);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                return binary(expression, node);
            } else {
                throw Unsupported("references, pointers, direct addresses and this literal");
            }
        },
        expression.node);
}

const sema::Type& Evaluator::type_of(const ast::Expression& expression) {
    const sema::Type* type = program_.type_of(expression);
    if (type == nullptr) {
        throw Unsupported("an expression the typing stage left untyped");
    }
    return *type;
}

Value Evaluator::unary(const ast::Expression& expression, const ast::UnaryExpression& node) {
    const sema::Type& type = type_of(expression);
    if (node.op == ast::UnaryOperator::Plus) {
        return eval(*node.operand);
    }
    if (node.op == ast::UnaryOperator::Not) {
        const Value operand = eval(*node.operand);
        const sema::Type& plain = program_.types().unranged(type);
        return integer(plain,
                       plain.elementary == E::Bool ? (operand.bits == 0 ? 1 : 0) : ~operand.bits);
    }
    const sema::Type& work = working(type);
    const Value operand = widen(eval(*node.operand), work);
    if (shape_of(work) == Shape::Integer) {
        return integer(work, 0 - operand.bits);
    }
    return real(work, -operand.real);
}

Value Evaluator::binary(const ast::Expression& expression, const ast::BinaryExpression& node) {
    using Op = ast::BinaryOperator;
    const sema::Type& type = type_of(expression);
    switch (node.op) {
    case Op::Less:
    case Op::Greater:
    case Op::LessEqual:
    case Op::GreaterEqual:
    case Op::Equal:
    case Op::NotEqual: {
        const Value left = eval(*node.left);
        const Value right = eval(*node.right);
        return integer(type, compare(node.op, left, right) ? 1 : 0);
    }
    case Op::And:
    case Op::Or:
    case Op::Xor: {
        const Value left = widen(eval(*node.left), type);
        const Value right = widen(eval(*node.right), type);
        const std::uint64_t bits = node.op == Op::And  ? left.bits & right.bits
                                   : node.op == Op::Or ? left.bits | right.bits
                                                       : left.bits ^ right.bits;
        return integer(type, bits);
    }
    case Op::Power: {
        const Value base = widen(eval(*node.left), type);
        const Value exponent = widen(eval(*node.right), type);
        return power(base, exponent, type);
    }
    default:
        break;
    }
    if (sema::is_time_like(type)) {
        const Value left = eval(*node.left);
        const Value right = eval(*node.right);
        return time_arithmetic(node.op, left, right, type);
    }
    const sema::Type& work = working(type);
    const Value left = widen(eval(*node.left), work);
    const Value right = widen(eval(*node.right), work);
    return arithmetic(node.op, left, right, work);
}

Value Evaluator::power(const Value& base, const Value& exponent, const sema::Type& type) {
    if (type.elementary == E::Real) {
        return real(type, static_cast<double>(std::pow(static_cast<float>(base.real),
                                                       static_cast<float>(exponent.real))));
    }
    return real(type, std::pow(base.real, exponent.real));
}

Value Evaluator::time_arithmetic(ast::BinaryOperator op, const Value& left, const Value& right,
                                 const sema::Type& type) {
    using Op = ast::BinaryOperator;
    if (shape_of(*right.type) != Shape::Integer) {
        throw Unsupported("a TIME scaled by a real number");
    }
    switch (op) {
    case Op::Add:
    case Op::Subtract:
        if (type.elementary == E::TimeOfDay || type.elementary == E::Ltod) {
            // Table 30: a time of day moved by a duration wraps around midnight (vm/README.md,
            // as CODESYS); of the operands' times of day, so that no sum of 64 bits wraps first.
            const std::int64_t l = since_midnight(left.as_signed());
            const std::int64_t r = since_midnight(right.as_signed());
            return integer(
                type, static_cast<std::uint64_t>(since_midnight(op == Op::Add ? l + r : l - r)));
        }
        return arithmetic(op, left, right, type);
    case Op::Multiply:
        return arithmetic(op, left, right, type);
    case Op::Divide:
        return arithmetic(op, left, widen(right, elementary(E::Lint)), type);
    default:
        throw Unsupported("this operation on times");
    }
}

Value Evaluator::arithmetic(ast::BinaryOperator op, const Value& left, const Value& right,
                            const sema::Type& type) {
    using Op = ast::BinaryOperator;
    if (shape_of(type) == Shape::Real) {
        const float l = static_cast<float>(left.real);
        const float r = static_cast<float>(right.real);
        switch (op) {
        case Op::Add:
            return real(type, static_cast<double>(l + r));
        case Op::Subtract:
            return real(type, static_cast<double>(l - r));
        case Op::Multiply:
            return real(type, static_cast<double>(l * r));
        case Op::Divide:
            return real(type, static_cast<double>(l / r));
        default:
            throw Unsupported("MOD on REAL");
        }
    }
    if (shape_of(type) == Shape::Lreal) {
        switch (op) {
        case Op::Add:
            return real(type, left.real + right.real);
        case Op::Subtract:
            return real(type, left.real - right.real);
        case Op::Multiply:
            return real(type, left.real * right.real);
        case Op::Divide:
            return real(type, left.real / right.real);
        default:
            throw Unsupported("MOD on LREAL");
        }
    }
    switch (op) {
    case Op::Add:
        return integer(type, left.bits + right.bits);
    case Op::Subtract:
        return integer(type, left.bits - right.bits);
    case Op::Multiply:
        return integer(type, left.bits * right.bits);
    case Op::Divide:
    case Op::Modulo: {
        if (right.bits == 0) {
            fault("division by zero");
        }
        const bool divide = op == Op::Divide;
        if (!signed_type(type)) {
            return integer(type, divide ? left.bits / right.bits : left.bits % right.bits);
        }
        // The most negative value divided by -1 wraps to itself (and leaves no remainder).
        if (right.as_signed() == -1) {
            return integer(type, divide ? 0 - left.bits : 0);
        }
        const std::int64_t l = left.as_signed();
        const std::int64_t r = right.as_signed();
        return integer(type, static_cast<std::uint64_t>(divide ? l / r : l % r));
    }
    default:
        throw Unsupported("this operator");
    }
}

int Evaluator::order(const Value& left, const Value& right) {
    const Shape l = shape_of(*left.type);
    const Shape r = shape_of(*right.type);
    if (l == Shape::String || r == Shape::String) {
        const int c = left.text.compare(right.text);
        return c < 0 ? -1 : c > 0 ? 1 : 0;
    }
    if (l != Shape::Integer || r != Shape::Integer) {
        const double a = widen(left, elementary(E::Lreal)).real;
        const double b = widen(right, elementary(E::Lreal)).real;
        return a < b ? -1 : a > b ? 1 : 0;
    }
    const bool left_negative = signed_type(*left.type) && left.as_signed() < 0;
    const bool right_negative = signed_type(*right.type) && right.as_signed() < 0;
    if (left_negative != right_negative) {
        return left_negative ? -1 : 1;
    }
    return left.bits < right.bits ? -1 : left.bits > right.bits ? 1 : 0;
}

bool Evaluator::compare(ast::BinaryOperator op, const Value& left, const Value& right) {
    using Op = ast::BinaryOperator;
    const bool real_operands =
        shape_of(*left.type) == Shape::Real || shape_of(*left.type) == Shape::Lreal ||
        shape_of(*right.type) == Shape::Real || shape_of(*right.type) == Shape::Lreal;
    if (real_operands && (std::isnan(widen(left, elementary(E::Lreal)).real) ||
                          std::isnan(widen(right, elementary(E::Lreal)).real))) {
        return op == Op::NotEqual; // IEC 60559: NaN is unordered
    }
    const int c = order(left, right);
    switch (op) {
    case Op::Less:
        return c < 0;
    case Op::Greater:
        return c > 0;
    case Op::LessEqual:
        return c <= 0;
    case Op::GreaterEqual:
        return c >= 0;
    case Op::Equal:
        return c == 0;
    default:
        return c != 0;
    }
}

} // namespace eposp::reference
