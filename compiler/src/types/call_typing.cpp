// Calls typed: user FUNCTIONs, FB instances and PROGRAMs with their arguments (6.6.1.2), and the
// conversions `<T>_TO_<U>` (table 22); standard functions are standard_function_typing.cpp's.

#include "eposp/compiler/sema/standard_library.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

std::string in_out_mismatch(const sema::Field& field, const sema::Type& formal) {
    if (field.type->conformant) {
        return fmt::format("VAR_IN_OUT '{}' needs an array of {} dimension(s) of {}", field.name,
                           formal.dimensions.size(), formal.element->name);
    }
    return fmt::format("VAR_IN_OUT '{}' needs a {} variable", field.name, formal.name);
}

/// Table 22: a WSTRING converts to and from WCHAR only, a STRING to and from every other
/// elementary type; the others between scalars that are no references.
bool converts_explicitly(const sema::Type& from, const sema::Type& to) {
    const bool from_string = from.kind == sema::TypeKind::String;
    const bool to_string = to.kind == sema::TypeKind::String;
    if (from_string && to_string) {
        return true;
    }
    if (from_string || to_string) {
        const sema::Type& other = to_string ? from : to;
        const bool wchar = other.kind == sema::TypeKind::Elementary &&
                           other.elementary == ast::ElementaryType::Wchar;
        return sema::is_scalar(other) && other.kind == sema::TypeKind::Elementary &&
               (to_string ? to.wide : from.wide) == wchar;
    }
    return sema::is_scalar(from) && sema::is_scalar(to) && from.kind != sema::TypeKind::Reference &&
           to.kind != sema::TypeKind::Reference;
}

} // namespace

std::vector<const ast::Argument*> ExpressionTyper::inputs(const ast::CallExpression& node) {
    std::vector<const ast::Argument*> result;
    for (const ast::Argument& argument : node.arguments) {
        if (argument.name && (sema::fold_case(argument.name->name) == "EN" ||
                              sema::fold_case(argument.name->name) == "ENO")) {
            if (argument.kind == ast::Argument::Kind::Input) {
                condition(*argument.value);
            } else if (const sema::Type* eno = type(*argument.value, nullptr);
                       eno != nullptr && !sema::is_bool(*eno)) {
                diagnostics_.error(DiagnosticCode::E0301, argument.value->range,
                                   fmt::format("ENO needs a BOOL variable, not {}", eno->name));
            }
            continue;
        }
        result.push_back(&argument);
    }
    return result;
}

const sema::Type* ExpressionTyper::call(const ast::Expression& expression,
                                        const ast::CallExpression& node,
                                        const sema::Type* expected) {
    if (const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node)) {
        const sema::Symbol* symbol = model_.resolved(callee->name);
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
            symbol->pou->kind == ast::PouKind::Function) {
            return pou_call(expression, node, *symbol->pou, nullptr);
        }
        const std::string upper = sema::fold_case(callee->name.name);
        if ((symbol == nullptr || symbol->kind == sema::SymbolKind::StandardFunction) &&
            (sema::is_conversion_function(upper) || upper == "TRUNC")) {
            return conversion(expression, node, upper);
        }
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::StandardFunction) {
            return standard_call(expression, node, upper, expected);
        }
    }
    if (const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node)) {
        const sema::Symbol* symbol = model_.resolved(callee->name);
        if (symbol != nullptr && (symbol->kind == sema::SymbolKind::StandardFunctionBlock ||
                                  (symbol->kind == sema::SymbolKind::Pou &&
                                   symbol->pou->kind == ast::PouKind::FunctionBlock))) {
            inputs(node);
            return fail(DiagnosticCode::E0204, expression.range,
                        fmt::format("'{}' is a {} type: call an instance of it", symbol->name,
                                    symbol->kind == sema::SymbolKind::Pou ? "FUNCTION_BLOCK"
                                                                          : "function block"));
        }
    }
    const sema::Type* instance = type(*node.callee, nullptr);
    if (instance == nullptr) {
        return nullptr;
    }
    if (instance->kind != sema::TypeKind::Instance || instance->pou == nullptr) {
        return fail(DiagnosticCode::E0204, node.callee->range,
                    fmt::format("a {} cannot be called: it is not a function block instance",
                                instance->name));
    }
    return pou_call(expression, node, *instance->pou, instance);
}

const sema::Type* ExpressionTyper::pou_call(const ast::Expression& expression,
                                            const ast::CallExpression& node, const ast::Pou& pou,
                                            const sema::Type* instance) {
    // Positional arguments take the inputs and in-outs in declaration order (6.6.1.4.2).
    const sema::Type* frame = instance != nullptr ? instance : program_.types().frame(pou);
    std::vector<const sema::Field*> positional;
    if (frame != nullptr) {
        for (const sema::Field& field : frame->fields) {
            if (field.section == ast::VarSectionKind::Input ||
                field.section == ast::VarSectionKind::InOut) {
                positional.push_back(&field);
            }
        }
    }
    std::size_t next = 0;
    const std::string& callee = instance != nullptr ? instance->name : pou.name.name;
    for (const ast::Argument* argument : inputs(node)) {
        const sema::Field* field = nullptr;
        if (argument->name) {
            field = frame != nullptr ? frame->field(argument->name->name) : nullptr;
        } else if (next < positional.size()) {
            field = positional[next++];
        }
        const bool output = argument->kind == ast::Argument::Kind::Output;
        if (field == nullptr) {
            type(*argument->value, nullptr);
            // An FB's positional arguments are the checking stage's (E0415).
            if (argument->name || instance == nullptr) {
                diagnostics_.error(
                    argument->name ? DiagnosticCode::E0210 : DiagnosticCode::E0306, argument->range,
                    argument->name ? fmt::format("'{}' has no {} '{}'", callee,
                                                 output ? "output" : "input", argument->name->name)
                                   : fmt::format("too many arguments for '{}'", callee));
            }
            continue;
        }
        if (output != (field->section == ast::VarSectionKind::Output) ||
            (field->section != ast::VarSectionKind::Input &&
             field->section != ast::VarSectionKind::InOut &&
             field->section != ast::VarSectionKind::Output)) {
            type(*argument->value, nullptr);
            diagnostics_.error(DiagnosticCode::E0210, argument->range,
                               fmt::format("'{}' is not an {} of '{}'", field->name,
                                           output ? "output" : "input", callee));
            continue;
        }
        if ((output || field->section == ast::VarSectionKind::InOut) &&
            !is_variable(*argument->value)) {
            type(*argument->value, nullptr);
            diagnostics_.error(DiagnosticCode::E0315, argument->value->range,
                               "this expression is not a variable");
            continue;
        }
        if (field->type->generic) {
            // ANY (a native function's): an elementary value or a string, with its own type.
            const sema::Type* actual = type(*argument->value, nullptr);
            if (actual != nullptr && actual->kind != sema::TypeKind::Elementary &&
                actual->kind != sema::TypeKind::Enum && actual->kind != sema::TypeKind::String) {
                diagnostics_.error(
                    DiagnosticCode::E0305, argument->value->range,
                    fmt::format("ANY takes an elementary value or a string, not a {}",
                                actual->name));
            }
            continue;
        }
        if (output) {
            const sema::Type* target = type(*argument->value, nullptr);
            if (target != nullptr && !sema::converts_implicitly(*field->type, *target)) {
                diagnostics_.error(DiagnosticCode::E0301, argument->range,
                                   fmt::format("output {} of type {} goes into {}", field->name,
                                               field->type->name, target->name));
            }
        } else if (field->section == ast::VarSectionKind::InOut) {
            // A VAR_IN_OUT is held as a reference to the variable passed (6.6.1.2.2).
            const bool by_reference =
                field->type->kind == sema::TypeKind::Reference ||
                (field->type->kind == sema::TypeKind::Struct && field->type->conformant);
            const sema::Type& formal = by_reference && field->type->element != nullptr
                                           ? *field->type->element
                                           : *field->type;
            const sema::Type* actual = type(*argument->value, &formal);
            if (actual != nullptr && !sema::same_type(*actual, formal) &&
                !sema::conforms(*actual, formal) &&
                !(actual->kind == sema::TypeKind::String && formal.kind == actual->kind)) {
                diagnostics_.error(DiagnosticCode::E0302, argument->range,
                                   in_out_mismatch(*field, formal));
            }
        } else {
            store(*argument->value, *field->type, "an input");
        }
    }
    CallTarget target;
    target.pou = &pou;
    if (instance != nullptr) {
        const ast::Pou* library = nullptr;
        target.kind = CallKind::FunctionBlock;
        if (const sema::Symbol* symbol = model_.global().find(pou.name.name);
            symbol != nullptr && symbol->kind == sema::SymbolKind::StandardFunctionBlock) {
            library = &pou;
        }
        if (library != nullptr) {
            target.kind = CallKind::StandardFunctionBlock;
            target.name = sema::fold_case(pou.name.name);
        }
        program_.set_call(expression, target);
        return nullptr;
    }
    target.kind = CallKind::Function;
    target.result = pou.return_type ? program_.types().resolve(*pou.return_type) : nullptr;
    program_.set_call(expression, target);
    return target.result;
}

const sema::Type* ExpressionTyper::conversion(const ast::Expression& expression,
                                              const ast::CallExpression& node,
                                              const std::string& name) {
    inputs(node); // EN and ENO
    const auto arguments = standard_arguments("TO", node);
    if (arguments.size() != 1 || arguments[0] == nullptr) {
        return fail(DiagnosticCode::E0306, expression.range,
                    fmt::format("{} takes one input", name));
    }
    CallTarget target{.kind = CallKind::Conversion, .name = name};
    const sema::Type* source = nullptr;
    const sema::Type* result = nullptr;
    if (name == "TRUNC") {
        // Table 22: TRUNC of an ANY_REAL; the project truncates to DINT.
        source = type(*arguments[0]->value, nullptr);
        if (source != nullptr && !sema::is_real(*source)) {
            return fail(DiagnosticCode::E0305, expression.range,
                        fmt::format("TRUNC needs a REAL, not {}", source->name));
        }
        result = &elementary(E::Dint);
    } else {
        const auto separator = name.find("_TO_");
        const std::string to =
            name.starts_with("TO_") ? name.substr(3) : name.substr(separator + 4);
        const auto to_type = ast::elementary_type_from_name(to);
        result = *to_type == E::String || *to_type == E::Wstring
                     ? &program_.types().string(80, *to_type == E::Wstring)
                     : &elementary(*to_type);
        if (name.starts_with("TO_")) {
            source = type(*arguments[0]->value, nullptr);
        } else {
            const auto from = *ast::elementary_type_from_name(name.substr(0, separator));
            const sema::Type& from_type = from == E::String || from == E::Wstring
                                              ? program_.types().string(80, from == E::Wstring)
                                              : elementary(from);
            expect(*arguments[0]->value, from_type, "a conversion's input");
            source = &from_type;
        }
    }
    if (source == nullptr) {
        return nullptr;
    }
    if (!converts_explicitly(program_.types().unranged(*source), *result)) {
        return fail(DiagnosticCode::E0310, expression.range,
                    fmt::format("{} cannot be converted to {}", source->name, result->name));
    }
    target.operand = &program_.types().unranged(*source);
    target.result = result;
    program_.set_call(expression, target);
    return result;
}

} // namespace eposp::compiler::types
