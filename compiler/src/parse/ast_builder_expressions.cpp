#include "ast_builder.hpp"
#include "literal_decoder.hpp"
#include "token_range.hpp"

#include <string_view>

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

template <typename Node>
ast::ExpressionPtr make(SourceRange range, Node node) {
    return std::make_unique<ast::Expression>(ast::Expression{range, std::move(node)});
}

SourceRange span(const SourceRange& first, const SourceRange& last) {
    return {first.file, first.begin, last.end};
}

// IEC 61131-3 ed. 3, table 71.
ast::BinaryOperator binary_operator(std::size_t token) {
    switch (token) {
    case P::POWER:
        return ast::BinaryOperator::Power;
    case P::STAR:
        return ast::BinaryOperator::Multiply;
    case P::SLASH:
        return ast::BinaryOperator::Divide;
    case P::MOD:
        return ast::BinaryOperator::Modulo;
    case P::PLUS:
        return ast::BinaryOperator::Add;
    case P::MINUS:
        return ast::BinaryOperator::Subtract;
    case P::LESS:
        return ast::BinaryOperator::Less;
    case P::GREATER:
        return ast::BinaryOperator::Greater;
    case P::LESS_EQUAL:
        return ast::BinaryOperator::LessEqual;
    case P::GREATER_EQUAL:
        return ast::BinaryOperator::GreaterEqual;
    case P::EQUAL:
        return ast::BinaryOperator::Equal;
    case P::NOT_EQUAL:
        return ast::BinaryOperator::NotEqual;
    case P::AND:
    case P::AMPERSAND:
        return ast::BinaryOperator::And;
    case P::XOR:
        return ast::BinaryOperator::Xor;
    default:
        return ast::BinaryOperator::Or;
    }
}

std::optional<LiteralForm> literal_form(std::size_t token) {
    switch (token) {
    case P::INTEGER:
        return LiteralForm::Integer;
    case P::BASED_INTEGER:
        return LiteralForm::BasedInteger;
    case P::REAL_LITERAL:
        return LiteralForm::Real;
    case P::STRING_LITERAL:
        return LiteralForm::String;
    case P::WSTRING_LITERAL:
        return LiteralForm::WideString;
    case P::TIME_LITERAL:
        return LiteralForm::Duration;
    case P::DATE_LITERAL:
        return LiteralForm::Date;
    case P::TIME_OF_DAY_LITERAL:
        return LiteralForm::TimeOfDay;
    case P::DATE_AND_TIME_LITERAL:
        return LiteralForm::DateAndTime;
    case P::TYPED_LITERAL:
        return LiteralForm::Typed;
    default:
        return std::nullopt;
    }
}

// `-5` is the literal -5, not a negation of 5, so that -2^63 fits a LINT and typed contexts see
// the literal value. Typed literals carry their own sign (`INT#-5`).
bool negate_literal(ast::Expression& operand) {
    auto* literal = std::get_if<ast::LiteralExpression>(&operand.node);
    if (literal == nullptr) {
        return false;
    }
    if (auto* integer = std::get_if<ast::IntegerLiteral>(&literal->value);
        integer != nullptr && !integer->type && !integer->negative) {
        integer->negative = integer->magnitude != 0;
        return true;
    }
    if (auto* real = std::get_if<ast::RealLiteral>(&literal->value);
        real != nullptr && !real->type && real->value >= 0.0) {
        real->value = -real->value;
        return true;
    }
    return false;
}

} // namespace

// The alternatives most frequent first.
ast::ExpressionPtr AstBuilder::expression(P::ExpressionContext& context) {
    if (auto* name = alternative<P::NameExpressionContext>(&context)) {
        ast::Identifier id = identifier(*name->name);
        const SourceRange where = id.range;
        return make(where, ast::NameExpression{std::move(id)});
    }
    if (auto* literal = alternative<P::LiteralExpressionContext>(&context)) {
        return literal_expression(*literal->value);
    }
    if (auto* binary = alternative<P::BinaryExpressionContext>(&context)) {
        ast::ExpressionPtr left = expression(*binary->left);
        ast::ExpressionPtr right = expression(*binary->right);
        const SourceRange whole = span(left->range, right->range);
        return make(whole, ast::BinaryExpression{binary_operator(binary->op->getType()),
                                                 std::move(left), std::move(right)});
    }
    if (auto* member = alternative<P::MemberAccessContext>(&context)) {
        if (member->bit != nullptr) {
            return bit_access(*member);
        }
        ast::ExpressionPtr base = expression(*member->base);
        ast::Identifier name = identifier(*member->member);
        const SourceRange whole = span(base->range, name.range);
        return make(whole, ast::MemberExpression{std::move(base), std::move(name)});
    }
    if (auto* index = alternative<P::IndexAccessContext>(&context)) {
        ast::ExpressionPtr base = expression(*index->base);
        std::vector<ast::ExpressionPtr> indices;
        indices.reserve(index->indices.size());
        for (P::ExpressionContext* subscript : index->indices) {
            indices.push_back(expression(*subscript));
        }
        const SourceRange whole = span(base->range, range(*index->getStop()));
        return make(whole, ast::IndexExpression{std::move(base), std::move(indices)});
    }
    if (auto* call = alternative<P::CallArgumentsContext>(&context)) {
        ast::ExpressionPtr callee = expression(*call->base);
        const SourceRange whole = span(callee->range, range(*call->getStop()));
        return make(whole, ast::CallExpression{std::move(callee), arguments(call->arguments)});
    }
    if (auto* unary = alternative<P::UnaryExpressionContext>(&context)) {
        return unary_expression(*unary);
    }
    if (auto* parenthesized = alternative<P::ParenthesizedExpressionContext>(&context)) {
        return expression(*parenthesized->inner);
    }
    if (auto* dereference = alternative<P::DereferenceContext>(&context)) {
        ast::ExpressionPtr base = expression(*dereference->base);
        const SourceRange whole = span(base->range, range(*dereference->getStop()));
        return make(whole, ast::DereferenceExpression{std::move(base)});
    }
    if (auto* call = alternative<P::OperatorCallContext>(&context)) {
        // The same call as one of a function named like the operator.
        const SourceRange where = range(*call->callee);
        auto callee = make(where, ast::NameExpression{{call->callee->getText(), where}});
        return make(range(context),
                    ast::CallExpression{std::move(callee), arguments(call->arguments)});
    }
    if (auto* located = alternative<P::DirectAddressExpressionContext>(&context)) {
        std::optional<ast::DirectAddress> address = direct_address(*located->address);
        return make(range(context),
                    ast::DirectAddressExpression{address.value_or(ast::DirectAddress{})});
    }
    auto& reference = static_cast<P::RefExpressionContext&>(context);
    return make(range(context), ast::ReferenceExpression{expression(*reference.inner)});
}

ast::ExpressionPtr AstBuilder::unary_expression(P::UnaryExpressionContext& context) {
    ast::ExpressionPtr value = expression(*context.operand);
    const SourceRange whole = span(range(*context.op), value->range);
    if (context.op->getType() == P::MINUS && negate_literal(*value)) {
        value->range = whole;
        return value;
    }
    const ast::UnaryOperator op = context.op->getType() == P::MINUS  ? ast::UnaryOperator::Negate
                                  : context.op->getType() == P::PLUS ? ast::UnaryOperator::Plus
                                                                     : ast::UnaryOperator::Not;
    return make(whole, ast::UnaryExpression{op, std::move(value)});
}

ast::ExpressionPtr AstBuilder::bit_access(P::MemberAccessContext& context) {
    ast::ExpressionPtr base = expression(*context.base);
    const std::string number_text = context.bit->getText();
    const auto index = decode_literal(LiteralForm::Integer, number_text);
    const auto* value = index ? std::get_if<ast::IntegerLiteral>(&*index) : nullptr;
    if (value == nullptr || value->magnitude > 63) {
        error(DiagnosticCode::E0105, token_range(file_, *context.DOT()->getSymbol(), *context.bit),
              "bit number " + number_text +
                  " is out of range; the widest bit string (LWORD) has bits 0 to 63");
    }
    const auto number = static_cast<std::uint32_t>(value != nullptr ? value->magnitude : 0);
    const SourceRange whole = span(base->range, range(*context.bit));
    return make(whole, ast::BitAccessExpression{std::move(base), number});
}

ast::ExpressionPtr AstBuilder::literal_expression(antlr4::Token& token) {
    const SourceRange where = range(token);
    const auto literal = [&](ast::Literal value) {
        return make(where, ast::LiteralExpression{std::move(value)});
    };
    switch (token.getType()) {
    case P::TRUE:
        return literal(ast::BoolLiteral{true});
    case P::FALSE:
        return literal(ast::BoolLiteral{false});
    case P::NULL_REFERENCE:
        return literal(ast::NullLiteral{});
    case P::UNTERMINATED_STRING: // reported with the other lexical errors, before parsing
        return literal(ast::StringLiteral{});
    default:
        break;
    }
    core::Result<ast::Literal> decoded =
        decode_literal(*literal_form(token.getType()), token.getText());
    if (!decoded) {
        error(DiagnosticCode::E0104, where, decoded.error());
        return literal(ast::IntegerLiteral{}); // placeholder; the unit has errors anyway
    }
    // `1E37` and `REAL#1E37` (not `REAL#1`, which needs no point); the number follows any `#`.
    const std::string text = token.getText();
    const std::size_t hash = text.find('#');
    const std::string_view number =
        std::string_view(text).substr(hash == std::string::npos ? 0 : hash + 1);
    if (std::holds_alternative<ast::RealLiteral>(*decoded) &&
        number.find('.') == std::string_view::npos &&
        number.find_first_of("eE") != std::string_view::npos) {
        warning(DiagnosticCode::W0102, where,
                "real literal '" + text +
                    "' has no decimal point, which IEC 61131-3 (6.3.2) requires; "
                    "accepted as CODESYS does");
    }
    if (auto* enum_value = std::get_if<ast::EnumValueLiteral>(&*decoded)) {
        // Names are ASCII, so their lengths in bytes are lengths in columns.
        const auto prefix = static_cast<std::uint32_t>(enum_value->type_name.name.size());
        enum_value->type_name.range = {
            file_, where.begin, {where.begin.line, where.begin.column + prefix - 1}};
        enum_value->value.range = {
            file_, {where.begin.line, where.begin.column + prefix + 1}, where.end};
    }
    return literal(std::move(*decoded));
}

std::vector<ast::Argument> AstBuilder::arguments(P::ArgumentListContext* context) {
    std::vector<ast::Argument> result;
    if (context == nullptr) {
        return result;
    }
    for (P::ArgumentContext* argument : context->argument()) {
        ast::Argument built;
        built.range = range(*argument);
        if (auto* input = alternative<P::InputArgumentContext>(argument)) {
            built.kind = ast::Argument::Kind::Input;
            built.name = identifier(*input->identifier());
            built.value = expression(*input->expression());
        } else if (auto* output = alternative<P::OutputArgumentContext>(argument)) {
            built.kind = ast::Argument::Kind::Output;
            built.name = identifier(*output->identifier());
            built.negated = output->NOT() != nullptr;
            built.value = expression(*output->expression());
        } else {
            built.value =
                expression(*static_cast<P::PositionalArgumentContext&>(*argument).expression());
        }
        result.push_back(std::move(built));
    }
    return result;
}

ast::Identifier AstBuilder::identifier(P::IdentifierContext& context) {
    // The rule is one token: its text, without the stream RuleContext::getText builds it in.
    antlr4::Token& token = *context.getStart();
    if (token.getType() == P::ON && !warned_about_on_) {
        warned_about_on_ = true; // once per file: the point is the form, not each use
        warning(DiagnosticCode::W0103, range(context),
                "'" + token.getText() +
                    "' is a keyword of IEC 61131-3 (RESOURCE ... ON); accepted "
                    "as a name, as CODESYS does");
    }
    return {token.getText(), range(token)};
}

SourceRange AstBuilder::range(antlr4::ParserRuleContext& context) const {
    antlr4::Token* start = context.getStart();
    antlr4::Token* stop = context.getStop();
    if (stop == nullptr || stop->getTokenIndex() < start->getTokenIndex()) {
        return token_range(file_, *start); // an empty rule such as an empty statement list
    }
    return token_range(file_, *start, *stop);
}

SourceRange AstBuilder::range(antlr4::Token& token) const {
    return token_range(file_, token);
}

void AstBuilder::error(DiagnosticCode code, const SourceRange& where, std::string message) {
    diagnostics_.error(code, where, std::move(message));
}

void AstBuilder::warning(DiagnosticCode code, const SourceRange& where, std::string message) {
    diagnostics_.warning(code, where, std::move(message));
}

} // namespace eposp::compiler
