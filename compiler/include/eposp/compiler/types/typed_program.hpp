#pragma once

// The typing stage (issue 16): every expression of a parsed, name-resolved program with its IEC
// type, its value when constant, and for every call what it calls. It owns the type rules of
// IEC 61131-3 ed. 3 (implicit widening of figure 11, ANY_* generic functions and operators,
// untyped literals taking the type their context needs, conversions, calls) and the choices
// docs/st-language.md documents where the standard leaves them open.

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/node_map.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"
#include "eposp/compiler/sema/type_table.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <variant>
#include <vector>

namespace eposp::compiler::types {

class ConstantFolder;

/// A folded constant: BOOL, a signed or unsigned integer (also bit strings, TIME and dates in
/// ns, enumeration values), a real number, a STRING's characters (Latin-1 bytes) or a WSTRING's
/// (UTF-16 units).
using Constant =
    std::variant<bool, std::int64_t, std::uint64_t, double, std::string, std::u16string>;

enum class CallKind {
    Function,              ///< a user FUNCTION
    FunctionBlock,         ///< an instance of a user FUNCTION_BLOCK
    StandardFunction,      ///< ed. 3, 6.6.2.5: ABS, SEL, CONCAT, ...
    Conversion,            ///< `<T>_TO_<U>`, `TO_<U>`, TRUNC (6.6.2.5.3)
    StandardFunctionBlock, ///< an instance of SR, TON, CTU, ... (6.6.3.5)
};

/// A value stored into a variable or parameter: an assignment's value, an initial value (or one
/// element of an array's or structure's), a call's input.
struct Store {
    const ast::Expression* value = nullptr;
    const sema::Type* into = nullptr; ///< the variable's or parameter's declared type
    const ast::Pou* pou = nullptr;    ///< the POU it is in; null outside POUs (globals, types)
};

/// What a call expression calls.
struct CallTarget {
    CallKind kind = CallKind::Function;
    /// The user FUNCTION or FB, or the library POU of a standard FB; null for functions.
    const ast::Pou* pou = nullptr;
    /// The standard function or FB, upper case (`LIMIT`, `DINT_TO_UDINT`, `TON`).
    std::string name{};
    /// The overload chosen: the type of a generic function's ANY_* inputs (`MAX` on INT), the
    /// source of a conversion; null where the function has none.
    const sema::Type* operand = nullptr;
    /// The result's type (null for an FB call used as a statement).
    const sema::Type* result = nullptr;
};

/// A VAR_ACCESS path as the typing stage resolved it (types/access_paths.cpp): the program
/// instance or global variable it starts at (its name, case-folded) and the members below it,
/// a leading resource name dropped. A direct address (`%IW4`) has none: it is its own target.
struct AccessPath {
    std::string variable;
    std::vector<std::string> members;
};

class TypedProgram {
public:
    TypedProgram(const sema::SemanticModel& model,
                 std::function<const ast::Pou*(std::string_view)> library,
                 std::function<bool(const ast::VariableDeclaration&)> is_constant,
                 Diagnostics& diagnostics);
    ~TypedProgram();
    TypedProgram(const TypedProgram&) = delete;
    TypedProgram& operator=(const TypedProgram&) = delete;

    /// The IEC type of an expression of the program; null when it was not typed (an error
    /// was reported, or the expression names a type or POU rather than a value).
    const sema::Type* type_of(const ast::Expression& expression) const;
    /// Its value when it is constant (a literal, a CONSTANT, an enumeration value, an
    /// operation on constants).
    const Constant* constant_of(const ast::Expression& expression) const;
    /// Whether an integer operation wrapped around computing that value, the expression's own
    /// or an operand's (`32767 + 1` in INT): it is not the number the expression means, which
    /// an initial value refuses (E0311).
    bool wraps(const ast::Expression& expression) const { return wrapping_.contains(&expression); }
    /// What a CallExpression calls; null for any other expression.
    const CallTarget* call_target(const ast::Expression& expression) const;
    /// The type a BinaryExpression's operands are both brought to and the operation computed
    /// in: their common type, or DINT for small integers inside an expression (CODESYS, see
    /// docs/st-language.md). Null for `**`, time arithmetic, `TIME * n` and pointer moves.
    const sema::Type* operands_of(const ast::Expression& expression) const;

    /// What a VAR_ACCESS declaration names; null for a direct address or a path refused.
    const AccessPath* access_path(const ast::AccessDeclaration& declaration) const;

    /// Every value stored, in the order of the program (checks/constant_subranges.cpp).
    const std::vector<Store>& stores() const { return stores_; }

    /// Whether a declaration is in a CONSTANT section.
    bool is_constant(const ast::VariableDeclaration& declaration) const {
        return is_constant_(declaration);
    }
    const sema::SemanticModel& model() const { return model_; }
    /// The POU of the built-in library (stdlib/standard_library_source.cpp) implementing a
    /// standard FB or host function of that name; null if there is none.
    const ast::Pou* library_pou(std::string_view name) const { return library_(name); }
    sema::TypeTable& types() { return types_; }
    const sema::TypeTable& types() const { return types_; }
    /// The one folder of constant expressions (types/constant_folder.hpp).
    const ConstantFolder& constants() const { return *folder_; }

    // Construction, used by the typing pass.
    void set_type(const ast::Expression& expression, const sema::Type& type);
    void set_constant(const ast::Expression& expression, Constant value);
    void set_wraps(const ast::Expression& expression, bool wraps);
    void set_call(const ast::Expression& expression, CallTarget target);
    void set_operands(const ast::Expression& expression, const sema::Type& type);
    void add_store(Store store) { stores_.push_back(store); }
    void set_access_path(const ast::AccessDeclaration& declaration, AccessPath path);

private:
    const sema::SemanticModel& model_;
    std::function<const ast::Pou*(std::string_view)> library_;
    std::function<bool(const ast::VariableDeclaration&)> is_constant_;
    // Before types_, which it is handed: the folder asks the table for constants' types and
    // the table asks it for bounds.
    std::unique_ptr<ConstantFolder> folder_;
    sema::TypeTable types_;
    sema::NodeMap<ast::Expression, sema::Type> types_of_;
    sema::NodeMap<ast::Expression, sema::Type> operands_of_;
    // Constants and call targets stay where they are made (deques), so that the pointers
    // constant_of() and call_target() hand out stay valid; a value set again is made anew.
    std::deque<Constant> constant_values_;
    sema::NodeMap<ast::Expression, Constant> constants_;
    std::deque<CallTarget> call_targets_;
    sema::NodeMap<ast::Expression, CallTarget> calls_;
    std::unordered_set<const ast::Expression*> wrapping_;
    std::vector<Store> stores_;
    std::unordered_map<const ast::AccessDeclaration*, AccessPath> access_paths_;
};

/// Types every expression of `units` (POU bodies, initial values, CASE labels, FOR bounds,
/// program connections) against `model`; type errors go to `diagnostics`. `library` finds the
/// POU implementing a standard FB (for its instance layout).
std::unique_ptr<TypedProgram> type_program(std::span<const ast::CompilationUnit> units,
                                           const sema::SemanticModel& model,
                                           std::function<const ast::Pou*(std::string_view)> library,
                                           Diagnostics& diagnostics);

/// Types the POUs of the built-in library (stdlib/standard_library_source.cpp), whose names
/// `model` resolves, into `program`: code generation generates their bodies like the program's
/// and reads their types here. Their layouts are the program's TypeTable's, where code
/// generation lays them out.
void type_library(TypedProgram& program, std::span<const ast::CompilationUnit> units,
                  const sema::SemanticModel& model, Diagnostics& diagnostics);

} // namespace eposp::compiler::types

namespace eposp::compiler::types {

/// The inputs of a call of the standard function `name` (upper case) in the order of its
/// signature (`IN1, IN2, ...`; `G, IN0, IN1`; `IN, L, P`; ...), written positionally or
/// formally in any order; EN and ENO are left out. Null where an input name is unknown.
std::vector<const ast::Argument*> standard_arguments(std::string_view name,
                                                     const ast::CallExpression& call);

} // namespace eposp::compiler::types
