#pragma once

// The one constant evaluator of the compiler (IEC 61131-3 ed. 3, 6.4.2, 6.5.1.3): the value of
// a constant expression as the expression computes at run time. The type table asks it for
// bounds, lengths and enumeration values (sema::IntegerConstants), the typing stage for initial
// values (initial_constant.cpp) and for the constant of every typed expression
// (TypedProgram::constant_of), the checks and code generation for CASE labels, FOR steps,
// constant indices and divisors.

#include "eposp/compiler/sema/integer_constants.hpp"
#include "eposp/compiler/sema/type_table.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace eposp::compiler::types {

class ConstantEvaluator final : public sema::IntegerConstants {
public:
    /// `program` gives the types of what it has typed; `types` may be still under
    /// construction: it is used only when asked.
    ConstantEvaluator(const TypedProgram& program, sema::TypeTable& types)
        : program_(program), types_(types) {}

    std::optional<std::int64_t> fold_integer(const ast::Expression& expression) const override;
    std::optional<std::uint64_t> fold_unsigned(const ast::Expression& expression) const override;
    std::optional<std::uint64_t> fold_as(const ast::Expression& expression,
                                         const sema::Type& type) const override;

    /// A constant REAL or LREAL expression (`1.0 / 3.0`, `Ratio * 2.0`), each part the typing
    /// stage typed computed in its type (`kSeven / 2` is 3.0, `kTenth * kThird` a REAL product
    /// in an LREAL too); `single`: a REAL (where the part is not typed),
    /// whose every value and operation rounds to single precision as it does at run time
    /// (`16777216.0 + 1.0 + 1.0` is 16777216.0, not 16777218.0 rounded once at the end).
    std::optional<double> real(const ast::Expression& expression, bool single) const;
    /// A constant duration or point in time in ns (table 30: `T#1ms * 4`, `DT#... + T#1h`);
    /// `day_wraps`: a TIME_OF_DAY, whose sums wrap around midnight (not folded).
    std::optional<std::int64_t> time(const ast::Expression& expression, bool day_wraps) const;
    /// A BOOL constant: TRUE, FALSE, a BOOL CONSTANT, and NOT, AND, OR, XOR of those.
    std::optional<bool> boolean(const ast::Expression& expression) const;
    /// The literal an expression is or a CONSTANT names (a STRING's, a CHAR's, NULL).
    const ast::Literal* literal(const ast::Expression& expression) const;

    /// The constant of an expression of `type` as the typing stage records it, bottom up from
    /// its operands' (constant_operations.cpp): literals, enumeration values, CONSTANTs (their
    /// value as their own type computes it), operators, conversions and the pure standard
    /// functions (ABS, MOVE, ADD..., AND..., GT..., SHL..., SEL, MUX, MIN, MAX, LIMIT), each
    /// computed as the VM computes it.
    std::optional<Constant> value(const ast::Expression& expression, const sema::Type& type) const;
    /// The constant the typing stage recorded for `expression` (constant_of), as a value of
    /// `type`; none where it recorded none or it does not convert.
    std::optional<Constant> typed_as(const ast::Expression& expression,
                                     const sema::Type& type) const;
    /// Whether that constant, an integer, is a value of `type` unchanged (no bits cut).
    bool typed_fits(const ast::Expression& expression, const sema::Type& type) const;
    /// `constant`, a value of `from`, as a value of `to`, converted as the VM converts
    /// (integers wrap, reals round to nearest and saturate); none between other kinds of value.
    std::optional<Constant> convert(const Constant& constant, const sema::Type& from,
                                    const sema::Type& to) const;

private:
    /// How folded integer arithmetic wraps: in `bits` (32 or 64), signed or not; `type`: the
    /// integer type computed for (fold_as), whose own bits NOT flips.
    struct Arithmetic {
        bool is_unsigned = false;
        unsigned bits = 64;
        const sema::Type* type = nullptr;
    };
    std::optional<std::uint64_t> integer(const ast::Expression& expression,
                                         Arithmetic arithmetic) const;
    /// Whether `expression` has `type` at run time: its literals untyped or of that type, its
    /// constants declared with it, so that NOT flips that type's bits.
    bool computes_in(const ast::Expression& expression, const sema::Type& type) const;
    /// The declaration of the CONSTANT `expression` names, with a plain initial value; null
    /// when it names none, or one being evaluated (a constant defined through itself).
    const ast::VariableDeclaration* constant(const ast::Expression& expression) const;
    static const ast::Expression& initial_value(const ast::VariableDeclaration& declaration) {
        return *std::get<ast::ExpressionPtr>(declaration.initial_value->value);
    }
    /// value() of a CONSTANT's initial value, as its declared type `own` computes it: folded
    /// (folded_value), else the typing stage's constant of it (typed_as).
    std::optional<Constant> own_value(const ast::Expression& initial, const sema::Type& own) const;
    std::optional<Constant> folded_value(const ast::Expression& initial,
                                         const sema::Type& own) const;
    /// `evaluate()` with the constant `declaration` marked as being evaluated.
    template <typename Evaluate>
    auto within(const ast::VariableDeclaration& declaration, Evaluate evaluate) const
        -> decltype(evaluate()) {
        evaluating_.insert(&declaration);
        auto value = evaluate();
        evaluating_.erase(&declaration);
        return value;
    }

    /// A constant with the type the VM holds it in.
    struct Held {
        Constant value;
        const sema::Type* type = nullptr;
    };
    /// An operand's constant as its operator reads it (codegen's operand_value): an
    /// arithmetic operation on small integers as computed, in DINT; else its constant.
    std::optional<Held> held(const ast::Expression& expression) const;
    /// A binary operator's operands, as held, converted to `computed` and operated on there.
    std::optional<Constant> operation(const ast::BinaryExpression& node,
                                      const sema::Type& computed) const;
    std::optional<Constant> unary_value(const ast::UnaryExpression& node) const;
    std::optional<Constant> binary_value(const ast::Expression& expression,
                                         const ast::BinaryExpression& node,
                                         const sema::Type& type) const;
    /// Time and date arithmetic (table 30), which has no operands_of.
    std::optional<Constant> time_value(const ast::BinaryExpression& node,
                                       const sema::Type& type) const;
    std::optional<Constant> call_value(const ast::Expression& expression,
                                       const ast::CallExpression& node) const;

    const TypedProgram& program_;
    sema::TypeTable& types_;
    /// The values of arithmetic on small integers computed wider than their type (held()).
    mutable std::unordered_map<const ast::Expression*, Constant> held_;
    mutable std::unordered_set<const ast::VariableDeclaration*> evaluating_;
};

} // namespace eposp::compiler::types
