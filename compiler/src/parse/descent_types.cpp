// Data types (grammar rules `typeSpec` to `enumValue`, IEC 61131-3 ed. 3, 6.4.4).
#include "StructuredTextParser.h"
#include "descent_parser.hpp"

namespace eposp::compiler {

using P = generated::StructuredTextParser;

ast::TypeSpec DescentParser::type_spec(TypePlace place) {
    const antlr4::Token& start = cursor_.peek();
    switch (start.getType()) {
    case P::STRUCT: {
        cursor_.take();
        ast::StructType result;
        do {
            result.members.push_back(variable());
        } while (at_identifier());
        cursor_.expect(P::END_STRUCT);
        return {range_from(start), std::move(result)};
    }
    case P::ARRAY: {
        cursor_.take();
        cursor_.expect(P::LEFT_BRACKET);
        ast::ArrayType result;
        do {
            result.dimensions.push_back(
                {cursor_.accept(P::STAR) ? std::nullopt : std::optional<ast::Subrange>(subrange())});
        } while (cursor_.accept(P::COMMA));
        cursor_.expect(P::RIGHT_BRACKET);
        cursor_.expect(P::OF);
        result.element = nodes_.make<ast::TypeSpec>(type_spec(place));
        return {range_from(start), std::move(result)};
    }
    case P::REF_TO:
    case P::POINTER: {
        cursor_.take();
        const auto kind = start.getType() == P::REF_TO ? ast::ReferenceType::Kind::Reference
                                                       : ast::ReferenceType::Kind::Pointer;
        if (kind == ast::ReferenceType::Kind::Pointer) {
            cursor_.expect(P::TO);
        }
        auto target = nodes_.make<ast::TypeSpec>(type_spec(place));
        return {range_from(start), ast::ReferenceType{kind, std::move(target)}};
    }
    case P::LEFT_PAREN:
        return enum_type(place);
    default:
        break;
    }
    ast::Identifier base = identifier();
    if (cursor_.accept(P::LEFT_BRACKET)) {
        ast::ExpressionPtr length = expression();
        cursor_.expect(P::RIGHT_BRACKET);
        return nodes_.sized_type(range_from(start), std::move(base), std::move(length), false);
    }
    if (place == TypePlace::ResultWithoutEnd || !cursor_.accept(P::LEFT_PAREN)) {
        return NodeBuilder::named_type(std::move(base));
    }
    // `DWORD (Red)` reads as a length in parentheses, the earlier alternative.
    if (at_identifier() && (cursor_.type(1) == P::COMMA || cursor_.type(1) == P::ASSIGN)) {
        ast::EnumType result{nodes_.make<ast::TypeSpec>(NodeBuilder::named_type(std::move(base))),
                             enum_values()};
        cursor_.expect(P::RIGHT_PAREN);
        return {range_from(start), std::move(result)};
    }
    ast::ExpressionPtr value = expression();
    if (cursor_.accept(P::RANGE)) {
        ast::ExpressionPtr high = expression();
        cursor_.expect(P::RIGHT_PAREN);
        return {range_from(start), ast::SubrangeType{nodes_.make<ast::TypeSpec>(
                                                         NodeBuilder::named_type(std::move(base))),
                                                     {std::move(value), std::move(high)}}};
    }
    cursor_.expect(P::RIGHT_PAREN);
    return nodes_.sized_type(range_from(start), std::move(base), std::move(value), true);
}

// `(a, b)` or TwinCAT's `(a, b) UDINT`, whose base type the oracle makes before the values.
ast::TypeSpec DescentParser::enum_type(TypePlace place) {
    const antlr4::Token& start = cursor_.peek();
    const std::size_t close = cursor_.closing(0);
    ast::TypeSpecPtr base;
    if (close != 0 && takes_enum_base(close + 1, place)) {
        base = nodes_.make<ast::TypeSpec>(
            NodeBuilder::named_type(nodes_.identifier(cursor_.peek(close + 1))));
    }
    cursor_.take();
    ast::EnumType result{std::move(base), enum_values()};
    cursor_.expect(P::RIGHT_PAREN);
    if (result.base) {
        cursor_.take(); // the base type's name, made above
    }
    return {range_from(start), std::move(result)};
}

// `identifier?` after the values: taken unless it is the next type declaration's name.
bool DescentParser::takes_enum_base(std::size_t ahead, TypePlace place) const {
    return place != TypePlace::ResultWithoutEnd && at_identifier(ahead) &&
           cursor_.type(ahead + 1) != P::COLON;
}

std::vector<ast::EnumValue> DescentParser::enum_values() {
    std::vector<ast::EnumValue> result;
    do {
        ast::Identifier name = identifier();
        ast::ExpressionPtr value = cursor_.accept(P::ASSIGN) ? expression() : nullptr;
        result.push_back({std::move(name), std::move(value)});
    } while (cursor_.accept(P::COMMA));
    return result;
}

ast::Subrange DescentParser::subrange() {
    ast::ExpressionPtr low = expression();
    cursor_.expect(P::RANGE);
    return {std::move(low), expression()};
}

} // namespace eposp::compiler
