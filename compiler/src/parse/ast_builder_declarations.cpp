#include "ast_builder.hpp"

namespace eposp::compiler {

ast::CompilationUnit build_ast(generated::StructuredTextParser::CompilationUnitContext& tree,
                               antlr4::BufferedTokenStream& tokens, FileId file,
                               Diagnostics& diagnostics) {
    return AstBuilder(tokens, file, diagnostics).compilation_unit(tree);
}

ast::CompilationUnit AstBuilder::compilation_unit(P::CompilationUnitContext& context) {
    ast::CompilationUnit unit = nodes_.unit();
    for (P::LibraryElementContext* element : context.libraryElement()) {
        library_element(*element, unit);
    }
    return unit;
}

void AstBuilder::library_element(P::LibraryElementContext& element, ast::CompilationUnit& unit) {
    if (auto* types = element.typeDeclarationBlock()) {
        for (P::TypeDeclarationContext* declaration : types->typeDeclaration()) {
            unit.types.push_back(type_declaration(*declaration));
        }
    } else if (auto* function_context = element.functionDeclaration()) {
        unit.pous.push_back(function(*function_context));
    } else if (auto* block = element.functionBlockDeclaration()) {
        unit.pous.push_back(function_block(*block));
    } else if (auto* program_context = element.programDeclaration()) {
        unit.pous.push_back(program(*program_context));
    } else if (auto* configuration_context = element.configurationDeclaration()) {
        unit.configurations.push_back(configuration(*configuration_context));
    } else if (auto* variables = element.varSection()) {
        global_variable_list(*variables, unit.global_variable_lists);
    }
}

void AstBuilder::global_variable_list(P::VarSectionContext& context,
                                      std::vector<ast::DeclarationSection>& lists) {
    ast::DeclarationSection section = std::move(sections({&context}).front());
    if (nodes_.check_global_list(section, *context.getStart())) {
        lists.push_back(std::move(section));
    }
}

ast::TypeDeclaration AstBuilder::type_declaration(P::TypeDeclarationContext& context) {
    return {identifier(*context.identifier()), type_spec(*context.typeSpec()),
            declaration_initializer(context.declarationInitializer()), range(context)};
}

ast::Pou AstBuilder::function(P::FunctionDeclarationContext& context) {
    ast::Pou pou;
    pou.kind = ast::PouKind::Function;
    pou.name = identifier(*context.identifier());
    if (context.typeSpec() != nullptr) {
        pou.return_type = type_spec(*context.typeSpec());
    }
    pou.sections = sections(context.varSection());
    pou.body = statements(context.statementList());
    pou.range = range(context);
    return pou;
}

ast::Pou AstBuilder::function_block(P::FunctionBlockDeclarationContext& context) {
    ast::Pou pou;
    pou.kind = ast::PouKind::FunctionBlock;
    const std::vector<P::IdentifierContext*> names = context.identifier();
    pou.name = identifier(*names[0]);
    std::size_t next = 1;
    if (context.EXTENDS() != nullptr) {
        pou.extends = identifier(*names[next++]);
    }
    for (; next < names.size(); ++next) {
        pou.implements.push_back(identifier(*names[next]));
    }
    pou.sections = sections(context.varSection());
    pou.body = statements(context.statementList());
    pou.range = range(context);
    return pou;
}

ast::Pou AstBuilder::program(P::ProgramDeclarationContext& context) {
    ast::Pou pou;
    pou.kind = ast::PouKind::Program;
    pou.name = identifier(*context.identifier());
    pou.sections = sections(context.varSection());
    pou.body = statements(context.statementList());
    pou.range = range(context);
    return pou;
}

// IEC 61131-3 ed. 3, 6.8.
ast::Configuration AstBuilder::configuration(P::ConfigurationDeclarationContext& context) {
    ast::Configuration result;
    result.name = identifier(*context.identifier());
    result.sections = sections(context.varSection());
    for (P::ResourceDeclarationContext* declared : context.resourceDeclaration()) {
        // The names in the order they are written (`ON` as either is warned about once).
        ast::Identifier name = identifier(*declared->identifier(0));
        ast::Identifier processor = identifier(*declared->identifier(1));
        result.resources.push_back(resource(*declared->resourceBody(), std::move(name),
                                            std::move(processor), range(*declared)));
    }
    if (auto* implicit = context.resourceBody()) {
        result.resources.push_back(resource(*implicit, result.name, std::nullopt, range(context)));
    }
    result.range = range(context);
    return result;
}

ast::Resource AstBuilder::resource(P::ResourceBodyContext& body, ast::Identifier name,
                                   std::optional<ast::Identifier> processor, SourceRange where) {
    ast::Resource result;
    result.name = std::move(name);
    result.processor = std::move(processor);
    result.sections = sections(body.varSection());
    for (P::TaskDeclarationContext* declared : body.taskDeclaration()) {
        result.tasks.push_back(task(*declared));
    }
    for (P::ProgramConfigurationContext* instance : body.programConfiguration()) {
        result.programs.push_back(program_instance(*instance));
    }
    result.range = where;
    return result;
}

ast::TaskDeclaration AstBuilder::task(P::TaskDeclarationContext& context) {
    ast::TaskDeclaration result;
    result.attributes =
        nodes_.attributes_before(tokens_.getTokens(), context.getStart()->getTokenIndex());
    result.name = identifier(*context.identifier());
    result.range = range(context);
    for (P::TaskPropertyContext* property : context.taskProperty()) {
        if (ast::ExpressionPtr* slot =
                nodes_.task_property(result, identifier(*property->identifier()))) {
            *slot = expression(*property->expression());
        }
    }
    nodes_.check_task(result);
    return result;
}

ast::ProgramInstance AstBuilder::program_instance(P::ProgramConfigurationContext& context) {
    ast::ProgramInstance result;
    const std::vector<P::IdentifierContext*> names = context.identifier();
    result.name = identifier(*names.front());
    result.retention = NodeBuilder::retention(context.retention);
    if (context.WITH() != nullptr) {
        result.task = identifier(*names[1]);
    }
    result.type = identifier(*names.back());
    result.connections = arguments(context.argumentList());
    result.range = range(context);
    return result;
}

std::vector<ast::DeclarationSection>
AstBuilder::sections(const std::vector<P::VarSectionContext*>& all) {
    std::vector<ast::DeclarationSection> result;
    for (P::VarSectionContext* section : all) {
        if (auto* access = alternative<P::AccessSectionContext>(section)) {
            ast::AccessSection built;
            built.range = range(*access);
            for (P::AccessDeclarationContext* declaration : access->accessDeclaration()) {
                P::AccessPathContext& path = *declaration->accessPath();
                ast::AccessDeclaration entry{identifier(*declaration->identifier()),
                                             {},
                                             type_spec(*declaration->typeSpec()),
                                             declaration->READ_WRITE() != nullptr,
                                             range(*declaration)};
                if (path.DIRECT_ADDRESS() != nullptr) {
                    if (auto address =
                            nodes_.direct_address(*path.DIRECT_ADDRESS()->getSymbol())) {
                        entry.path = std::move(*address);
                    }
                } else {
                    std::vector<ast::Identifier> parts;
                    for (P::IdentifierContext* part : path.identifier()) {
                        parts.push_back(identifier(*part));
                    }
                    entry.path = std::move(parts);
                }
                built.paths.push_back(std::move(entry));
            }
            result.emplace_back(std::move(built));
            continue;
        }
        auto& variables = static_cast<P::VariableSectionContext&>(*section);
        ast::VarSection built;
        built.kind = NodeBuilder::section_kind(variables.kind->getType());
        built.range = range(variables);
        for (P::VarQualifierContext* qualifier : variables.varQualifier()) {
            NodeBuilder::qualify(built, *qualifier->getStart());
        }
        nodes_.check_qualifiers(built);
        for (P::VarDeclarationContext* declaration : variables.varDeclaration()) {
            built.variables.push_back(variable(*declaration));
        }
        result.emplace_back(std::move(built));
    }
    return result;
}

ast::VariableDeclaration AstBuilder::variable(P::VarDeclarationContext& context) {
    ast::VariableDeclaration result{{},
                                    std::nullopt,
                                    type_spec(*context.typeSpec()),
                                    declaration_initializer(context.declarationInitializer()),
                                    range(context)};
    for (P::IdentifierContext* name : context.identifier()) {
        result.names.push_back(identifier(*name));
    }
    if (context.AT() != nullptr) {
        nodes_.locate(result, *context.DIRECT_ADDRESS()->getSymbol());
    }
    return result;
}

ast::InitializerPtr AstBuilder::initializer(P::InitializerContext* context) {
    if (context == nullptr) {
        return nullptr;
    }
    auto result = make<ast::Initializer>();
    result->range = range(*context);
    if (auto* array = alternative<P::ArrayInitializerContext>(context)) {
        result->value = array_elements(array->arrayInitElement());
    } else if (auto* structure = alternative<P::StructInitializerContext>(context)) {
        std::vector<ast::StructInitElement> elements;
        for (P::StructInitElementContext* element : structure->structInitElement()) {
            elements.push_back(
                {identifier(*element->identifier()), initializer(element->initializer())});
        }
        result->value = std::move(elements);
    } else {
        result->value =
            expression(*static_cast<P::ExpressionInitializerContext&>(*context).expression());
    }
    return result;
}

ast::InitializerPtr AstBuilder::declaration_initializer(P::DeclarationInitializerContext* context) {
    if (auto* bracketed = alternative<P::BracketedInitializerContext>(context)) {
        return initializer(bracketed->initializer());
    }
    auto* bare = alternative<P::BareArrayInitializerContext>(context);
    if (bare == nullptr) {
        return nullptr;
    }
    return nodes_.bare_array_initializer(array_elements(bare->arrayInitElement()), range(*bare));
}

std::vector<ast::ArrayInitElement>
AstBuilder::array_elements(const std::vector<P::ArrayInitElementContext*>& contexts) {
    std::vector<ast::ArrayInitElement> elements;
    for (P::ArrayInitElementContext* element : contexts) {
        ast::ExpressionPtr count = element->INTEGER() != nullptr
                                       ? nodes_.literal(*element->INTEGER()->getSymbol())
                                       : nullptr;
        elements.push_back({std::move(count), initializer(element->initializer())});
    }
    return elements;
}

} // namespace eposp::compiler
