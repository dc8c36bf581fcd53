#include "node_builder.hpp"

#include "StructuredTextParser.h"
#include "eposp/compiler/ascii_case.hpp"
#include "literal_decoder.hpp"
#include "token_range.hpp"

#include <cctype>
#include <charconv>
#include <string_view>

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

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

bool is_assignable(const ast::Expression& target) {
    return std::holds_alternative<ast::NameExpression>(target.node) ||
           std::holds_alternative<ast::DirectAddressExpression>(target.node) ||
           std::holds_alternative<ast::MemberExpression>(target.node) ||
           std::holds_alternative<ast::BitAccessExpression>(target.node) ||
           std::holds_alternative<ast::IndexExpression>(target.node) ||
           std::holds_alternative<ast::DereferenceExpression>(target.node);
}

// `x = 1;` meant `x := 1;`: the '=' between the operands (with a blank on each side, or none),
// when nothing else stands there, becomes ':='.
std::optional<FixIt> assignment_instead_of(const ast::BinaryExpression& comparison) {
    const SourceRange& left = comparison.left->range;
    const SourceRange& right = comparison.right->range;
    if (left.end.line != right.begin.line || right.begin.column <= left.end.column + 1) {
        return std::nullopt;
    }
    const std::uint32_t gap = right.begin.column - left.end.column - 1;
    if (gap != 1 && gap != 3) {
        return std::nullopt;
    }
    return FixIt{
        {left.file, {left.end.line, left.end.column + 1}, {left.end.line, right.begin.column - 1}},
        gap == 1 ? ":=" : " := "};
}

bool is_string_type(ast::ElementaryType type) {
    return type == ast::ElementaryType::String || type == ast::ElementaryType::Wstring;
}

} // namespace

ast::CompilationUnit NodeBuilder::unit() {
    ast::CompilationUnit unit{file_, std::make_unique<ast::NodeArena>(), {}, {}, {}, {}};
    arena_ = unit.nodes.get();
    return unit;
}

SourceRange NodeBuilder::range(const antlr4::Token& token) const {
    return token_range(file_, token);
}

SourceRange NodeBuilder::range(const antlr4::Token& first, const antlr4::Token* last) const {
    if (last == nullptr || last->getTokenIndex() < first.getTokenIndex()) {
        return token_range(file_, first); // an empty rule such as an empty statement list
    }
    return token_range(file_, first, *last);
}

ast::Identifier NodeBuilder::identifier(const antlr4::Token& token) {
    if (token.getType() == P::ON && !warned_about_on_) {
        warned_about_on_ = true; // once per file: the point is the form, not each use
        warning(DiagnosticCode::W0103, range(token),
                "'" + token.getText() +
                    "' is a keyword of IEC 61131-3 (RESOURCE ... ON); accepted "
                    "as a name, as CODESYS does");
    }
    return {token.getText(), range(token)};
}

ast::ExpressionPtr NodeBuilder::literal(const antlr4::Token& token) {
    const SourceRange where = range(token);
    const auto literal = [&](ast::Literal value) {
        return expression(where, ast::LiteralExpression{std::move(value)});
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
    const std::string text = token.getText();
    core::Result<ast::Literal> decoded = decode_literal(*literal_form(token.getType()), text);
    if (!decoded) {
        error(DiagnosticCode::E0104, where, decoded.error());
        return literal(ast::IntegerLiteral{}); // placeholder; the unit has errors anyway
    }
    // `1E37` and `REAL#1E37` (not `REAL#1`, which needs no point); the number follows any `#`.
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

// IEC 61131-3 ed. 3, 6.5.5, table 16: %, I/Q/M, an optional size X/B/W/D/L, then a
// hierarchical address `0.0` or `*` for a location assigned in VAR_CONFIG.
std::optional<ast::DirectAddress> NodeBuilder::direct_address(const antlr4::Token& token) {
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

ast::ExpressionPtr NodeBuilder::name(const antlr4::Token& token) {
    ast::Identifier id = identifier(token);
    const SourceRange where = id.range;
    return expression(where, ast::NameExpression{std::move(id)});
}

ast::ExpressionPtr NodeBuilder::binary(std::size_t op, ast::ExpressionPtr left,
                                       ast::ExpressionPtr right) {
    const SourceRange whole = span(left->range, right->range);
    return expression(
        whole, ast::BinaryExpression{binary_operator(op), std::move(left), std::move(right)});
}

ast::ExpressionPtr NodeBuilder::unary(const antlr4::Token& op, ast::ExpressionPtr value) {
    const SourceRange whole = span(range(op), value->range);
    if (op.getType() == P::MINUS && negate_literal(*value)) {
        value->range = whole;
        return value;
    }
    const ast::UnaryOperator kind = op.getType() == P::MINUS  ? ast::UnaryOperator::Negate
                                    : op.getType() == P::PLUS ? ast::UnaryOperator::Plus
                                                              : ast::UnaryOperator::Not;
    return expression(whole, ast::UnaryExpression{kind, std::move(value)});
}

ast::ExpressionPtr NodeBuilder::member(ast::ExpressionPtr base, ast::Identifier name) {
    const SourceRange whole = span(base->range, name.range);
    return expression(whole, ast::MemberExpression{std::move(base), std::move(name)});
}

ast::ExpressionPtr NodeBuilder::bit_access(ast::ExpressionPtr base, const antlr4::Token& dot,
                                           const antlr4::Token& bit) {
    const std::string number_text = bit.getText();
    const auto index = decode_literal(LiteralForm::Integer, number_text);
    const auto* value = index ? std::get_if<ast::IntegerLiteral>(&*index) : nullptr;
    if (value == nullptr || value->magnitude > 63) {
        error(DiagnosticCode::E0105, token_range(file_, dot, bit),
              "bit number " + number_text +
                  " is out of range; the widest bit string (LWORD) has bits 0 to 63");
    }
    const auto number = static_cast<std::uint32_t>(value != nullptr ? value->magnitude : 0);
    const SourceRange whole = span(base->range, range(bit));
    return expression(whole, ast::BitAccessExpression{std::move(base), number});
}

ast::ExpressionPtr NodeBuilder::index(ast::ExpressionPtr base,
                                      std::vector<ast::ExpressionPtr> indices,
                                      const antlr4::Token& close) {
    const SourceRange whole = span(base->range, range(close));
    return expression(whole, ast::IndexExpression{std::move(base), std::move(indices)});
}

ast::ExpressionPtr NodeBuilder::call(ast::ExpressionPtr callee,
                                     std::vector<ast::Argument> arguments,
                                     const antlr4::Token& close) {
    const SourceRange whole = span(callee->range, range(close));
    return expression(whole, ast::CallExpression{std::move(callee), std::move(arguments)});
}

ast::ExpressionPtr NodeBuilder::dereference(ast::ExpressionPtr base, const antlr4::Token& caret) {
    const SourceRange whole = span(base->range, range(caret));
    return expression(whole, ast::DereferenceExpression{std::move(base)});
}

ast::ExpressionPtr NodeBuilder::operator_call(const antlr4::Token& callee,
                                              std::vector<ast::Argument> arguments,
                                              SourceRange whole) {
    const SourceRange where = range(callee);
    auto name = expression(where, ast::NameExpression{{callee.getText(), where}});
    return expression(whole, ast::CallExpression{std::move(name), std::move(arguments)});
}

ast::ExpressionPtr NodeBuilder::direct_address_expression(const antlr4::Token& token) {
    std::optional<ast::DirectAddress> address = direct_address(token);
    return expression(range(token),
                      ast::DirectAddressExpression{address.value_or(ast::DirectAddress{})});
}

ast::ExpressionPtr NodeBuilder::reference(ast::ExpressionPtr inner, SourceRange whole) {
    return expression(whole, ast::ReferenceExpression{std::move(inner)});
}

void NodeBuilder::check_assignment_target(const ast::Expression& target) {
    if (!is_assignable(target)) {
        error(DiagnosticCode::E0106, target.range, "the left side of ':=' must be a variable");
    }
}

ast::Statement NodeBuilder::call_statement(SourceRange whole, ast::ExpressionPtr target) {
    if (!std::holds_alternative<ast::CallExpression>(target->node)) {
        const auto* binary = std::get_if<ast::BinaryExpression>(&target->node);
        const bool comparison = binary != nullptr && binary->op == ast::BinaryOperator::Equal;
        Diagnostic diagnostic(
            DiagnosticCode::E0107, target->range,
            comparison ? "this statement does nothing; did you mean ':=' instead of '='?"
                       : "this statement does nothing; expected an assignment ':=' or a call");
        if (comparison) {
            diagnostic.fix_it = assignment_instead_of(*binary);
        }
        diagnostics_->report(std::move(diagnostic));
    }
    return {whole, ast::CallStatement{std::move(target)}};
}

// IEC 61131-3 ed. 3, 6.8.2, table 63: SINGLE, INTERVAL and PRIORITY, each at most once.
ast::ExpressionPtr* NodeBuilder::task_property(ast::TaskDeclaration& task,
                                               const ast::Identifier& name) {
    ast::ExpressionPtr* slot = equal_ignoring_case(name.name, "SINGLE")     ? &task.single
                               : equal_ignoring_case(name.name, "INTERVAL") ? &task.interval
                               : equal_ignoring_case(name.name, "PRIORITY") ? &task.priority
                                                                            : nullptr;
    if (slot == nullptr) {
        error(DiagnosticCode::E0110, name.range,
              "unknown task property '" + name.name +
                  "'; a task has SINGLE, INTERVAL and PRIORITY");
        return nullptr;
    }
    if (*slot) {
        error(DiagnosticCode::E0110, name.range,
              "task property '" + name.name + "' is given twice");
        return nullptr;
    }
    return slot;
}

void NodeBuilder::check_task(const ast::TaskDeclaration& task) {
    if (!task.priority) {
        error(DiagnosticCode::E0110, task.name.range,
              "task '" + task.name.name + "' needs a PRIORITY");
    }
}

ast::VarSectionKind NodeBuilder::section_kind(std::size_t token) {
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

ast::Retention NodeBuilder::retention(const antlr4::Token* qualifier) {
    if (qualifier == nullptr) {
        return ast::Retention::Unspecified;
    }
    // RETAIN, or CODESYS's PERSISTENT, which is kept the same way here.
    return qualifier->getType() == P::NON_RETAIN ? ast::Retention::NonRetain
                                                 : ast::Retention::Retain;
}

void NodeBuilder::qualify(ast::VarSection& section, const antlr4::Token& qualifier) {
    if (qualifier.getType() == P::CONSTANT) {
        section.constant = true;
    } else {
        section.retention = retention(&qualifier);
    }
}

void NodeBuilder::check_qualifiers(const ast::VarSection& section) {
    if (section.constant && section.retention == ast::Retention::Retain) {
        error(DiagnosticCode::E0111, section.range, "a CONSTANT section cannot be RETAIN");
    }
}

bool NodeBuilder::check_global_list(const ast::DeclarationSection& section,
                                    const antlr4::Token& start) {
    const auto* variables = std::get_if<ast::VarSection>(&section);
    if (variables == nullptr || variables->kind != ast::VarSectionKind::Global) {
        error(DiagnosticCode::E0109, range(start),
              "only VAR_GLOBAL can be declared outside a POU or configuration");
        return false;
    }
    return true;
}

void NodeBuilder::locate(ast::VariableDeclaration& declaration, const antlr4::Token& address) {
    if (declaration.names.size() > 1) {
        error(DiagnosticCode::E0112, declaration.names[1].range,
              "AT locates a single variable; declare '" + declaration.names[1].name +
                  "' separately");
    }
    declaration.address = direct_address(address);
}

ast::InitializerPtr NodeBuilder::bare_array_initializer(std::vector<ast::ArrayInitElement> elements,
                                                        SourceRange whole) {
    auto result = make<ast::Initializer>();
    result->range = whole;
    result->value = std::move(elements);
    warning(DiagnosticCode::W0101, result->range,
            "array initial values without brackets are a CODESYS V2 form; IEC "
            "61131-3 (6.4.4.5) writes them in brackets: [1, 2, 3]");
    return result;
}

// A type by name: an elementary type keyword, or a derived/FB type to resolve later.
ast::TypeSpec NodeBuilder::named_type(ast::Identifier name) {
    const SourceRange where = name.range;
    if (const auto elementary = ast::elementary_type_from_name(name.name)) {
        if (is_string_type(*elementary)) {
            return {where, ast::StringTypeRef{*elementary, nullptr}};
        }
        return {where, ast::ElementaryTypeRef{*elementary}};
    }
    return {where, ast::NamedTypeRef{std::move(name)}};
}

ast::TypeSpec NodeBuilder::sized_type(SourceRange whole, ast::Identifier base,
                                      ast::ExpressionPtr length, bool parenthesized) {
    const auto elementary = ast::elementary_type_from_name(base.name);
    if (elementary && is_string_type(*elementary)) {
        return {whole, ast::StringTypeRef{*elementary, std::move(length)}};
    }
    // `DWORD (Red)`: a typed enumeration with one value reads like a length in parentheses.
    if (auto* name = std::get_if<ast::NameExpression>(&length->node);
        name != nullptr && parenthesized) {
        std::vector<ast::EnumValue> values;
        values.push_back({std::move(name->name), nullptr});
        return {whole,
                ast::EnumType{make<ast::TypeSpec>(named_type(std::move(base))), std::move(values)}};
    }
    error(DiagnosticCode::E0108, base.range,
          "only STRING and WSTRING take a length; '" + base.name + "' does not");
    return named_type(std::move(base));
}

void NodeBuilder::error(DiagnosticCode code, const SourceRange& where, std::string message) {
    diagnostics_->error(code, where, std::move(message));
}

void NodeBuilder::warning(DiagnosticCode code, const SourceRange& where, std::string message) {
    diagnostics_->warning(code, where, std::move(message));
}

} // namespace eposp::compiler
