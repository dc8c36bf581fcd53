// Library elements and declarations (grammar rules `compilationUnit` to `accessPath`,
// IEC 61131-3 ed. 3, 6.1, 6.5 and 6.8).
#include "StructuredTextParser.h"
#include "descent_parser.hpp"

#include <limits>

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

bool is_variable_section(std::size_t token) {
    switch (token) {
    case P::VAR:
    case P::VAR_INPUT:
    case P::VAR_OUTPUT:
    case P::VAR_IN_OUT:
    case P::VAR_TEMP:
    case P::VAR_GLOBAL:
    case P::VAR_EXTERNAL:
        return true;
    default:
        return false;
    }
}

bool is_qualifier(std::size_t token) {
    return token == P::CONSTANT || token == P::RETAIN || token == P::NON_RETAIN ||
           token == P::PERSISTENT;
}

} // namespace

std::optional<ast::CompilationUnit> DescentParser::compilation_unit() {
    ast::CompilationUnit unit = nodes_.unit();
    try {
        while (!cursor_.at(antlr4::Token::EOF)) {
            library_element(unit);
        }
    } catch (const ParseBail&) {
        refused_at_ = &cursor_.peek();
        return std::nullopt;
    }
    return unit;
}

void DescentParser::library_element(ast::CompilationUnit& unit) {
    switch (cursor_.type()) {
    case P::TYPE:
        cursor_.take();
        do {
            unit.types.push_back(type_declaration());
        } while (at_identifier());
        cursor_.expect(P::END_TYPE);
        return;
    case P::FUNCTION:
        unit.pous.push_back(pou(ast::PouKind::Function));
        return;
    case P::FUNCTION_BLOCK:
        unit.pous.push_back(pou(ast::PouKind::FunctionBlock));
        return;
    case P::PROGRAM:
        unit.pous.push_back(pou(ast::PouKind::Program));
        return;
    case P::CONFIGURATION:
        unit.configurations.push_back(configuration());
        return;
    default:
        break;
    }
    if (!at_section()) {
        throw ParseBail{};
    }
    const antlr4::Token& start = cursor_.peek();
    ast::DeclarationSection variables = section();
    if (nodes_.check_global_list(variables, start)) {
        unit.global_variable_lists.push_back(std::move(variables));
    }
}

ast::TypeDeclaration DescentParser::type_declaration() {
    const antlr4::Token& start = cursor_.peek();
    ast::Identifier name = identifier();
    cursor_.expect(P::COLON);
    ast::TypeSpec type = type_spec(TypePlace::Declaration);
    ast::InitializerPtr value = cursor_.accept(P::ASSIGN) ? declaration_initializer() : nullptr;
    cursor_.accept(P::SEMICOLON);
    return {std::move(name), std::move(type), std::move(value), range_from(start)};
}

ast::Pou DescentParser::pou(ast::PouKind kind) {
    const antlr4::Token& start = cursor_.take();
    ast::Pou result;
    result.kind = kind;
    result.name = identifier();
    if (kind == ast::PouKind::Function && cursor_.accept(P::COLON)) {
        return function_with_result(start, std::move(result));
    }
    if (kind == ast::PouKind::FunctionBlock) {
        if (cursor_.accept(P::EXTENDS)) {
            result.extends = identifier();
        }
        if (cursor_.accept(P::IMPLEMENTS)) {
            do {
                result.implements.push_back(identifier());
            } while (cursor_.accept(P::COMMA));
        }
    }
    pou_body(start, result);
    return result;
}

// The optional end of a result type (a base type after an enumeration, `(a, b) x`; a length or
// values after a name, `INT (x)`) may also begin the body (`x;`, `(x) := 1;`). ANTLR reads the
// longer type, its first alternative, when the function parses so, the shorter one otherwise:
// the function is parsed the first way, what it says kept apart, and again the second way
// should the first fail.
ast::Pou DescentParser::function_with_result(const antlr4::Token& start, ast::Pou function) {
    const TokenCursor::Mark mark = cursor_.mark();
    const NodeBuilder::Sink outer = nodes_.sink();
    Diagnostics said(std::numeric_limits<std::size_t>::max());
    nodes_.set_sink({&said, outer.warned_about_on});
    ast::Pou longer;
    longer.kind = function.kind;
    longer.name = function.name;
    try {
        longer.return_type = type_spec(TypePlace::Result);
        pou_body(start, longer);
    } catch (const ParseBail&) {
        cursor_.reset(mark);
        nodes_.set_sink(outer);
        function.return_type = type_spec(TypePlace::ResultWithoutEnd);
        pou_body(start, function);
        return function;
    }
    nodes_.set_sink({outer.diagnostics, nodes_.sink().warned_about_on});
    for (const Diagnostic& diagnostic : said.all()) {
        outer.diagnostics->report(diagnostic);
    }
    return longer;
}

void DescentParser::pou_body(const antlr4::Token& start, ast::Pou& pou) {
    pou.sections = sections();
    pou.body = statements();
    cursor_.expect(pou.kind == ast::PouKind::Function        ? P::END_FUNCTION
                   : pou.kind == ast::PouKind::FunctionBlock ? P::END_FUNCTION_BLOCK
                                                             : P::END_PROGRAM);
    pou.range = range_from(start);
}

// A configuration's sections come before its resources, or before the body of its one implicit
// resource, which then spans the whole configuration.
ast::Configuration DescentParser::configuration() {
    const antlr4::Token& start = cursor_.take();
    ast::Configuration result;
    result.name = identifier();
    result.sections = sections();
    if (cursor_.at(P::RESOURCE)) {
        do {
            const antlr4::Token& resource_start = cursor_.take();
            ast::Identifier name = identifier();
            cursor_.expect(P::ON);
            ast::Identifier processor = identifier();
            result.resources.push_back(resource_body(std::move(name), std::move(processor)));
            cursor_.expect(P::END_RESOURCE);
            result.resources.back().range = range_from(resource_start);
        } while (cursor_.at(P::RESOURCE));
        cursor_.expect(P::END_CONFIGURATION);
    } else {
        result.resources.push_back(resource_body(result.name, std::nullopt));
        cursor_.expect(P::END_CONFIGURATION);
        result.resources.back().range = range_from(start);
    }
    result.range = range_from(start);
    return result;
}

ast::Resource DescentParser::resource_body(ast::Identifier name,
                                           std::optional<ast::Identifier> processor) {
    ast::Resource result;
    result.name = std::move(name);
    result.processor = std::move(processor);
    result.sections = sections();
    while (cursor_.at(P::TASK)) {
        result.tasks.push_back(task());
    }
    while (cursor_.at(P::PROGRAM)) {
        result.programs.push_back(program_instance());
    }
    return result;
}

// The values of properties the oracle does not make (unknown or repeated) say nothing.
ast::TaskDeclaration DescentParser::task() {
    const antlr4::Token& start = cursor_.take();
    ast::TaskDeclaration result;
    result.attributes = nodes_.attributes_before(tokens_, start.getTokenIndex());
    result.name = identifier();
    cursor_.expect(P::LEFT_PAREN);
    do {
        ast::ExpressionPtr* slot = nodes_.task_property(result, identifier());
        cursor_.expect(P::ASSIGN);
        if (slot != nullptr) {
            *slot = expression();
        } else {
            unused_expression();
        }
    } while (cursor_.accept(P::COMMA));
    cursor_.expect(P::RIGHT_PAREN);
    cursor_.expect(P::SEMICOLON);
    result.range = range_from(start);
    nodes_.check_task(result);
    return result;
}

ast::ProgramInstance DescentParser::program_instance() {
    const antlr4::Token& start = cursor_.take();
    ast::ProgramInstance result;
    const antlr4::Token* retention = nullptr;
    if (cursor_.at(P::RETAIN) || cursor_.at(P::NON_RETAIN)) {
        retention = &cursor_.take();
    }
    result.name = identifier();
    result.retention = NodeBuilder::retention(retention);
    if (cursor_.accept(P::WITH)) {
        result.task = identifier();
    }
    cursor_.expect(P::COLON);
    result.type = identifier();
    if (cursor_.accept(P::LEFT_PAREN)) {
        result.connections = arguments();
        cursor_.expect(P::RIGHT_PAREN);
    }
    cursor_.expect(P::SEMICOLON);
    result.range = range_from(start);
    return result;
}

std::vector<ast::DeclarationSection> DescentParser::sections() {
    std::vector<ast::DeclarationSection> result;
    while (at_section()) {
        result.push_back(section());
    }
    return result;
}

bool DescentParser::at_section() const {
    return is_variable_section(cursor_.type()) || cursor_.at(P::VAR_ACCESS);
}

ast::DeclarationSection DescentParser::section() {
    const antlr4::Token& start = cursor_.take();
    if (start.getType() == P::VAR_ACCESS) {
        ast::AccessSection built;
        while (at_identifier()) {
            built.paths.push_back(access_declaration());
        }
        cursor_.expect(P::END_VAR);
        built.range = range_from(start);
        return built;
    }
    ast::VarSection built;
    built.kind = NodeBuilder::section_kind(start.getType());
    while (is_qualifier(cursor_.type())) {
        NodeBuilder::qualify(built, cursor_.take());
    }
    if (built.constant && built.retention == ast::Retention::Retain) {
        // Reported before the declarations, over the whole section: up to its END_VAR, the
        // first one ahead, as no declaration holds one.
        std::size_t end = 0;
        while (cursor_.type(end) != P::END_VAR && cursor_.type(end) != antlr4::Token::EOF) {
            ++end;
        }
        built.range = nodes_.range(start, &cursor_.peek(end));
        nodes_.check_qualifiers(built);
    }
    while (at_identifier()) {
        built.variables.push_back(variable());
    }
    cursor_.expect(P::END_VAR);
    built.range = range_from(start);
    return built;
}

// The oracle makes the access path after the type.
ast::AccessDeclaration DescentParser::access_declaration() {
    const antlr4::Token& start = cursor_.peek();
    ast::Identifier name = identifier();
    cursor_.expect(P::COLON);
    std::vector<const antlr4::Token*> path;
    if (cursor_.at(P::DIRECT_ADDRESS)) {
        path.push_back(&cursor_.take());
    } else {
        do {
            path.push_back(&expect_identifier());
        } while (cursor_.accept(P::DOT));
    }
    cursor_.expect(P::COLON);
    ast::TypeSpec type = type_spec(TypePlace::Variable);
    const bool read_write = cursor_.at(P::READ_WRITE);
    if (read_write || cursor_.at(P::READ_ONLY)) {
        cursor_.take();
    }
    cursor_.expect(P::SEMICOLON);
    ast::AccessDeclaration entry{std::move(name), {}, std::move(type), read_write,
                                 range_from(start)};
    if (path.front()->getType() == P::DIRECT_ADDRESS) {
        if (auto address = nodes_.direct_address(*path.front())) {
            entry.path = std::move(*address);
        }
    } else {
        std::vector<ast::Identifier> parts;
        for (const antlr4::Token* part : path) {
            parts.push_back(nodes_.identifier(*part));
        }
        entry.path = std::move(parts);
    }
    return entry;
}

// The oracle makes the type and initial value first, then the names, then the address.
ast::VariableDeclaration DescentParser::variable() {
    const antlr4::Token& start = cursor_.peek();
    std::vector<const antlr4::Token*> names;
    do {
        names.push_back(&expect_identifier());
    } while (cursor_.accept(P::COMMA));
    const antlr4::Token* address = nullptr;
    if (cursor_.accept(P::AT)) {
        address = &cursor_.expect(P::DIRECT_ADDRESS);
    }
    cursor_.expect(P::COLON);
    ast::TypeSpec type = type_spec(TypePlace::Variable);
    ast::InitializerPtr value = cursor_.accept(P::ASSIGN) ? declaration_initializer() : nullptr;
    cursor_.expect(P::SEMICOLON);
    ast::VariableDeclaration result{
        {}, std::nullopt, std::move(type), std::move(value), range_from(start)};
    result.names.reserve(names.size());
    for (const antlr4::Token* name : names) {
        result.names.push_back(nodes_.identifier(*name));
    }
    if (address != nullptr) {
        nodes_.locate(result, *address);
    }
    return result;
}

} // namespace eposp::compiler
