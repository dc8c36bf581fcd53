// Operands typed: literals (an untyped one takes its context's type, 6.3.3), names, members,
// array elements; what is a variable.

#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

bool fits(const ast::IntegerLiteral& literal, ast::ElementaryType type) {
    const auto range = ast::integer_range(type);
    if (!range) {
        return ast::is_real(type);
    }
    if (literal.negative) {
        return literal.magnitude == 0 ||
               (range->min < 0 &&
                literal.magnitude - 1 <= static_cast<std::uint64_t>(-(range->min + 1)));
    }
    return literal.magnitude <= range->max;
}

} // namespace

bool ExpressionTyper::is_variable(const ast::Expression& expression) const {
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = model_.resolved(name->name);
        return symbol == nullptr || symbol->kind == sema::SymbolKind::Variable ||
               (symbol->kind == sema::SymbolKind::Pou && symbol->pou == current_);
    }
    return std::holds_alternative<ast::MemberExpression>(expression.node) ||
           std::holds_alternative<ast::IndexExpression>(expression.node) ||
           std::holds_alternative<ast::DereferenceExpression>(expression.node) ||
           std::holds_alternative<ast::DirectAddressExpression>(expression.node);
}

bool ExpressionTyper::names_program(const ast::Expression& expression) const {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    const sema::Symbol* symbol = name != nullptr ? model_.resolved(name->name) : nullptr;
    return symbol != nullptr &&
           ((symbol->kind == sema::SymbolKind::Pou && symbol->pou->kind == ast::PouKind::Program) ||
            symbol->kind == sema::SymbolKind::ProgramInstance);
}

const sema::Type* ExpressionTyper::variable_type(const sema::Symbol& symbol) {
    if (symbol.variable != nullptr) {
        return program_.types().resolve(symbol.variable->type);
    }
    if (!symbol.standard_type.empty()) {
        if (const auto e = ast::elementary_type_from_name(symbol.standard_type)) {
            return &elementary(*e);
        }
    }
    return nullptr;
}

const sema::Type* ExpressionTyper::literal(const ast::Expression& expression,
                                           const ast::Literal& literal,
                                           const sema::Type* expected) {
    if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal)) {
        if (integer->type) {
            if (!fits(*integer, *integer->type)) {
                return fail(
                    DiagnosticCode::E0311, expression.range,
                    fmt::format("the literal does not fit {}", ast::name_of(*integer->type)));
            }
            return &elementary(*integer->type);
        }
        if (numeric_context(expected) && fits(*integer, expected->elementary)) {
            return &program_.types().unranged(*expected);
        }
        for (const E e : {E::Dint, E::Lint, E::Ulint}) {
            if (fits(*integer, e)) {
                return &elementary(e);
            }
        }
        return fail(DiagnosticCode::E0311, expression.range, "the literal fits no integer type");
    }
    if (const auto* real = std::get_if<ast::RealLiteral>(&literal)) {
        if (real->type) {
            return &elementary(*real->type);
        }
        return expected != nullptr && sema::is_real(*expected) ? expected : &elementary(E::Lreal);
    }
    if (std::holds_alternative<ast::BoolLiteral>(literal)) {
        return &elementary(E::Bool);
    }
    if (const auto* duration = std::get_if<ast::DurationLiteral>(&literal)) {
        return &elementary(duration->type);
    }
    if (const auto* date = std::get_if<ast::DateTimeLiteral>(&literal)) {
        return &elementary(date->type);
    }
    if (const auto* text = std::get_if<ast::StringLiteral>(&literal)) {
        if (text->type == E::Char || text->type == E::Wchar) {
            return &elementary(text->type);
        }
        // Of the capacity of the STRING it goes to where it fits, so that storing it is one
        // copy; else of its own length. No value is a STRING[0] (a declaration refuses it): ''
        // is a STRING[1].
        const bool wide = text->type == E::Wstring;
        const auto length = static_cast<std::uint32_t>(std::max<std::size_t>(
            std::visit([](const auto& value) { return value.size(); }, text->value), 1));
        if (expected != nullptr && expected->kind == sema::TypeKind::String &&
            expected->wide == wide && expected->capacity >= length) {
            return expected;
        }
        return &program_.types().string(length, wide);
    }
    if (std::holds_alternative<ast::EnumValueLiteral>(literal)) {
        const sema::Symbol* value = model_.enum_value(expression);
        return value != nullptr ? program_.types().enumeration_of(*value) : nullptr;
    }
    // NULL is the reference it goes to.
    return expected != nullptr && expected->kind == sema::TypeKind::Reference
               ? expected
               : &program_.types().null();
}

const sema::Type* ExpressionTyper::name(const ast::Expression& expression,
                                        const ast::NameExpression& node) {
    if (const sema::Symbol* value = model_.enum_value(expression)) {
        return program_.types().enumeration_of(*value);
    }
    const sema::Symbol* symbol = model_.resolved(node.name);
    if (symbol == nullptr) {
        return nullptr; // reported by name resolution
    }
    if (symbol->kind == sema::SymbolKind::Variable) {
        return variable_type(*symbol);
    }
    // Inside a FUNCTION its name is its result variable (6.6.2.2).
    if (symbol->kind == sema::SymbolKind::Pou && symbol->pou == current_ &&
        symbol->pou->kind == ast::PouKind::Function && symbol->pou->return_type) {
        return program_.types().resolve(*symbol->pou->return_type);
    }
    // A PROGRAM's name stands for its single instance: `P()`, `P.x` (CODESYS).
    if (symbol->kind == sema::SymbolKind::Pou && symbol->pou->kind == ast::PouKind::Program) {
        return program_.types().instance(*symbol->pou);
    }
    // A configuration's program instance (in a program connection, `P1.out`).
    if (symbol->kind == sema::SymbolKind::ProgramInstance) {
        return program_instance(*symbol->program_instance);
    }
    return fail(DiagnosticCode::E0204, expression.range,
                fmt::format("'{}' is not a variable", symbol->name));
}

const sema::Type* ExpressionTyper::member(const ast::Expression& expression,
                                          const ast::MemberExpression& node) {
    if (const sema::Symbol* value = model_.enum_value(expression)) {
        return program_.types().enumeration_of(*value);
    }
    const sema::Type* object = type(*node.object, nullptr);
    if (object == nullptr) {
        return nullptr;
    }
    const sema::Field* field =
        object->kind == sema::TypeKind::Struct || object->kind == sema::TypeKind::Instance
            ? object->field(node.member.name)
            : nullptr;
    if (field == nullptr) {
        return fail(DiagnosticCode::E0206, node.member.range,
                    fmt::format("'{}' has no member '{}'", object->name, node.member.name));
    }
    // 6.5.2.2: only inputs and outputs of an instance are visible outside it; a PROGRAM
    // reached by its name shows all its variables but its in-outs and temporaries (CODESYS).
    const bool program = names_program(*node.object);
    const bool internal = program ? field->section == ast::VarSectionKind::InOut ||
                                        field->section == ast::VarSectionKind::Temp ||
                                        field->declaration == nullptr
                                  : object->kind == sema::TypeKind::Instance &&
                                        (field->section == ast::VarSectionKind::Var ||
                                         field->section == ast::VarSectionKind::InOut);
    if (internal) {
        return fail(DiagnosticCode::E0212, node.member.range,
                    fmt::format("'{}' is internal to '{}'", field->name, object->name));
    }
    return field->type;
}

const sema::Type* ExpressionTyper::index(const ast::Expression& expression,
                                         const ast::IndexExpression& node) {
    const sema::Type* array = type(*node.array, nullptr);
    for (const ast::ExpressionPtr& index : node.indices) {
        const sema::Type* type = this->type(*index, nullptr);
        if (type != nullptr && !sema::is_integer(program_.types().unranged(*type)) &&
            type->kind != sema::TypeKind::Enum) {
            diagnostics_.error(
                DiagnosticCode::E0307, index->range,
                fmt::format("an array index must be an integer, not {}", type->name));
        }
    }
    if (array == nullptr) {
        return nullptr;
    }
    if (array->kind != sema::TypeKind::Array) {
        return fail(DiagnosticCode::E0308, expression.range,
                    fmt::format("{} is not an array", array->name));
    }
    if (node.indices.size() != array->dimensions.size()) {
        return fail(DiagnosticCode::E0308, expression.range,
                    fmt::format("{} needs {} indices", array->name, array->dimensions.size()));
    }
    return array->element;
}

} // namespace eposp::compiler::types
