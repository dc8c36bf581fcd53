#pragma once

// The typing pass over one program: walks every POU body and initial value, giving each
// expression its type from the bottom up, with the type its context expects passed down so
// that an untyped literal takes it (IEC 61131-3 ed. 3, 6.3.3).

#include "eposp/compiler/types/typed_program.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace eposp::compiler::types {

/// The operator a standard function of the arithmetic, logic or comparison family applies (ADD
/// is `+`, GT is `>`); none for the others.
std::optional<ast::BinaryOperator> operator_of(vm::stdlib::Operation operation);

/// The elementary type of the manifest's `type` (vm::NativeType lists them in
/// ast::ElementaryType's order, sema/type.cpp).
inline ast::ElementaryType elementary_of(vm::NativeType type) {
    return static_cast<ast::ElementaryType>(type);
}

class ExpressionTyper {
public:
    /// `model` resolves the names of what is typed: the program's, or the built-in library's
    /// for its POUs (type_library).
    ExpressionTyper(TypedProgram& program, const sema::SemanticModel& model,
                    Diagnostics& diagnostics);

    void pou(const ast::Pou& pou);
    void sections(const std::vector<ast::DeclarationSection>& sections);
    void configuration(const ast::Configuration& configuration);
    void type_declaration(const ast::TypeDeclaration& declaration);
    /// Types `expression` (`expected`: what its context needs) apart from the pass, for the
    /// constant folder (a bound, a CONSTANT used before its declaration is typed).
    void type_alone(const ast::Expression& expression, const sema::Type* expected) {
        type(expression, expected);
    }

private:
    using E = ast::ElementaryType;

    void type_spec(const ast::TypeSpec& spec);
    void statements(const ast::StatementList& list);
    void statement(const ast::Statement& statement);
    void initializer(const ast::Initializer& initializer, const sema::Type* target);
    /// A configuration's program instance: its program's instance type (null: none).
    const sema::Type* program_instance(const ast::ProgramInstance& instance);
    void connections(const ast::ProgramInstance& instance);
    /// The VAR_ACCESS paths of a configuration (access_paths.cpp).
    void access_paths(const ast::Configuration& configuration);
    void access_path(const ast::Configuration& configuration,
                     const ast::AccessDeclaration& declaration, std::set<std::string>& names);
    /// The type of the variable an access path names; null (reported) when there is none.
    const sema::Type* access_path_target(const ast::Configuration& configuration,
                                         const ast::AccessDeclaration& declaration);
    const sema::Type& address_type(const ast::DirectAddress& address);
    void condition(const ast::Expression& expression);
    /// A CASE label folds to a value of the selector's type (E0313, E0301).
    void case_label_constant(const ast::CaseLabel& label, const sema::Type& selector);
    /// Types `expression` where a value of `target` is expected, and checks that it converts.
    void expect(const ast::Expression& expression, const sema::Type& target, const char* what);
    /// expect(), for a value stored into a variable or parameter of type `target`.
    void store(const ast::Expression& expression, const sema::Type& target, const char* what);

    /// Records `value` as the constant of `expression` and whether it wraps (TypedProgram::
    /// wraps).
    void record_constant(const ast::Expression& expression, Constant value);
    /// The type of `expression`; `expected` is what its context needs (null: nothing).
    const sema::Type* type(const ast::Expression& expression, const sema::Type* expected);
    const sema::Type* literal(const ast::Expression& expression, const ast::Literal& literal,
                              const sema::Type* expected);
    const sema::Type* name(const ast::Expression& expression, const ast::NameExpression& node);
    const sema::Type* member(const ast::Expression& expression, const ast::MemberExpression& node);
    const sema::Type* index(const ast::Expression& expression, const ast::IndexExpression& node);
    const sema::Type* unary(const ast::Expression& expression, const ast::UnaryExpression& node,
                            const sema::Type* expected);
    const sema::Type* binary(const ast::Expression& expression, const ast::BinaryExpression& node,
                             const sema::Type* expected);
    const sema::Type* call(const ast::Expression& expression, const ast::CallExpression& node,
                           const sema::Type* expected);
    const sema::Type* pou_call(const ast::Expression& expression, const ast::CallExpression& node,
                               const ast::Pou& pou, const sema::Type* instance);
    const sema::Type* standard_call(const ast::Expression& expression,
                                    const ast::CallExpression& node, const std::string& name,
                                    const sema::Type* expected);
    /// ADD, SUB, MUL or DIV whose first input (`first`) is a time: the row of table 30 it takes
    /// (at each step of an extensible ADD or MUL, the last recorded).
    const sema::Type* time_call(const ast::Expression& expression,
                                const vm::stdlib::StandardFunction& function,
                                const std::vector<const ast::Expression*>& values,
                                const sema::Type& first);
    const sema::Type* conversion(const ast::Expression& expression, const ast::CallExpression& node,
                                 const std::string& name);
    /// The type `expression` names where SIZEOF sizes one (`SIZEOF(Axis)`, `SIZEOF(LREAL)`):
    /// a declared type, an FB, an elementary type; null if it names none.
    const sema::Type* named_type(const ast::Expression& expression);

    /// Both operands of a binary operator (or all inputs of a generic function) typed and
    /// brought to their common type; untyped literals take the others' type.
    /// `first`: the type of the first operand when it is already typed.
    const sema::Type* unify(const std::vector<const ast::Expression*>& operands,
                            const sema::Type* expected, const SourceRange& range,
                            const sema::Type* first = nullptr);
    /// Whether `operand` is an operation on small integers that an operator holds in DINT: an
    /// arithmetic binary operation or a negation (of no literal).
    bool held(const ast::Expression& operand) const;
    /// Holds `operand` (held()) in DINT: computed there, its constant as computed.
    void hold(const ast::Expression& operand);
    /// Records the type `expression`'s operands are computed in (TypedProgram::operands_of),
    /// `common` or DINT, and holds its arithmetic operands of small integers in DINT.
    void computed_in(const ast::Expression& expression, const ast::BinaryExpression& node,
                     const sema::Type& common);
    /// An input of EXPT (`**`) computed in `real`: an untyped integer literal is laid out in it
    /// where its own type widens to it (figure 11), as `r := 2` is.
    void power_input(const ast::Expression& input, const sema::Type& real);
    /// Records that the operator `expression` computes in `type`, its untyped literals too.
    void computed_at(const ast::Expression& expression, const sema::Type& type);
    /// A point in time or duration (`left`) added to or subtracted from `right`.
    const sema::Type* time_arithmetic(ast::BinaryOperator op, const sema::Type& left,
                                      const sema::Type& right, const SourceRange& range);
    /// The row of table 30 that `operation` (ADD, SUB, MUL, DIV, or their operator) takes on
    /// `left` and `right`: the first whose operand types both convert to (figure 11 widens TIME
    /// to LTIME, DATE to LDATE, TOD to LTOD, DT to LDT), so a short one where both are short; a
    /// scaled row takes any number. Null where table 30 has none (a date moved by a duration).
    const vm::stdlib::StandardFunction* time_row(vm::stdlib::Operation operation,
                                                 const sema::Type& left, const sema::Type& right);
    /// The smallest type both convert to implicitly (figure 11); null if there is none.
    const sema::Type* common(const sema::Type& a, const sema::Type& b);
    const sema::Type* variable_type(const sema::Symbol& symbol);
    /// Whether `expression` names a variable: what an output or a VAR_IN_OUT takes.
    bool is_variable(const ast::Expression& expression) const;
    /// Whether `expression` is a PROGRAM's name (`P.x`).
    bool names_program(const ast::Expression& expression) const;
    /// The arguments of a call except EN and ENO, in order.
    std::vector<const ast::Argument*> inputs(const ast::CallExpression& node);

    const sema::Type& elementary(E e) { return program_.types().elementary(e); }
    const sema::Type* fail(DiagnosticCode code, const SourceRange& range, std::string message);

    TypedProgram& program_;
    const sema::SemanticModel& model_;
    Diagnostics& diagnostics_;
    const ast::Pou* current_ = nullptr;
    /// The CONSTANT whose initial value is being typed (null: none), named where it is
    /// defined through itself.
    const ast::VariableDeclaration* defining_ = nullptr;
    /// The call of the CallStatement being typed: it needs no value.
    const ast::Expression* statement_call_ = nullptr;
};

/// An integer or real literal without a type prefix, or the negation of one: it takes the type
/// of its context.
bool is_untyped_literal(const ast::Expression& expression);

/// A literal whose type its context gives: an untyped number, a text (STRING or WSTRING of the
/// capacity it goes to) or NULL (the reference it goes to).
bool is_context_literal(const ast::Expression& expression);

/// Why a value of `actual` cannot be stored where `target` is expected (`what`: "a value", "an
/// initial value", "a CASE label", ...).
std::string mismatch(const char* what, const sema::Type& actual, const sema::Type& target);

/// Whether `type` is an elementary number or bit string: a context whose type an untyped
/// literal takes.
bool numeric_context(const sema::Type* type);

} // namespace eposp::compiler::types
