#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"

#include <Token.h>
#include <optional>
#include <utility>
#include <vector>

namespace eposp::compiler {

/// Makes AST nodes from tokens and nodes already made, with the checks the grammar leaves to
/// after parsing (literal values, addresses, task properties, qualifiers...). Shared by the
/// parser (`descent_parser.hpp`) and its oracle in tests, the parse-tree walk `AstBuilder`, so
/// that both make the same nodes and say the same things, in the same order.
class NodeBuilder {
public:
    NodeBuilder(FileId file, Diagnostics& diagnostics) : file_(file), diagnostics_(&diagnostics) {}

    FileId file() const { return file_; }
    /// A unit without declarations yet, whose arena the nodes made from now on go into.
    ast::CompilationUnit unit();
    /// A node in the arena of the last `unit()`.
    template <typename Node, typename... Args>
    ast::NodePtr<Node> make(Args&&... args) {
        return arena_->make<Node>(std::forward<Args>(args)...);
    }
    SourceRange range(const antlr4::Token& token) const;
    /// From `first` to `last`; only `first` when the rule matched nothing (`last` before it).
    SourceRange range(const antlr4::Token& first, const antlr4::Token* last) const;

    /// A name; `ON` as a name is warned about once per file.
    ast::Identifier identifier(const antlr4::Token& token);
    ast::ExpressionPtr literal(const antlr4::Token& token);
    std::optional<ast::DirectAddress> direct_address(const antlr4::Token& token);

    ast::ExpressionPtr name(const antlr4::Token& token);
    ast::ExpressionPtr binary(std::size_t op, ast::ExpressionPtr left, ast::ExpressionPtr right);
    ast::ExpressionPtr unary(const antlr4::Token& op, ast::ExpressionPtr operand);
    ast::ExpressionPtr member(ast::ExpressionPtr base, ast::Identifier name);
    ast::ExpressionPtr bit_access(ast::ExpressionPtr base, const antlr4::Token& dot,
                                  const antlr4::Token& bit);
    ast::ExpressionPtr index(ast::ExpressionPtr base, std::vector<ast::ExpressionPtr> indices,
                             const antlr4::Token& close);
    ast::ExpressionPtr call(ast::ExpressionPtr callee, std::vector<ast::Argument> arguments,
                            const antlr4::Token& close);
    ast::ExpressionPtr dereference(ast::ExpressionPtr base, const antlr4::Token& caret);
    /// `MOD(a, b)`: a call of a function named like the operator.
    ast::ExpressionPtr operator_call(const antlr4::Token& callee,
                                     std::vector<ast::Argument> arguments, SourceRange whole);
    ast::ExpressionPtr direct_address_expression(const antlr4::Token& address);
    ast::ExpressionPtr reference(ast::ExpressionPtr inner, SourceRange whole);

    /// Before the value of `target := value` is made.
    void check_assignment_target(const ast::Expression& target);
    /// `target;`: a call, or a statement that does nothing.
    ast::Statement call_statement(SourceRange whole, ast::ExpressionPtr target);

    /// Where the value of a task property goes, or null (reported) when it has none.
    ast::ExpressionPtr* task_property(ast::TaskDeclaration& task, const ast::Identifier& name);
    void check_task(const ast::TaskDeclaration& task);

    static ast::VarSectionKind section_kind(std::size_t token);
    /// RETAIN, NON_RETAIN or PERSISTENT; null for none.
    static ast::Retention retention(const antlr4::Token* qualifier);
    /// The section after one more qualifier (CONSTANT, RETAIN, NON_RETAIN, PERSISTENT).
    static void qualify(ast::VarSection& section, const antlr4::Token& qualifier);
    void check_qualifiers(const ast::VarSection& section);
    /// A section at the top level of a file; false (reported) unless it is VAR_GLOBAL.
    bool check_global_list(const ast::DeclarationSection& section, const antlr4::Token& start);
    /// `a, b AT %IX1.0`: the address of a declaration, after its type and names.
    void locate(ast::VariableDeclaration& declaration, const antlr4::Token& address);
    ast::InitializerPtr bare_array_initializer(std::vector<ast::ArrayInitElement> elements,
                                               SourceRange whole);

    static ast::TypeSpec named_type(ast::Identifier name);
    /// `STRING[10]`, `STRING(10)`, or `DWORD (Red)`: a typed enumeration of one value.
    ast::TypeSpec sized_type(SourceRange whole, ast::Identifier base, ast::ExpressionPtr length,
                             bool parenthesized);

    /// The attribute pragmas just before `tokens[index]` (other pragmas are not attributes).
    std::vector<ast::Attribute> attributes_before(const std::vector<antlr4::Token*>& tokens,
                                                  std::size_t index);

    /// Where diagnostics go and whether `ON` was warned about: set aside by the parser where it
    /// makes nodes in another order than the oracle, to replay or drop what they say.
    struct Sink {
        Diagnostics* diagnostics;
        bool warned_about_on;
    };
    Sink sink() const { return {diagnostics_, warned_about_on_}; }
    void set_sink(Sink sink) {
        diagnostics_ = sink.diagnostics;
        warned_about_on_ = sink.warned_about_on;
    }

private:
    void error(DiagnosticCode code, const SourceRange& range, std::string message);
    void warning(DiagnosticCode code, const SourceRange& range, std::string message);
    template <typename Node>
    ast::ExpressionPtr expression(SourceRange range, Node&& node) {
        return make<ast::Expression>(range, std::forward<Node>(node));
    }

    FileId file_;
    ast::NodeArena* arena_ = nullptr;
    Diagnostics* diagnostics_;
    bool warned_about_on_ = false;
};

} // namespace eposp::compiler
