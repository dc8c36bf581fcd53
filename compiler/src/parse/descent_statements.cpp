// Statements (grammar rules `statementList` to `caseLabel`, IEC 61131-3 ed. 3, 7.3.3).
#include "StructuredTextParser.h"
#include "descent_parser.hpp"

#include <limits>

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

bool starts_keyword_statement(std::size_t token) {
    switch (token) {
    case P::IF:
    case P::CASE:
    case P::FOR:
    case P::WHILE:
    case P::REPEAT:
    case P::EXIT:
    case P::CONTINUE:
    case P::RETURN:
    case P::SEMICOLON:
        return true;
    default:
        return false;
    }
}

} // namespace

ast::StatementList DescentParser::statements(bool in_case_branch) {
    ast::StatementList result;
    while (at_statement(in_case_branch)) {
        result.push_back(statement());
    }
    return result;
}

// In a CASE branch, an expression followed by ':', ',' or '..' starts the next branch's labels.
bool DescentParser::at_statement(bool in_case_branch) const {
    const std::size_t type = cursor_.type();
    if (starts_keyword_statement(type)) {
        return true;
    }
    return starts_expression(type) && !(in_case_branch && at_case_label());
}

// Looks past the expression ahead, whose tokens outside brackets are names, literals and
// operators, to what follows it.
bool DescentParser::at_case_label() const {
    std::size_t depth = 0;
    for (std::size_t ahead = 0;; ++ahead) {
        const std::size_t type = cursor_.type(ahead);
        switch (type) {
        case P::LEFT_PAREN:
        case P::LEFT_BRACKET:
            ++depth;
            continue;
        case P::RIGHT_PAREN:
        case P::RIGHT_BRACKET:
            if (depth == 0) {
                return false;
            }
            --depth;
            continue;
        case antlr4::Token::EOF:
            return false;
        default:
            break;
        }
        if (depth == 0 && (type == P::COLON || type == P::COMMA || type == P::RANGE)) {
            return true;
        }
        if (depth == 0 && (type == P::ASSIGN || type == P::SEMICOLON)) {
            return false;
        }
    }
}

ast::Statement DescentParser::statement() {
    const antlr4::Token& start = cursor_.peek();
    switch (start.getType()) {
    case P::IF:
        return if_statement();
    case P::CASE:
        return case_statement();
    case P::FOR:
        return for_statement();
    case P::WHILE: {
        cursor_.take();
        ast::ExpressionPtr condition = expression();
        cursor_.expect(P::DO);
        ast::StatementList body = statements();
        cursor_.expect(P::END_WHILE);
        cursor_.accept(P::SEMICOLON);
        return {range_from(start), ast::WhileStatement{std::move(condition), std::move(body)}};
    }
    case P::REPEAT: {
        cursor_.take();
        ast::StatementList body = statements();
        cursor_.expect(P::UNTIL);
        ast::ExpressionPtr condition = expression();
        cursor_.expect(P::END_REPEAT);
        cursor_.accept(P::SEMICOLON);
        return {range_from(start), ast::RepeatStatement{std::move(body), std::move(condition)}};
    }
    case P::EXIT:
        cursor_.take();
        cursor_.expect(P::SEMICOLON);
        return {range_from(start), ast::ExitStatement{}};
    case P::CONTINUE:
        cursor_.take();
        cursor_.expect(P::SEMICOLON);
        return {range_from(start), ast::ContinueStatement{}};
    case P::RETURN:
        cursor_.take();
        cursor_.expect(P::SEMICOLON);
        return {range_from(start), ast::ReturnStatement{}};
    case P::SEMICOLON:
        cursor_.take();
        return {range_from(start), ast::EmptyStatement{}};
    default:
        break;
    }
    ast::ExpressionPtr target = expression();
    if (cursor_.accept(P::ASSIGN)) {
        nodes_.check_assignment_target(*target);
        ast::ExpressionPtr value = expression();
        cursor_.expect(P::SEMICOLON);
        return {range_from(start), ast::AssignmentStatement{std::move(target), std::move(value)}};
    }
    cursor_.expect(P::SEMICOLON);
    return nodes_.call_statement(range_from(start), std::move(target));
}

ast::Statement DescentParser::if_statement() {
    const antlr4::Token& start = cursor_.take();
    ast::IfStatement result;
    do {
        ast::ExpressionPtr condition = expression();
        cursor_.expect(P::THEN);
        result.branches.push_back({std::move(condition), statements()});
    } while (cursor_.accept(P::ELSIF));
    if (cursor_.accept(P::ELSE)) {
        result.else_body = statements();
    }
    cursor_.expect(P::END_IF);
    cursor_.accept(P::SEMICOLON);
    return {range_from(start), std::move(result)};
}

ast::Statement DescentParser::case_statement() {
    const antlr4::Token& start = cursor_.take();
    ast::CaseStatement result;
    result.selector = expression();
    cursor_.expect(P::OF);
    while (starts_expression(cursor_.type())) {
        ast::CaseBranch branch;
        do {
            branch.labels.push_back(case_label());
        } while (cursor_.accept(P::COMMA));
        cursor_.expect(P::COLON);
        branch.body = statements(true);
        result.branches.push_back(std::move(branch));
    }
    if (cursor_.accept(P::ELSE)) {
        result.else_body = statements();
    }
    cursor_.expect(P::END_CASE);
    cursor_.accept(P::SEMICOLON);
    return {range_from(start), std::move(result)};
}

// The oracle makes a range's high bound before its low one: the low bound's diagnostics wait
// until the high bound's are out, and its `ON` warning gives way to the high bound's.
ast::CaseLabel DescentParser::case_label() {
    const antlr4::Token& start = cursor_.peek();
    const NodeBuilder::Sink outer = nodes_.sink();
    Diagnostics low_said(std::numeric_limits<std::size_t>::max());
    nodes_.set_sink({&low_said, outer.warned_about_on});
    ast::ExpressionPtr low = expression(); // after a bail the parser is not used again
    const bool low_warned = nodes_.sink().warned_about_on;
    nodes_.set_sink(outer);
    ast::ExpressionPtr high;
    if (cursor_.accept(P::RANGE)) {
        high = expression();
    }
    const bool high_warned = nodes_.sink().warned_about_on != outer.warned_about_on;
    for (const Diagnostic& diagnostic : low_said.all()) {
        if (!high_warned || diagnostic.code != DiagnosticCode::W0103) {
            outer.diagnostics->report(diagnostic);
        }
    }
    nodes_.set_sink({outer.diagnostics, low_warned || high_warned});
    return {std::move(low), std::move(high), range_from(start)};
}

ast::Statement DescentParser::for_statement() {
    const antlr4::Token& start = cursor_.take();
    ast::ForStatement result;
    result.control_variable = identifier();
    cursor_.expect(P::ASSIGN);
    result.from = expression();
    cursor_.expect(P::TO);
    result.to = expression();
    if (cursor_.accept(P::BY)) {
        result.by = expression();
    }
    cursor_.expect(P::DO);
    result.body = statements();
    cursor_.expect(P::END_FOR);
    cursor_.accept(P::SEMICOLON);
    return {range_from(start), std::move(result)};
}

} // namespace eposp::compiler
