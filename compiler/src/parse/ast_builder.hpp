#pragma once

#include "StructuredTextParser.h"
#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "node_builder.hpp"

#include <typeinfo>

namespace eposp::compiler {

/// Turns a parse tree without syntax errors into our typed AST, with the nodes and checks of
/// `NodeBuilder`. The product parses with the hand-written `DescentParser`; this walk of the
/// generated parser's tree is its oracle in tests/compiler/parse/parser_equivalence_test.cpp.
ast::CompilationUnit build_ast(generated::StructuredTextParser::CompilationUnitContext& tree,
                               antlr4::BufferedTokenStream& tokens, FileId file,
                               Diagnostics& diagnostics);

/// `parse_tokens` as it was before the hand-written parser: the generated parser with SLL
/// prediction, one library element at a time, each tree turned into its AST; on a syntax error
/// the whole file again with LL prediction and recovery, its tree built when it has none.
ast::CompilationUnit parse_tokens_with_tree(antlr4::TokenSource& lexer, FileId file,
                                            Diagnostics& diagnostics);

/// The context of one labelled alternative (`# name` in the grammar), or null. The type is
/// compared exactly: a dynamic_cast walks the class hierarchy and costs several times as much,
/// and the builder asks for every node.
template <typename Alternative, typename Rule>
Alternative* alternative(Rule* context) {
    return context != nullptr && typeid(*context) == typeid(Alternative)
               ? static_cast<Alternative*>(context)
               : nullptr;
}

/// The builder's state, shared by its parts (declarations, statements, expressions), each in
/// its own file.
class AstBuilder {
public:
    using P = generated::StructuredTextParser;

    AstBuilder(antlr4::BufferedTokenStream& tokens, FileId file, Diagnostics& diagnostics)
        : tokens_(tokens), nodes_(file, diagnostics) {}

    ast::CompilationUnit compilation_unit(P::CompilationUnitContext& context);
    /// A unit without declarations yet, whose arena the nodes made from now on go into.
    ast::CompilationUnit unit() { return nodes_.unit(); }
    template <typename Node, typename... Args>
    ast::NodePtr<Node> make(Args&&... args) {
        return nodes_.make<Node>(std::forward<Args>(args)...);
    }
    /// Adds a TYPE block, POU, configuration or global variable list to `unit`.
    void library_element(P::LibraryElementContext& context, ast::CompilationUnit& unit);

    // ast_builder_declarations.cpp
    ast::TypeDeclaration type_declaration(P::TypeDeclarationContext& context);
    /// A VAR_GLOBAL section at the top level of a file, appended to `lists`.
    void global_variable_list(P::VarSectionContext& context,
                              std::vector<ast::DeclarationSection>& lists);
    ast::Pou function(P::FunctionDeclarationContext& context);
    ast::Pou function_block(P::FunctionBlockDeclarationContext& context);
    ast::Pou program(P::ProgramDeclarationContext& context);
    ast::Configuration configuration(P::ConfigurationDeclarationContext& context);
    ast::Resource resource(P::ResourceBodyContext& body, ast::Identifier name,
                           std::optional<ast::Identifier> processor, SourceRange range);
    ast::TaskDeclaration task(P::TaskDeclarationContext& context);
    ast::ProgramInstance program_instance(P::ProgramConfigurationContext& context);
    std::vector<ast::DeclarationSection> sections(const std::vector<P::VarSectionContext*>& all);
    ast::VariableDeclaration variable(P::VarDeclarationContext& context);
    ast::InitializerPtr initializer(P::InitializerContext* context);
    ast::InitializerPtr declaration_initializer(P::DeclarationInitializerContext* context);
    std::vector<ast::ArrayInitElement>
    array_elements(const std::vector<P::ArrayInitElementContext*>& contexts);

    // ast_builder_types.cpp
    ast::TypeSpec type_spec(P::TypeSpecContext& context);

    // ast_builder_statements.cpp
    ast::StatementList statements(P::StatementListContext* context);
    ast::Statement statement(P::StatementContext& context);

    // ast_builder_expressions.cpp
    ast::ExpressionPtr expression(P::ExpressionContext& context);
    std::vector<ast::Argument> arguments(P::ArgumentListContext* context);
    ast::Argument argument(P::ArgumentContext& context);

    ast::Identifier identifier(P::IdentifierContext& context);
    SourceRange range(antlr4::ParserRuleContext& context) const;

private:
    antlr4::BufferedTokenStream& tokens_; ///< with the pragmas on its hidden channel
    NodeBuilder nodes_;
};

} // namespace eposp::compiler
