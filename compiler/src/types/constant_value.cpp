// The constant the typing stage records for an expression (TypedProgram::constant_of), and
// what the stages after it ask of it.

#include "constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <algorithm>

namespace eposp::compiler::types {

namespace {

std::optional<Constant> literal_value(const ast::Literal& literal, const sema::Type& type) {
    // A REAL literal has the single-precision value it has at run time.
    const auto rounded = [&type](double value) {
        return type.size == 4 ? static_cast<double>(static_cast<float>(value)) : value;
    };
    return std::visit(
        [&](const auto& value) -> std::optional<Constant> {
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, ast::IntegerLiteral>) {
                if (sema::is_real(type)) {
                    const double magnitude = static_cast<double>(value.magnitude);
                    return rounded(value.negative ? -magnitude : magnitude);
                }
                if (sema::is_signed(type) || sema::is_time_like(type)) {
                    return value.negative ? static_cast<std::int64_t>(0 - value.magnitude)
                                          : static_cast<std::int64_t>(value.magnitude);
                }
                return value.magnitude;
            } else if constexpr (std::is_same_v<T, ast::RealLiteral>) {
                return sema::is_real(type) ? rounded(value.value) : value.value;
            } else if constexpr (std::is_same_v<T, ast::BoolLiteral>) {
                return value.value;
            } else if constexpr (std::is_same_v<T, ast::DurationLiteral> ||
                                 std::is_same_v<T, ast::DateTimeLiteral>) {
                return value.nanoseconds;
            } else if constexpr (std::is_same_v<T, ast::StringLiteral>) {
                const auto* text = std::get_if<std::string>(&value.value);
                if (text != nullptr && value.type == ast::ElementaryType::Char) {
                    // A CHAR is its character's code.
                    return static_cast<std::uint64_t>(
                        text->empty() ? 0 : static_cast<unsigned char>(text->front()));
                }
                if (text != nullptr) {
                    return *text;
                }
                // A WSTRING's units; a WCHAR is its unit's code.
                const auto* wide = std::get_if<std::u16string>(&value.value);
                if (wide != nullptr && value.type == ast::ElementaryType::Wchar) {
                    return static_cast<std::uint64_t>(wide->empty() ? 0 : wide->front());
                }
                return wide != nullptr && value.type == ast::ElementaryType::Wstring
                           ? std::optional<Constant>(*wide)
                           : std::nullopt;
            } else {
                return std::nullopt;
            }
        },
        literal);
}

template <typename T>
std::optional<Constant> as_constant(const std::optional<T>& value) {
    return value ? std::optional<Constant>(*value) : std::nullopt;
}

} // namespace

bool same_number(const Constant& a, const Constant& b) {
    // Held signed or unsigned: its sign and its bits.
    const auto number = [](const Constant& c) -> std::optional<std::pair<bool, std::uint64_t>> {
        if (const auto* i = std::get_if<std::int64_t>(&c)) {
            return std::pair{*i < 0, static_cast<std::uint64_t>(*i)};
        }
        if (const auto* u = std::get_if<std::uint64_t>(&c)) {
            return std::pair{false, *u};
        }
        return std::nullopt;
    };
    return number(a) && number(a) == number(b);
}

const ast::VariableDeclaration* ConstantFolder::constant(const ast::Expression& expression) const {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    const sema::Symbol* symbol = name != nullptr ? types_.model().resolved(name->name) : nullptr;
    if (symbol == nullptr || symbol->kind != sema::SymbolKind::Variable ||
        symbol->variable == nullptr || !symbol->variable->initial_value ||
        !std::holds_alternative<ast::ExpressionPtr>(symbol->variable->initial_value->value) ||
        !types_.is_constant(*symbol->variable)) {
        return nullptr;
    }
    if (const auto used = std::find(evaluating_.begin(), evaluating_.end(), symbol->variable);
        used != evaluating_.end()) {
        // Each CONSTANT from it up to the one using it again is defined through itself.
        circular_.insert(used, evaluating_.end());
        return nullptr;
    }
    return symbol->variable;
}

bool ConstantFolder::enter(const ast::VariableDeclaration& declaration) const {
    if (std::find(evaluating_.begin(), evaluating_.end(), &declaration) != evaluating_.end()) {
        return false;
    }
    evaluating_.push_back(&declaration);
    return true;
}

const Constant* ConstantFolder::typed_constant(const ast::Expression& expression,
                                               const sema::Type* expected) const {
    if (program_.type_of(expression) == nullptr) {
        // Its own place in the program reports its errors, when the typing pass reaches it.
        Diagnostics unreported;
        ExpressionTyper(program_, types_.model(), unreported).type_alone(expression, expected);
    }
    return program_.constant_of(expression);
}

std::optional<std::int64_t> ConstantFolder::fold_integer(const ast::Expression& expression) const {
    const Constant* constant = typed_constant(expression, nullptr);
    if (const auto* i = constant != nullptr ? std::get_if<std::int64_t>(constant) : nullptr) {
        return *i;
    }
    const auto* u = constant != nullptr ? std::get_if<std::uint64_t>(constant) : nullptr;
    if (u == nullptr || *u > static_cast<std::uint64_t>(INT64_MAX)) {
        return std::nullopt;
    }
    return static_cast<std::int64_t>(*u);
}

std::optional<std::uint64_t>
ConstantFolder::fold_unsigned(const ast::Expression& expression) const {
    const Constant* constant = typed_constant(expression, nullptr);
    if (const auto* i = constant != nullptr ? std::get_if<std::int64_t>(constant) : nullptr) {
        return static_cast<std::uint64_t>(*i);
    }
    const auto* u = constant != nullptr ? std::get_if<std::uint64_t>(constant) : nullptr;
    return u != nullptr ? std::optional(*u) : std::nullopt;
}

const ast::Literal* ConstantFolder::literal(const ast::Expression& expression) const {
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        return &literal->value;
    }
    const ast::VariableDeclaration* declaration = constant(expression);
    return declaration != nullptr
               ? defining(*declaration, [&] { return literal(initial_value(*declaration)); })
               : nullptr;
}

std::optional<Constant> ConstantFolder::typed_as(const ast::Expression& expression,
                                                 const sema::Type& type) const {
    const Constant* constant = program_.constant_of(expression);
    const sema::Type* from = program_.type_of(expression);
    return constant != nullptr && from != nullptr ? convert(*constant, types_.unranged(*from), type)
                                                  : std::nullopt;
}

bool ConstantFolder::typed_fits(const ast::Expression& expression, const sema::Type& type) const {
    const Constant* constant = program_.constant_of(expression);
    const sema::Type* from = program_.type_of(expression);
    const auto into = constant != nullptr && from != nullptr
                          ? convert(*constant, types_.unranged(*from), type)
                          : std::nullopt;
    return into && same_number(*into, *constant);
}

std::optional<Constant> ConstantFolder::value(const ast::Expression& expression,
                                              const sema::Type& type) const {
    if (const sema::Symbol* value = types_.model().enum_value(expression)) {
        return as_constant(types_.enumerator(*value));
    }
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        return literal_value(literal->value, type);
    }
    if (const ast::VariableDeclaration* declaration = constant(expression)) {
        // A CONSTANT has the value its own type computes for its initial value.
        // Its initial value typed on demand where the typing pass has not reached it yet (a
        // CONSTANT of a VAR_GLOBAL CONSTANT used in a bound).
        const sema::Type* own = types_.resolve(declaration->type);
        if (own == nullptr) {
            return std::nullopt;
        }
        const ast::Expression& initial = initial_value(*declaration);
        const Constant* constant =
            defining(*declaration, [&] { return typed_constant(initial, own); });
        const sema::Type* from = constant != nullptr ? program_.type_of(initial) : nullptr;
        return from != nullptr ? convert(*constant, types_.unranged(*from), *own) : std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary_value(expression, *unary);
    }
    if (const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node)) {
        // Most operations are on variables: no constant, and nothing more to look at.
        if (program_.constant_of(*binary->left) == nullptr ||
            program_.constant_of(*binary->right) == nullptr) {
            return std::nullopt;
        }
        return binary_value(expression, *binary, type);
    }
    if (const auto* call = std::get_if<ast::CallExpression>(&expression.node)) {
        return call_value(expression, *call);
    }
    return std::nullopt;
}

} // namespace eposp::compiler::types
