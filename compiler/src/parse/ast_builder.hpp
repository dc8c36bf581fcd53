#pragma once

#include "StructuredTextParser.h"
#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"

#include <typeinfo>

namespace eposp::compiler {

/// Turns a parse tree without syntax errors into our typed AST: literal values decoded, names
/// and locations kept, everything the grammar matched loosely checked here with a precise
/// message. The parse tree can be dropped afterwards.
ast::CompilationUnit build_ast(generated::StructuredTextParser::CompilationUnitContext& tree,
                               antlr4::BufferedTokenStream& tokens, FileId file,
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
        : tokens_(tokens), file_(file), diagnostics_(diagnostics) {}

    ast::CompilationUnit compilation_unit(P::CompilationUnitContext& context);
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
    std::optional<ast::DirectAddress> direct_address(antlr4::Token& token);
    ast::InitializerPtr initializer(P::InitializerContext* context);
    ast::InitializerPtr declaration_initializer(P::DeclarationInitializerContext* context);
    std::vector<ast::ArrayInitElement>
    array_elements(const std::vector<P::ArrayInitElementContext*>& contexts);

    // ast_builder_attributes.cpp
    /// The attribute pragmas just above `context` (other pragmas are not attributes).
    std::vector<ast::Attribute> attributes_before(antlr4::ParserRuleContext& context);

    // ast_builder_types.cpp
    ast::TypeSpec type_spec(P::TypeSpecContext& context);

    // ast_builder_statements.cpp
    ast::StatementList statements(P::StatementListContext* context);
    ast::Statement statement(P::StatementContext& context);

    // ast_builder_expressions.cpp
    ast::ExpressionPtr expression(P::ExpressionContext& context);
    std::vector<ast::Argument> arguments(P::ArgumentListContext* context);
    ast::ExpressionPtr literal_expression(antlr4::Token& token);

    ast::Identifier identifier(P::IdentifierContext& context);
    SourceRange range(antlr4::ParserRuleContext& context) const;
    SourceRange range(antlr4::Token& token) const;
    void error(DiagnosticCode code, const SourceRange& range, std::string message);
    void warning(DiagnosticCode code, const SourceRange& range, std::string message);

private:
    ast::ExpressionPtr unary_expression(P::UnaryExpressionContext& context);
    ast::ExpressionPtr bit_access(P::MemberAccessContext& context); ///< `x.3`

    antlr4::BufferedTokenStream& tokens_; ///< with the pragmas on its hidden channel
    FileId file_;
    Diagnostics& diagnostics_;
    bool warned_about_on_ = false;
};

} // namespace eposp::compiler
