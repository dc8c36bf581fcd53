// E0415: the form of a call (IEC 61131-3 ed. 3, 6.6.1.4.2, 6.6.1.2.2): EN is an input (`EN :=`)
// and ENO an output (`ENO =>`), both only in a formal call; a function block is called with
// formal arguments; a standard function's call names all its inputs or none.

#include "calls.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

// Whether EN and ENO are written as they must be.
bool check_enable(const ast::CallExpression& call, Diagnostics& diagnostics) {
    const std::size_t errors = diagnostics.error_count();
    const ast::Argument* positional = nullptr;
    bool enable = false;
    for (const ast::Argument& argument : call.arguments) {
        if (!argument.name && positional == nullptr) {
            positional = &argument;
        }
        if (!is_enable_argument(argument)) {
            continue;
        }
        enable = true;
        const bool en = sema::fold_case(argument.name->name) == "EN";
        if (argument.kind != (en ? ast::Argument::Kind::Input : ast::Argument::Kind::Output)) {
            diagnostics.error(DiagnosticCode::E0415, argument.range,
                              en ? "EN is an input: write EN := condition"
                                 : "ENO is an output: write ENO => variable");
        }
    }
    if (positional != nullptr && enable) {
        diagnostics.error(DiagnosticCode::E0415, positional->range,
                          "EN and ENO need a formal call: name every input");
    }
    return diagnostics.error_count() == errors;
}

void check_arguments(const Callee& callee, const ast::CallExpression& call,
                     Diagnostics& diagnostics) {
    if (callee.kind == Callee::Kind::Instance) {
        for (const ast::Argument& argument : call.arguments) {
            if (!argument.name) {
                diagnostics.error(DiagnosticCode::E0415, argument.range,
                                  "a function block call needs formal arguments (IN := x)");
            }
        }
        return;
    }
    // ADR and SIZEOF take a variable or a type, not inputs.
    if (callee.kind != Callee::Kind::StandardFunction || callee.name == "ADR" ||
        callee.name == "SIZEOF") {
        return;
    }
    const auto formal = [](const ast::Argument& a) {
        return a.name.has_value() && !is_enable_argument(a);
    };
    if (std::none_of(call.arguments.begin(), call.arguments.end(), formal)) {
        return;
    }
    const auto positional = std::find_if(call.arguments.begin(), call.arguments.end(),
                                         [](const ast::Argument& a) { return !a.name; });
    if (positional != call.arguments.end()) {
        diagnostics.error(DiagnosticCode::E0415, positional->range,
                          fmt::format("a call of {} names all its inputs or none", callee.name));
    }
}

} // namespace

void check_call_forms(const PouUnderCheck& check) {
    for (const ast::Expression* expression : check.body.calls()) {
        const auto& call = std::get<ast::CallExpression>(expression->node);
        if (check_enable(call, check.diagnostics)) {
            check_arguments(callee_of(check.program, call), call, check.diagnostics);
        }
    }
}

} // namespace eposp::compiler::checks
