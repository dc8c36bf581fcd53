#include "ast_builder.hpp"

namespace eposp::compiler {

// The alternatives most frequent first.
ast::ExpressionPtr AstBuilder::expression(P::ExpressionContext& context) {
    if (auto* name = alternative<P::NameExpressionContext>(&context)) {
        return nodes_.name(*name->name->getStart());
    }
    if (auto* literal = alternative<P::LiteralExpressionContext>(&context)) {
        return nodes_.literal(*literal->value);
    }
    if (auto* binary = alternative<P::BinaryExpressionContext>(&context)) {
        ast::ExpressionPtr left = expression(*binary->left);
        ast::ExpressionPtr right = expression(*binary->right);
        return nodes_.binary(binary->op->getType(), std::move(left), std::move(right));
    }
    if (auto* member = alternative<P::MemberAccessContext>(&context)) {
        ast::ExpressionPtr base = expression(*member->base);
        if (member->bit != nullptr) {
            return nodes_.bit_access(std::move(base), *member->DOT()->getSymbol(), *member->bit);
        }
        return nodes_.member(std::move(base), identifier(*member->member));
    }
    if (auto* index = alternative<P::IndexAccessContext>(&context)) {
        ast::ExpressionPtr base = expression(*index->base);
        std::vector<ast::ExpressionPtr> indices;
        indices.reserve(index->indices.size());
        for (P::ExpressionContext* subscript : index->indices) {
            indices.push_back(expression(*subscript));
        }
        return nodes_.index(std::move(base), std::move(indices), *index->getStop());
    }
    if (auto* call = alternative<P::CallArgumentsContext>(&context)) {
        ast::ExpressionPtr callee = expression(*call->base);
        return nodes_.call(std::move(callee), arguments(call->arguments), *call->getStop());
    }
    if (auto* unary = alternative<P::UnaryExpressionContext>(&context)) {
        return nodes_.unary(*unary->op, expression(*unary->operand));
    }
    if (auto* parenthesized = alternative<P::ParenthesizedExpressionContext>(&context)) {
        return expression(*parenthesized->inner);
    }
    if (auto* dereference = alternative<P::DereferenceContext>(&context)) {
        return nodes_.dereference(expression(*dereference->base), *dereference->getStop());
    }
    if (auto* call = alternative<P::OperatorCallContext>(&context)) {
        return nodes_.operator_call(*call->callee, arguments(call->arguments), range(context));
    }
    if (auto* call = alternative<P::FormalNotContext>(&context)) {
        std::vector<ast::Argument> inputs(1);
        inputs[0].kind = ast::Argument::Kind::Input;
        inputs[0].range = range(*call->input);
        inputs[0].name = identifier(*call->input->identifier());
        inputs[0].value = expression(*call->input->expression());
        for (P::ArgumentContext* more : call->more) {
            inputs.push_back(argument(*more));
        }
        return nodes_.operator_call(*call->callee, std::move(inputs), range(context));
    }
    if (auto* located = alternative<P::DirectAddressExpressionContext>(&context)) {
        return nodes_.direct_address_expression(*located->address);
    }
    auto& reference = static_cast<P::RefExpressionContext&>(context);
    return nodes_.reference(expression(*reference.inner), range(context));
}

std::vector<ast::Argument> AstBuilder::arguments(P::ArgumentListContext* context) {
    std::vector<ast::Argument> result;
    if (context == nullptr) {
        return result;
    }
    for (P::ArgumentContext* argument : context->argument()) {
        result.push_back(this->argument(*argument));
    }
    return result;
}

ast::Argument AstBuilder::argument(P::ArgumentContext& context) {
    ast::Argument built;
    built.range = range(context);
    if (auto* input = alternative<P::InputArgumentContext>(&context)) {
        built.kind = ast::Argument::Kind::Input;
        built.name = identifier(*input->identifier());
        built.value = expression(*input->expression());
    } else if (auto* output = alternative<P::OutputArgumentContext>(&context)) {
        built.kind = ast::Argument::Kind::Output;
        built.name = identifier(*output->identifier());
        built.negated = output->NOT() != nullptr;
        built.value = expression(*output->expression());
    } else {
        built.value = expression(*static_cast<P::PositionalArgumentContext&>(context).expression());
    }
    return built;
}

ast::Identifier AstBuilder::identifier(P::IdentifierContext& context) {
    return nodes_.identifier(*context.getStart()); // the rule is one token
}

SourceRange AstBuilder::range(antlr4::ParserRuleContext& context) const {
    return nodes_.range(*context.getStart(), context.getStop());
}

} // namespace eposp::compiler
