#include "ast_builder.hpp"

namespace eposp::compiler {

ast::StatementList AstBuilder::statements(P::StatementListContext* context) {
    ast::StatementList result;
    if (context == nullptr) {
        return result;
    }
    for (P::StatementContext* statement_context : context->statement()) {
        result.push_back(statement(*statement_context));
    }
    return result;
}

ast::Statement AstBuilder::statement(P::StatementContext& context) {
    const SourceRange where = range(context);
    if (auto* simple = alternative<P::ExpressionStatementContext>(&context)) {
        ast::ExpressionPtr target = expression(*simple->target);
        if (simple->value != nullptr) {
            nodes_.check_assignment_target(*target);
            return {where, ast::AssignmentStatement{std::move(target), expression(*simple->value)}};
        }
        return nodes_.call_statement(where, std::move(target));
    }
    if (auto* if_statement = alternative<P::IfStatementContext>(&context)) {
        ast::IfStatement result;
        result.branches.push_back(
            {expression(*if_statement->expression()), statements(if_statement->statementList(0))});
        for (P::ElsifClauseContext* elsif : if_statement->elsifClause()) {
            result.branches.push_back(
                {expression(*elsif->expression()), statements(elsif->statementList())});
        }
        if (if_statement->ELSE() != nullptr) {
            result.else_body = statements(if_statement->statementList(1));
        }
        return {where, std::move(result)};
    }
    if (auto* case_statement = alternative<P::CaseStatementContext>(&context)) {
        ast::CaseStatement result;
        result.selector = expression(*case_statement->expression());
        for (P::CaseBranchContext* branch : case_statement->caseBranch()) {
            ast::CaseBranch built;
            for (P::CaseLabelContext* label : branch->caseLabel()) {
                ast::ExpressionPtr high =
                    label->RANGE() != nullptr ? expression(*label->expression(1)) : nullptr;
                built.labels.push_back(
                    {expression(*label->expression(0)), std::move(high), range(*label)});
            }
            built.body = statements(branch->statementList());
            result.branches.push_back(std::move(built));
        }
        result.else_body = statements(case_statement->statementList());
        return {where, std::move(result)};
    }
    if (auto* for_statement = alternative<P::ForStatementContext>(&context)) {
        ast::ForStatement result;
        result.control_variable = identifier(*for_statement->identifier());
        result.from = expression(*for_statement->expression(0));
        result.to = expression(*for_statement->expression(1));
        if (for_statement->BY() != nullptr) {
            result.by = expression(*for_statement->expression(2));
        }
        result.body = statements(for_statement->statementList());
        return {where, std::move(result)};
    }
    if (auto* while_statement = alternative<P::WhileStatementContext>(&context)) {
        return {where, ast::WhileStatement{expression(*while_statement->expression()),
                                           statements(while_statement->statementList())}};
    }
    if (auto* repeat = alternative<P::RepeatStatementContext>(&context)) {
        return {where, ast::RepeatStatement{statements(repeat->statementList()),
                                            expression(*repeat->expression())}};
    }
    if (alternative<P::ExitStatementContext>(&context) != nullptr) {
        return {where, ast::ExitStatement{}};
    }
    if (alternative<P::ContinueStatementContext>(&context) != nullptr) {
        return {where, ast::ContinueStatement{}};
    }
    if (alternative<P::ReturnStatementContext>(&context) != nullptr) {
        return {where, ast::ReturnStatement{}};
    }
    return {where, ast::EmptyStatement{}};
}

} // namespace eposp::compiler
