#pragma once

// The tree walker: runs the typed program's statements and expressions by the rules of
// IEC 61131-3 ed. 3 and the project's documented choices (docs/st-language.md), over values
// held per variable (value.hpp).

#include "eposp/compiler/types/front_end.hpp"
#include "value.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace eposp::reference {

namespace ast = compiler::ast;
namespace types = compiler::types;

class Evaluator {
public:
    /// Lays out every global and program instance and finds the first task; throws Unsupported for
    /// what it does not model.
    explicit Evaluator(std::unique_ptr<types::FrontEnd> front_end);

    /// One scan of the first task at the clock `now_ns`; throws Fault or Unsupported.
    void scan(std::int64_t now_ns);
    /// A variable by its path (`Main.x`, `Inst0.s.a`, `Config0.g`, `g`, `Main.a[2]`).
    const Value* find(const std::string& path) const;

private:
    /// Where the names of the POU being run live.
    struct Frame {
        const ast::Pou* pou = nullptr;
        Value* instance = nullptr;                            ///< FB or PROGRAM instance
        std::unordered_map<std::string, Value> locals{};      ///< FUNCTION variables, VAR_TEMP
        std::unordered_map<std::string, Value*> references{}; ///< VAR_IN_OUT
    };
    enum class Flow { Next, Exit, Continue, Return };

    // Set-up (evaluator.cpp).
    Value make(const sema::Type& type, const ast::Initializer* initializer);
    /// Whether `pou` is a standard FB of the built-in library (modelled, not run).
    bool is_library(const ast::Pou* pou) const;
    void initialise(Value& value, const ast::Initializer& initializer);
    /// A FUNCTION's variables, or an FB's or PROGRAM's VAR_TEMP, fresh for one call.
    void locals(const ast::Pou& pou, Frame& frame, bool temporaries_only);
    /// The instance a PROGRAM's name reaches (`P()`, `P.x`, docs/st-language.md "Calling a
    /// PROGRAM"): the configuration's only one, or one made for the calls, named after it.
    Value& instance_of(const ast::Pou& program);

    // Statements (statements.cpp).
    Flow statements(const ast::StatementList& list);
    Flow statement(const ast::Statement& statement);
    Flow for_loop(const ast::ForStatement& node);
    void step();

    // Expressions (expressions.cpp).
    Value eval(const ast::Expression& expression);
    const sema::Type& type_of(const ast::Expression& expression);
    Value& place(const ast::Expression& expression);
    Value* variable(const ast::Identifier& name);
    Value constant(const types::Constant& constant, const sema::Type& type);
    Value unary(const ast::Expression& expression, const ast::UnaryExpression& node);
    Value binary(const ast::Expression& expression, const ast::BinaryExpression& node);
    Value power(const Value& base, const Value& exponent, const sema::Type& type);
    Value time_arithmetic(ast::BinaryOperator op, const Value& left, const Value& right,
                          const sema::Type& type);
    Value arithmetic(ast::BinaryOperator op, const Value& left, const Value& right,
                     const sema::Type& type);
    bool compare(ast::BinaryOperator op, const Value& left, const Value& right);
    int order(const Value& left, const Value& right);
    /// `value` stored into a variable of `type`: cut to its width or length, checked against a
    /// subrange (6.4.4.4).
    Value store(const Value& value, const sema::Type& type);
    /// `value` widened to `type` for an operation (figure 11); small integers stay in DINT.
    Value widen(const Value& value, const sema::Type& type);
    const sema::Type& working(const sema::Type& type);
    const sema::Type& elementary(ast::ElementaryType e);
    /// Stops the scan with a run-time fault, named as the VM names it, at the current line.
    [[noreturn]] void fault(const std::string& what);

    // Calls (calls.cpp).
    Value call(const ast::Expression& expression, const ast::CallExpression& node);
    /// The call itself, once EN allows it.
    Value execute(const types::CallTarget* target, const ast::CallExpression& node);
    /// A user POU, or (`standard` its name) a standard FB modelled in
    /// standard_function_blocks.cpp.
    Value pou_call(const ast::CallExpression& node, const ast::Pou& pou, Value* instance,
                   const std::string& standard = {});
    Value standard_function(const types::CallTarget& target, const ast::CallExpression& node);
    Value string_function(const std::string& name, const std::vector<Value>& in,
                          const sema::Type& result);
    Value conversion(const types::CallTarget& target, const Value& value);
    void standard_function_block(const std::string& name, Value& instance);

    std::unique_ptr<types::FrontEnd> front_end_;
    types::TypedProgram& program_;
    std::int64_t now_ns_ = 0;
    std::uint64_t steps_ = 0;
    /// Configuration globals and global variable lists, by folded name.
    std::unordered_map<std::string, Value> globals_;
    /// Program instances by folded name.
    std::unordered_map<std::string, Value> instances_;
    /// Each PROGRAM's instances (values in instances_, which never moves them).
    std::unordered_map<const ast::Pou*, std::vector<Value*>> instances_of_;
    /// Symbol paths (folded) to the variable: `CONFIG0.G`, `G`, `MAIN`.
    std::unordered_map<std::string, Value*> roots_;
    /// What the first task runs: each program instance with its PROGRAM, in order.
    std::vector<std::pair<const ast::Pou*, Value*>> task_;
    Frame* frame_ = nullptr; ///< the POU being run
    int line_ = 0;           ///< the line of the statement being run, for fault texts
    /// The last call that EN skipped: an assignment of it keeps its target.
    const ast::Expression* skipped_ = nullptr;
};

} // namespace eposp::reference
