#pragma once

// The one constant folder of the compiler (IEC 61131-3 ed. 3, 6.4.2, 6.5.1.3): the constant the
// typing stage records for every expression it types (TypedProgram::constant_of), the value the
// expression computes at run time. What the type table asks for before the typing pass reaches
// it (array and subrange bounds, string lengths, enumeration values: sema::IntegerConstants), and
// a CONSTANT's value before its declaration is typed, it types on demand with the same rules.
// The typing stage reads it for initial values (initial_constant.cpp) and CASE labels, the
// checks and code generation for CASE labels, FOR steps, constant indices and divisors.

#include "eposp/compiler/sema/integer_constants.hpp"
#include "eposp/compiler/sema/type_table.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <optional>
#include <unordered_set>
#include <vector>

namespace eposp::compiler::types {

/// Whether two integer constants are the same number, each held signed or unsigned.
bool same_number(const Constant& a, const Constant& b);

class ConstantFolder final : public sema::IntegerConstants {
public:
    /// `program` gives the types and constants of what it has typed, and takes those typed
    /// on demand; `types` may be still under construction: it is used only when asked.
    ConstantFolder(TypedProgram& program, sema::TypeTable& types)
        : program_(program), types_(types) {}

    /// The constant of `expression` as a signed number (a ULINT above LINT's range is none),
    /// the expression typed on demand if the typing pass has not reached it.
    std::optional<std::int64_t> fold_integer(const ast::Expression& expression) const override;
    /// The same as 64 bits, a negative number as its two's complement (the CASE labels of a
    /// ULINT or LWORD selector).
    std::optional<std::uint64_t> fold_unsigned(const ast::Expression& expression) const;
    /// The literal an expression is or a CONSTANT names (NULL): what an initial value of a
    /// reference takes.
    const ast::Literal* literal(const ast::Expression& expression) const;

    /// The constant of an expression of `type` as the typing stage records it, bottom up from
    /// its operands' (constant_operations.cpp): literals, enumeration values, CONSTANTs (their
    /// value as their own type computes it), operators, conversions and the pure standard
    /// functions (ABS, MOVE, ADD..., AND..., GT..., SHL..., SEL, MUX, MIN, MAX, LIMIT, the real
    /// functions, table 30, LOWER_BOUND, UPPER_BOUND, the string functions), each computed as
    /// the VM computes it.
    std::optional<Constant> value(const ast::Expression& expression, const sema::Type& type) const;
    /// The constant the typing stage recorded for `expression` (constant_of), as a value of
    /// `type`; none where it recorded none or it does not convert.
    std::optional<Constant> typed_as(const ast::Expression& expression,
                                     const sema::Type& type) const;
    /// Whether that constant, an integer, is a value of `type` unchanged (no bits cut).
    bool typed_fits(const ast::Expression& expression, const sema::Type& type) const;
    /// `constant`, a value of `from`, as a value of `to`, converted as the VM converts
    /// (integers wrap, reals round to nearest and saturate, a text is cut at a STRING's
    /// capacity); none between other kinds of value.
    std::optional<Constant> convert(const Constant& constant, const sema::Type& from,
                                    const sema::Type& to) const;
    /// The arithmetic operation or negation `expression` on constants as computed in its
    /// operands' type (operands_of), not cut to its own type: its value where its operator
    /// holds it in DINT (the typing stage's hold()).
    std::optional<Constant> computed(const ast::Expression& expression) const;
    /// Whether the operator of `expression` wrapped around computing its constant from its
    /// operands' (`32767 + 1` in INT, `0 - 1` in UDINT, a result computed in DINT cut to its
    /// INT): the constant is not the number the expression means.
    bool wraps(const ast::Expression& expression) const;

    /// `evaluate()` with the CONSTANT `declaration` marked as being defined: a use of it
    /// meanwhile is a constant defined through itself (circular()).
    template <typename Evaluate>
    auto defining(const ast::VariableDeclaration& declaration, Evaluate evaluate) const
        -> decltype(evaluate()) {
        struct Marked {
            std::vector<const ast::VariableDeclaration*>& evaluating;
            bool outer;
            ~Marked() {
                if (outer) {
                    evaluating.pop_back();
                }
            }
        } marked{evaluating_, enter(declaration)};
        return evaluate();
    }
    /// Whether the CONSTANT `declaration` was used while it was being defined, or is one of the
    /// CONSTANTs that such a use went through (`a := b + 1; b := a + 1`: both).
    bool circular(const ast::VariableDeclaration& declaration) const {
        return circular_.contains(&declaration);
    }

private:
    /// Marks `declaration` as being defined, above the CONSTANTs whose definitions use it;
    /// false when it is already.
    bool enter(const ast::VariableDeclaration& declaration) const;
    /// The declaration of the CONSTANT `expression` names, with a plain initial value; null
    /// when it names none, or one being defined (recorded as circular).
    const ast::VariableDeclaration* constant(const ast::Expression& expression) const;
    static const ast::Expression& initial_value(const ast::VariableDeclaration& declaration) {
        return *std::get<ast::ExpressionPtr>(declaration.initial_value->value);
    }
    /// The constant of `expression`, typed on demand (where `expected`) when the typing pass
    /// has not typed it yet: a bound, a CONSTANT's initial value used before it is declared.
    const Constant* typed_constant(const ast::Expression& expression,
                                   const sema::Type* expected) const;

    /// A constant with the type the VM holds it in.
    struct Held {
        Constant value;
        const sema::Type* type = nullptr;
    };
    /// An operand's constant as its operator reads it (codegen's operand_value): an
    /// arithmetic operation or negation on small integers as computed, in DINT; else its
    /// constant.
    std::optional<Held> held(const ast::Expression& expression) const;
    /// A binary operator's operands, as held, converted to `computed` and operated on there.
    std::optional<Constant> operation(const ast::BinaryExpression& node,
                                      const sema::Type& computed) const;
    /// `-x`: its operand, as held, converted to `computed` and negated there.
    std::optional<Constant> negation(const ast::UnaryExpression& node,
                                     const sema::Type& computed) const;
    std::optional<Constant> unary_value(const ast::Expression& expression,
                                        const ast::UnaryExpression& node) const;
    std::optional<Constant> binary_value(const ast::Expression& expression,
                                         const ast::BinaryExpression& node,
                                         const sema::Type& type) const;
    std::optional<Constant> call_value(const ast::Expression& expression,
                                       const ast::CallExpression& node) const;

    // The families folded by the VM's own functions, each in its file.
    /// SQRT ... ATAN2, EXPT of `inputs`, values of `real` (constant_real_functions.cpp).
    std::optional<Constant> real_function(std::string_view name,
                                          const std::vector<Constant>& inputs,
                                          const sema::Type& real) const;
    /// `a ** b` of the real type `type`.
    std::optional<Constant> power_value(const ast::BinaryExpression& node,
                                        const sema::Type& type) const;
    /// Time and date arithmetic (table 30), which has no operands_of
    /// (constant_time_operations.cpp).
    std::optional<Constant> time_value(const ast::BinaryExpression& node,
                                       const sema::Type& type) const;
    /// A point in time or duration moved by a duration, or two subtracted, into `result`.
    std::optional<Constant> moved_time(bool add, std::int64_t left, std::int64_t right,
                                       const sema::Type& result) const;
    /// A duration times or divided by a number.
    std::optional<Constant> scaled_time(bool multiply, std::int64_t time, const Constant& factor,
                                        const sema::Type& factor_type) const;
    /// ADD_TIME, ADD_TOD_TIME, MUL_TIME ... of `values`, of `types`.
    std::optional<Constant> time_function(std::string_view name,
                                          const std::vector<Constant>& values,
                                          const std::vector<const sema::Type*>& types,
                                          const sema::Type& result) const;
    /// A conversion `from` -> `to` (table 22) as code generation's explicit_convert: convert()
    /// and to and from the times (TIME_TO_DINT, DINT_TO_TIME, DT_TO_DATE) and the texts.
    std::optional<Constant> explicit_conversion(const Constant& constant, const sema::Type& from,
                                                const sema::Type& to) const;
    /// A conversion to or from a STRING or WSTRING: INT_TO_STRING, STRING_TO_REAL,
    /// CHAR_TO_STRING, STRING_TO_WSTRING... (constant_text_conversions.cpp).
    std::optional<Constant> text_conversion(const Constant& constant, const sema::Type& from,
                                            const sema::Type& to) const;
    /// LOWER_BOUND or UPPER_BOUND of an array of fixed bounds (constant_array_bounds.cpp).
    std::optional<Constant> bound_value(const ast::CallExpression& node, bool upper) const;
    /// LEN, LEFT ... FIND of `values` (the texts, then the lengths and positions), a value of
    /// `result` (constant_texts.cpp).
    std::optional<Constant> text_function(std::string_view name,
                                          const std::vector<Constant>& values,
                                          const sema::Type& result) const;

    TypedProgram& program_;
    sema::TypeTable& types_;
    /// The CONSTANTs being defined, each used by the definition of the one below it.
    mutable std::vector<const ast::VariableDeclaration*> evaluating_;
    mutable std::unordered_set<const ast::VariableDeclaration*> circular_;
};

} // namespace eposp::compiler::types
