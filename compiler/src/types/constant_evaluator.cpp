// Constant expressions evaluated as they compute at run time (ed. 3, 6.4.2, 6.5.1.3).

#include "constant_evaluator.hpp"

#include "eposp/compiler/sema/symbol.hpp"

#include <algorithm>

namespace eposp::compiler::types {

namespace {

const ast::Literal* literal_of(const ast::Expression& expression) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    return literal != nullptr ? &literal->value : nullptr;
}

std::int64_t wrapping_sum(std::int64_t a, std::int64_t b, bool add) {
    const auto ua = static_cast<std::uint64_t>(a);
    const auto ub = static_cast<std::uint64_t>(b);
    return static_cast<std::int64_t>(add ? ua + ub : ua - ub);
}

} // namespace

const ast::VariableDeclaration*
ConstantEvaluator::constant(const ast::Expression& expression) const {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    const sema::Symbol* symbol = name != nullptr ? types_.model().resolved(name->name) : nullptr;
    if (symbol == nullptr || symbol->kind != sema::SymbolKind::Variable ||
        symbol->variable == nullptr || !symbol->variable->initial_value ||
        !std::holds_alternative<ast::ExpressionPtr>(symbol->variable->initial_value->value) ||
        !types_.is_constant(*symbol->variable) || evaluating_.contains(symbol->variable)) {
        return nullptr;
    }
    return symbol->variable;
}

std::optional<std::int64_t>
ConstantEvaluator::fold_integer(const ast::Expression& expression) const {
    const auto bits = integer(expression, Arithmetic{});
    return bits ? std::optional(static_cast<std::int64_t>(*bits)) : std::nullopt;
}

std::optional<std::uint64_t>
ConstantEvaluator::fold_unsigned(const ast::Expression& expression) const {
    return integer(expression, Arithmetic{.is_unsigned = true});
}

std::optional<std::uint64_t> ConstantEvaluator::fold_as(const ast::Expression& expression,
                                                        const sema::Type& type) const {
    switch (sema::scalar_of(type)) {
    case vm::Scalar::U32:
        return integer(expression, Arithmetic{.is_unsigned = true, .bits = 32, .type = &type});
    case vm::Scalar::I64:
        return integer(expression, Arithmetic{.type = &type});
    case vm::Scalar::U64:
        return integer(expression, Arithmetic{.is_unsigned = true, .type = &type});
    default:
        return integer(expression, Arithmetic{.bits = 32, .type = &type});
    }
}

bool ConstantEvaluator::computes_in(const ast::Expression& expression,
                                    const sema::Type& type) const {
    if (const ast::Literal* literal = literal_of(expression)) {
        const auto* integer = std::get_if<ast::IntegerLiteral>(literal);
        return integer != nullptr && (!integer->type || *integer->type == type.elementary);
    }
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = types_.model().resolved(name->name);
        const sema::Type* declared = symbol != nullptr &&
                                             symbol->kind == sema::SymbolKind::Variable &&
                                             symbol->variable != nullptr
                                         ? types_.resolve(symbol->variable->type)
                                         : nullptr;
        return declared != nullptr && declared->size == type.size &&
               sema::is_signed(*declared) == sema::is_signed(type);
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return computes_in(*unary->operand, type);
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    return binary != nullptr && computes_in(*binary->left, type) &&
           computes_in(*binary->right, type);
}

std::optional<std::uint64_t> ConstantEvaluator::integer(const ast::Expression& expression,
                                                        Arithmetic arithmetic) const {
    const bool unsigned64 = arithmetic.is_unsigned && arithmetic.bits == 64;
    // A result as the arithmetic holds it: cut to its bits, then sign- or zero-extended.
    const auto held = [arithmetic](std::uint64_t bits) -> std::uint64_t {
        if (arithmetic.bits == 64) {
            return bits;
        }
        return arithmetic.is_unsigned
                   ? static_cast<std::uint32_t>(bits)
                   : static_cast<std::uint64_t>(static_cast<std::int64_t>(
                         static_cast<std::int32_t>(static_cast<std::uint32_t>(bits))));
    };
    if (const sema::Symbol* value = types_.model().enum_value(expression)) {
        const auto number = types_.enumerator(*value);
        return number ? std::optional(static_cast<std::uint64_t>(*number)) : std::nullopt;
    }
    if (const ast::Literal* literal = literal_of(expression)) {
        if (const auto* integer = std::get_if<ast::IntegerLiteral>(literal)) {
            if (integer->magnitude > static_cast<std::uint64_t>(INT64_MAX) && !unsigned64) {
                return integer->negative ? std::optional(std::uint64_t{1} << 63) : std::nullopt;
            }
            return held(integer->negative ? 0ULL - integer->magnitude : integer->magnitude);
        }
        return std::nullopt;
    }
    if (std::holds_alternative<ast::NameExpression>(expression.node)) {
        const ast::VariableDeclaration* declaration = constant(expression);
        if (declaration == nullptr) {
            return std::nullopt;
        }
        // A constant holds the value of its own type, computed as that type computes.
        const sema::Type* own = types_.resolve(declaration->type);
        return within(*declaration, [&] {
            return own != nullptr && (sema::is_integer(*own) || sema::is_bit_string(*own))
                       ? fold_as(initial_value(*declaration), *own)
                       : integer(initial_value(*declaration), arithmetic);
        });
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const auto operand = integer(*unary->operand, arithmetic);
        if (!operand) {
            return std::nullopt;
        }
        switch (unary->op) {
        case ast::UnaryOperator::Negate:
            return held(0ULL - *operand);
        case ast::UnaryOperator::Not: {
            // At run time NOT flips its operand type's bits: a BYTE's eight (NOT 16#0F is
            // 16#F0), also where the result widens. Folded only where that type is known.
            const sema::Type* type = arithmetic.type;
            if (type == nullptr || !computes_in(*unary->operand, *type)) {
                return std::nullopt;
            }
            const std::uint64_t flipped = held(~*operand);
            return sema::is_signed(*type) || type->size >= 4
                       ? flipped
                       : flipped & ((std::uint64_t{1} << (8 * type->size)) - 1);
        }
        default:
            return *operand;
        }
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    if (binary == nullptr) {
        return std::nullopt;
    }
    const auto left = integer(*binary->left, arithmetic);
    const auto right = integer(*binary->right, arithmetic);
    if (!left || !right) {
        return std::nullopt;
    }
    const std::uint64_t l = *left;
    const std::uint64_t r = *right;
    const auto sl = static_cast<std::int64_t>(l);
    const auto sr = static_cast<std::int64_t>(r);
    switch (binary->op) {
    case ast::BinaryOperator::Add:
        return held(l + r);
    case ast::BinaryOperator::Subtract:
        return held(l - r);
    case ast::BinaryOperator::Multiply:
        return held(l * r);
    case ast::BinaryOperator::Divide:
        // Division by zero is no constant (it traps at run time); MIN / -1 wraps to MIN, as
        // the VM computes it (value_semantics.hpp, divide).
        if (r == 0) {
            return std::nullopt;
        }
        if (arithmetic.is_unsigned) {
            return l / r;
        }
        return sr == -1 ? held(0ULL - l) : held(static_cast<std::uint64_t>(sl / sr));
    case ast::BinaryOperator::Modulo:
        // MOD -1 is 0, also of MIN (value_semantics.hpp, modulo).
        if (r == 0) {
            return std::nullopt;
        }
        if (arithmetic.is_unsigned) {
            return l % r;
        }
        return sr == -1 ? 0 : static_cast<std::uint64_t>(sl % sr);
    case ast::BinaryOperator::And:
        return l & r;
    case ast::BinaryOperator::Or:
        return l | r;
    case ast::BinaryOperator::Xor:
        return l ^ r;
    default:
        return std::nullopt;
    }
}

std::optional<double> ConstantEvaluator::real(const ast::Expression& expression,
                                              bool single) const {
    // A part the typing stage typed computes in its own type, and converts after: a REAL
    // product in single precision also inside an LREAL (`kTenth * kThird`), an integer
    // division as one (`kSeven / 2`, `DINT#7 / 2`).
    const sema::Type* part = program_.type_of(expression);
    if (part != nullptr && sema::is_real(*part)) {
        single = part->size == 4;
    }
    const auto rounded = [single](double value) {
        return single ? static_cast<double>(static_cast<float>(value)) : value;
    };
    if (part != nullptr && (sema::is_integer(*part) || sema::is_bit_string(*part))) {
        const auto bits = fold_as(expression, *part);
        if (!bits) {
            return std::nullopt;
        }
        // Held in the part's own width, as the VM holds it (an INT's 16 bits).
        const unsigned unused = 64 - 8 * std::min<unsigned>(part->size, 8);
        const std::uint64_t held = *bits << unused;
        return rounded(sema::is_signed(*part)
                           ? static_cast<double>(static_cast<std::int64_t>(held) >> unused)
                           : static_cast<double>(held >> unused));
    }
    if (const ast::Literal* literal = literal_of(expression)) {
        if (const auto* real = std::get_if<ast::RealLiteral>(literal)) {
            return rounded(real->value);
        }
        if (const auto* integer = std::get_if<ast::IntegerLiteral>(literal)) {
            return rounded(static_cast<double>(integer->magnitude) * (integer->negative ? -1 : 1));
        }
        return std::nullopt;
    }
    if (const ast::VariableDeclaration* declaration = constant(expression)) {
        // A named constant has the value of its own type (a REAL one in an LREAL too).
        const sema::Type* type = types_.resolve(declaration->type);
        if (type != nullptr && sema::is_real(*type)) {
            return within(*declaration,
                          [&] { return real(initial_value(*declaration), type->size == 4); });
        }
        const auto integer = fold_integer(expression);
        return integer ? std::optional(rounded(static_cast<double>(*integer))) : std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const auto operand = real(*unary->operand, single);
        if (!operand || unary->op == ast::UnaryOperator::Not) {
            return std::nullopt;
        }
        return unary->op == ast::UnaryOperator::Negate ? -*operand : *operand;
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    const auto left = binary != nullptr ? real(*binary->left, single) : std::nullopt;
    const auto right = left ? real(*binary->right, single) : std::nullopt;
    if (!right) {
        return std::nullopt;
    }
    switch (binary->op) {
    case ast::BinaryOperator::Add:
        return rounded(*left + *right);
    case ast::BinaryOperator::Subtract:
        return rounded(*left - *right);
    case ast::BinaryOperator::Multiply:
        return rounded(*left * *right);
    case ast::BinaryOperator::Divide:
        return rounded(*left / *right);
    default:
        return std::nullopt;
    }
}

std::optional<std::int64_t> ConstantEvaluator::time(const ast::Expression& expression,
                                                    bool day_wraps) const {
    if (const ast::Literal* literal = literal_of(expression)) {
        if (const auto* duration = std::get_if<ast::DurationLiteral>(literal)) {
            return duration->nanoseconds;
        }
        if (const auto* date = std::get_if<ast::DateTimeLiteral>(literal)) {
            return date->nanoseconds;
        }
        return std::nullopt;
    }
    if (const ast::VariableDeclaration* declaration = constant(expression)) {
        const sema::Type* type = types_.resolve(declaration->type);
        return type != nullptr && sema::is_time_like(*type)
                   ? within(*declaration,
                            [&] { return time(initial_value(*declaration), day_wraps); })
                   : std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const auto operand = time(*unary->operand, day_wraps);
        if (!operand || unary->op == ast::UnaryOperator::Not) {
            return std::nullopt;
        }
        return unary->op == ast::UnaryOperator::Negate ? wrapping_sum(0, *operand, false)
                                                       : *operand;
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    if (binary == nullptr) {
        return std::nullopt;
    }
    const auto left = time(*binary->left, false);
    switch (binary->op) {
    case ast::BinaryOperator::Add:
    case ast::BinaryOperator::Subtract: {
        // A TIME_OF_DAY wraps around midnight at run time (ADD_TOD_TIME): not folded.
        const auto right = left && !day_wraps ? time(*binary->right, false) : std::nullopt;
        return right ? std::optional(
                           wrapping_sum(*left, *right, binary->op == ast::BinaryOperator::Add))
                     : std::nullopt;
    }
    case ast::BinaryOperator::Multiply: {
        // TIME * ANY_INT as MUL_TIME computes it: modulo 2^64. A REAL factor rounds at run
        // time (MUL_TIME_LREAL): not folded.
        const auto factor = left ? fold_integer(*binary->right) : std::nullopt;
        return factor
                   ? std::optional(static_cast<std::int64_t>(static_cast<std::uint64_t>(*left) *
                                                             static_cast<std::uint64_t>(*factor)))
                   : std::nullopt;
    }
    case ast::BinaryOperator::Divide: {
        // As DIV_TIME: / -1 wraps, / 0 is no constant.
        const auto divisor = left ? fold_integer(*binary->right) : std::nullopt;
        if (!divisor || *divisor == 0) {
            return std::nullopt;
        }
        return *divisor == -1 ? wrapping_sum(0, *left, false) : *left / *divisor;
    }
    default:
        return std::nullopt;
    }
}

std::optional<bool> ConstantEvaluator::boolean(const ast::Expression& expression) const {
    if (const ast::Literal* literal = literal_of(expression)) {
        const auto* boolean = std::get_if<ast::BoolLiteral>(literal);
        return boolean != nullptr ? std::optional(boolean->value) : std::nullopt;
    }
    if (const ast::VariableDeclaration* declaration = constant(expression)) {
        const sema::Type* type = types_.resolve(declaration->type);
        return type != nullptr && sema::is_bool(*type)
                   ? within(*declaration, [&] { return boolean(initial_value(*declaration)); })
                   : std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const auto operand = boolean(*unary->operand);
        return operand && unary->op == ast::UnaryOperator::Not ? std::optional(!*operand)
                                                               : std::nullopt;
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    const auto left = binary != nullptr ? boolean(*binary->left) : std::nullopt;
    const auto right = left ? boolean(*binary->right) : std::nullopt;
    if (!right) {
        return std::nullopt;
    }
    switch (binary->op) {
    case ast::BinaryOperator::And:
        return *left && *right;
    case ast::BinaryOperator::Or:
        return *left || *right;
    case ast::BinaryOperator::Xor:
        return *left != *right;
    default:
        return std::nullopt;
    }
}

const ast::Literal* ConstantEvaluator::literal(const ast::Expression& expression) const {
    if (const ast::Literal* literal = literal_of(expression)) {
        return literal;
    }
    const ast::VariableDeclaration* declaration = constant(expression);
    return declaration != nullptr
               ? within(*declaration, [&] { return literal(initial_value(*declaration)); })
               : nullptr;
}

} // namespace eposp::compiler::types
