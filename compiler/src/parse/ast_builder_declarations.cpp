#include "ast_builder.hpp"
#include "eposp/compiler/ascii_case.hpp"

#include <cctype>
#include <charconv>

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

ast::VarSectionKind section_kind(std::size_t token) {
    switch (token) {
    case P::VAR_INPUT:
        return ast::VarSectionKind::Input;
    case P::VAR_OUTPUT:
        return ast::VarSectionKind::Output;
    case P::VAR_IN_OUT:
        return ast::VarSectionKind::InOut;
    case P::VAR_TEMP:
        return ast::VarSectionKind::Temp;
    case P::VAR_GLOBAL:
        return ast::VarSectionKind::Global;
    case P::VAR_EXTERNAL:
        return ast::VarSectionKind::External;
    default:
        return ast::VarSectionKind::Var;
    }
}

ast::Retention retention_of(const antlr4::Token* token) {
    if (token == nullptr) {
        return ast::Retention::Unspecified;
    }
    // RETAIN, or CODESYS's PERSISTENT, which is kept the same way here.
    return token->getType() == P::NON_RETAIN ? ast::Retention::NonRetain : ast::Retention::Retain;
}

} // namespace

ast::CompilationUnit build_ast(P::CompilationUnitContext& tree, antlr4::BufferedTokenStream& tokens,
                               FileId file, Diagnostics& diagnostics) {
    return AstBuilder(tokens, file, diagnostics).compilation_unit(tree);
}

ast::CompilationUnit AstBuilder::compilation_unit(P::CompilationUnitContext& context) {
    ast::CompilationUnit unit{file_, {}, {}, {}, {}};
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
    const auto* variables = std::get_if<ast::VarSection>(&section);
    if (variables == nullptr || variables->kind != ast::VarSectionKind::Global) {
        error(DiagnosticCode::E0109, range(*context.getStart()),
              "only VAR_GLOBAL can be declared outside a POU or configuration");
        return;
    }
    lists.push_back(std::move(section));
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
        result.resources.push_back(
            resource(*declared->resourceBody(), identifier(*declared->identifier(0)),
                     identifier(*declared->identifier(1)), range(*declared)));
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

// IEC 61131-3 ed. 3, 6.8.2, table 63: SINGLE, INTERVAL and PRIORITY, each at most once.
ast::TaskDeclaration AstBuilder::task(P::TaskDeclarationContext& context) {
    ast::TaskDeclaration result;
    result.attributes = attributes_before(context);
    result.name = identifier(*context.identifier());
    result.range = range(context);
    for (P::TaskPropertyContext* property : context.taskProperty()) {
        const ast::Identifier name = identifier(*property->identifier());
        ast::ExpressionPtr* slot = equal_ignoring_case(name.name, "SINGLE")     ? &result.single
                                   : equal_ignoring_case(name.name, "INTERVAL") ? &result.interval
                                   : equal_ignoring_case(name.name, "PRIORITY") ? &result.priority
                                                                                : nullptr;
        if (slot == nullptr) {
            error(DiagnosticCode::E0110, name.range,
                  "unknown task property '" + name.name +
                      "'; a task has SINGLE, INTERVAL and PRIORITY");
            continue;
        }
        if (*slot) {
            error(DiagnosticCode::E0110, name.range,
                  "task property '" + name.name + "' is given twice");
            continue;
        }
        *slot = expression(*property->expression());
    }
    if (!result.priority) {
        error(DiagnosticCode::E0110, result.name.range,
              "task '" + result.name.name + "' needs a PRIORITY");
    }
    return result;
}

ast::ProgramInstance AstBuilder::program_instance(P::ProgramConfigurationContext& context) {
    ast::ProgramInstance result;
    const std::vector<P::IdentifierContext*> names = context.identifier();
    result.name = identifier(*names.front());
    result.retention = retention_of(context.retention);
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
                    if (auto address = direct_address(*path.DIRECT_ADDRESS()->getSymbol())) {
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
        built.kind = section_kind(variables.kind->getType());
        built.range = range(variables);
        for (P::VarQualifierContext* qualifier : variables.varQualifier()) {
            if (qualifier->CONSTANT() != nullptr) {
                built.constant = true;
            } else {
                built.retention = retention_of(qualifier->getStart());
            }
        }
        if (built.constant && built.retention == ast::Retention::Retain) {
            error(DiagnosticCode::E0111, built.range, "a CONSTANT section cannot be RETAIN");
        }
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
        if (result.names.size() > 1) {
            error(DiagnosticCode::E0112, result.names[1].range,
                  "AT locates a single variable; declare '" + result.names[1].name +
                      "' separately");
        }
        result.address = direct_address(*context.DIRECT_ADDRESS()->getSymbol());
    }
    return result;
}

// IEC 61131-3 ed. 3, 6.5.5, table 16: %, I/Q/M, an optional size X/B/W/D/L, then a
// hierarchical address `0.0` or `*` for a location assigned in VAR_CONFIG.
std::optional<ast::DirectAddress> AstBuilder::direct_address(antlr4::Token& token) {
    const std::string text = token.getText();
    ast::DirectAddress address;
    address.range = range(token);
    const char area = static_cast<char>(std::toupper(static_cast<unsigned char>(text[1])));
    address.area = area == 'I'   ? ast::DirectAddress::Area::Input
                   : area == 'Q' ? ast::DirectAddress::Area::Output
                                 : ast::DirectAddress::Area::Memory;
    std::size_t position = 2;
    static constexpr std::pair<char, ast::DirectAddress::Size> kSizes[] = {
        {'X', ast::DirectAddress::Size::Bit},      {'B', ast::DirectAddress::Size::Byte},
        {'W', ast::DirectAddress::Size::Word},     {'D', ast::DirectAddress::Size::DoubleWord},
        {'L', ast::DirectAddress::Size::LongWord},
    };
    for (const auto& [letter, size] : kSizes) {
        if (position < text.size() &&
            std::toupper(static_cast<unsigned char>(text[position])) == letter) {
            address.size = size;
            ++position;
            break;
        }
    }
    while (position < text.size() && text[position] != '*') {
        std::uint32_t part = 0;
        const auto [end, status] =
            std::from_chars(text.data() + position, text.data() + text.size(), part);
        if (status != std::errc{}) {
            error(DiagnosticCode::E0113, address.range,
                  "address part in '" + text + "' is too large");
            return std::nullopt;
        }
        address.path.push_back(part);
        position = static_cast<std::size_t>(end - text.data()) + 1; // past the '.'
    }
    return address;
}

ast::InitializerPtr AstBuilder::initializer(P::InitializerContext* context) {
    if (context == nullptr) {
        return nullptr;
    }
    auto result = std::make_unique<ast::Initializer>();
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
    auto result = std::make_unique<ast::Initializer>();
    result->range = range(*bare);
    result->value = array_elements(bare->arrayInitElement());
    warning(DiagnosticCode::W0101, result->range,
            "array initial values without brackets are a CODESYS V2 form; IEC "
            "61131-3 (6.4.4.5) writes them in brackets: [1, 2, 3]");
    return result;
}

std::vector<ast::ArrayInitElement>
AstBuilder::array_elements(const std::vector<P::ArrayInitElementContext*>& contexts) {
    std::vector<ast::ArrayInitElement> elements;
    for (P::ArrayInitElementContext* element : contexts) {
        ast::ExpressionPtr count = element->INTEGER() != nullptr
                                       ? literal_expression(*element->INTEGER()->getSymbol())
                                       : nullptr;
        elements.push_back({std::move(count), initializer(element->initializer())});
    }
    return elements;
}

} // namespace eposp::compiler
