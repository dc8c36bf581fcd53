#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "node_builder.hpp"
#include "token_cursor.hpp"

#include <optional>
#include <vector>

namespace eposp::compiler {

/// The grammar StructuredText.g4 as a hand-written recursive-descent parser that makes the AST
/// as it goes: the same language, the same choice where the grammar is ambiguous (ANTLR's: the
/// first alternative), and through `NodeBuilder` the same nodes and diagnostics, in the same
/// order, as the generated parser's tree walked by `AstBuilder`
/// (tests/compiler/parse/parser_equivalence_test.cpp holds the two to that). It does not
/// recover: at the first token it cannot take it gives up, and the generated parser reports
/// the syntax error. Recursion is bounded by `check_nesting`, run before.
class DescentParser {
public:
    DescentParser(const std::vector<antlr4::Token*>& tokens, FileId file, Diagnostics& diagnostics)
        : tokens_(tokens), cursor_(tokens), nodes_(file, diagnostics) {}

    /// The file's AST, or nothing when it has a syntax error.
    std::optional<ast::CompilationUnit> compilation_unit();
    /// The token it gave up at, after `compilation_unit()` gave nothing.
    const antlr4::Token* refused_at() const { return refused_at_; }

private:
    /// Where a type is written: what may follow it decides whether a name after an anonymous
    /// enumeration `(a, b)` is its base type. A function's result type is read with its
    /// optional end (`Result`) or without (`ResultWithoutEnd`), as the body after it decides.
    enum class TypePlace { Declaration, Variable, Result, ResultWithoutEnd };

    // descent_declarations.cpp
    void library_element(ast::CompilationUnit& unit);
    ast::TypeDeclaration type_declaration();
    ast::Pou pou(ast::PouKind kind);
    ast::Pou function_with_result(const antlr4::Token& start, ast::Pou function);
    void pou_body(const antlr4::Token& start, ast::Pou& pou);
    ast::Configuration configuration();
    ast::Resource resource_body(ast::Identifier name, std::optional<ast::Identifier> processor);
    ast::TaskDeclaration task();
    ast::ProgramInstance program_instance();
    std::vector<ast::DeclarationSection> sections();
    bool at_section() const;
    ast::DeclarationSection section();
    ast::AccessDeclaration access_declaration();
    ast::VariableDeclaration variable();

    // descent_initializers.cpp
    ast::InitializerPtr declaration_initializer();
    ast::InitializerPtr initializer();
    std::vector<ast::ArrayInitElement> array_elements();
    ast::ArrayInitElement array_element();

    // descent_types.cpp
    ast::TypeSpec type_spec(TypePlace place);
    ast::TypeSpec enum_type(TypePlace place);
    std::vector<ast::EnumValue> enum_values();
    ast::Subrange subrange();
    bool takes_enum_base(std::size_t ahead, TypePlace place) const;

    // descent_statements.cpp
    ast::StatementList statements(bool in_case_branch = false);
    bool at_statement(bool in_case_branch) const;
    bool at_case_label() const;
    ast::Statement statement();
    ast::Statement if_statement();
    ast::Statement case_statement();
    ast::CaseLabel case_label();
    ast::Statement for_statement();

    // descent_expressions.cpp
    ast::ExpressionPtr expression(int lowest_precedence = 1);
    ast::ExpressionPtr prefixed();
    ast::ExpressionPtr primary();
    ast::ExpressionPtr postfixed(ast::ExpressionPtr base);
    std::vector<ast::Argument> arguments();
    ast::Argument argument();
    /// An expression whose nodes the oracle does not make: parsed, its diagnostics dropped.
    void unused_expression();

    bool at_identifier(std::size_t ahead = 0) const;
    const antlr4::Token& expect_identifier();
    ast::Identifier identifier() { return nodes_.identifier(expect_identifier()); }
    SourceRange range_from(const antlr4::Token& start) const {
        return nodes_.range(start, cursor_.last());
    }

    const std::vector<antlr4::Token*>& tokens_; ///< with the pragmas, for attributes
    TokenCursor cursor_;
    NodeBuilder nodes_;
    const antlr4::Token* refused_at_ = nullptr;
};

/// True for a token an expression may start with.
bool starts_expression(std::size_t token_type);

} // namespace eposp::compiler
