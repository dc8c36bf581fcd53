#include "ast_builder.hpp"

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

std::vector<ast::EnumValue> enum_values(AstBuilder& builder,
                                        const std::vector<P::EnumValueContext*>& values) {
    std::vector<ast::EnumValue> result;
    for (P::EnumValueContext* value : values) {
        result.push_back(
            {builder.identifier(*value->identifier()),
             value->expression() != nullptr ? builder.expression(*value->expression()) : nullptr});
    }
    return result;
}

// `(a, b)`, `UDINT (a, b)` (IEC) or `(a, b) UDINT` (TwinCAT): `base` is null for the first.
ast::EnumType enum_type(AstBuilder& builder, P::IdentifierContext* base,
                        const std::vector<P::EnumValueContext*>& values) {
    return {base != nullptr
                ? builder.make<ast::TypeSpec>(NodeBuilder::named_type(builder.identifier(*base)))
                : nullptr,
            enum_values(builder, values)};
}

ast::Subrange subrange(AstBuilder& builder, P::SubrangeContext& context) {
    return {builder.expression(*context.expression(0)), builder.expression(*context.expression(1))};
}

} // namespace

// IEC 61131-3 ed. 3, 6.4.4.
ast::TypeSpec AstBuilder::type_spec(P::TypeSpecContext& context) {
    const SourceRange where = range(context);
    const auto pointer_to = [&](ast::ReferenceType::Kind kind, P::TypeSpecContext& target) {
        return ast::TypeSpec{where,
                             ast::ReferenceType{kind, make<ast::TypeSpec>(type_spec(target))}};
    };
    if (auto* structure = alternative<P::StructTypeContext>(&context)) {
        ast::StructType result;
        for (P::VarDeclarationContext* member : structure->varDeclaration()) {
            result.members.push_back(variable(*member));
        }
        return {where, std::move(result)};
    }
    if (auto* array = alternative<P::ArrayTypeContext>(&context)) {
        ast::ArrayType result;
        for (P::ArrayDimensionContext* dimension : array->arrayDimension()) {
            result.dimensions.push_back(
                {dimension->subrange() != nullptr
                     ? std::optional<ast::Subrange>(subrange(*this, *dimension->subrange()))
                     : std::nullopt});
        }
        result.element = make<ast::TypeSpec>(type_spec(*array->typeSpec()));
        return {where, std::move(result)};
    }
    if (auto* reference = alternative<P::ReferenceTypeContext>(&context)) {
        return pointer_to(ast::ReferenceType::Kind::Reference, *reference->typeSpec());
    }
    if (auto* pointer = alternative<P::PointerTypeContext>(&context)) {
        return pointer_to(ast::ReferenceType::Kind::Pointer, *pointer->typeSpec());
    }
    if (auto* enumeration = alternative<P::EnumTypeContext>(&context)) {
        return {where, enum_type(*this, enumeration->identifier(), enumeration->enumValue())};
    }
    if (auto* typed_enum = alternative<P::TypedEnumTypeContext>(&context)) {
        return {where, enum_type(*this, typed_enum->identifier(), typed_enum->enumValue())};
    }
    if (auto* sub = alternative<P::SubrangeTypeContext>(&context)) {
        return {where, ast::SubrangeType{make<ast::TypeSpec>(NodeBuilder::named_type(
                                             identifier(*sub->identifier()))),
                                         subrange(*this, *sub->subrange())}};
    }
    if (auto* sized = alternative<P::SizedTypeContext>(&context)) {
        ast::Identifier base = identifier(*sized->identifier());
        ast::ExpressionPtr length = expression(*sized->expression());
        return nodes_.sized_type(where, std::move(base), std::move(length),
                                 sized->LEFT_PAREN() != nullptr);
    }
    return NodeBuilder::named_type(
        identifier(*static_cast<P::NamedTypeContext&>(context).identifier()));
}

} // namespace eposp::compiler
