// E0414: a call gives each parameter once (IEC 61131-3 ed. 3, 6.6.1.4.2), positionally or by
// its name: `LIMIT(MN := 0, IN := x, IN := 5, MX := 100)` would leave which IN counts to chance.

#include "calls.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>
#include <unordered_map>

namespace eposp::compiler::checks {
namespace {

void check_call(const PouUnderCheck& check, const ast::CallExpression& call) {
    const Callee callee = callee_of(check.program, call);
    if (callee.kind == Callee::Kind::Unknown ||
        (callee.kind != Callee::Kind::StandardFunction && callee.frame == nullptr)) {
        return;
    }
    // A standard function's inputs by their names; a POU's parameters as its frame has them.
    std::unordered_map<std::string, const ast::Argument*> given;
    std::size_t positional = 0;
    for (const ast::Argument& argument : call.arguments) {
        if (is_enable_argument(argument)) {
            continue;
        }
        std::string parameter;
        std::string shown; // as declared, or as written for a standard function
        if (callee.kind == Callee::Kind::StandardFunction) {
            if (!argument.name) {
                continue; // inputs in order, or the call's form is wrong (E0415)
            }
            parameter = sema::fold_case(argument.name->name);
            shown = argument.name->name;
        } else if (const sema::Field* field =
                       sema::formal_parameter(*callee.frame, argument, positional)) {
            parameter = sema::fold_case(field->name);
            shown = field->name;
        } else {
            continue; // no such parameter: E0210, E0306
        }
        const auto [first, inserted] = given.emplace(parameter, &argument);
        if (inserted) {
            continue;
        }
        Diagnostic diagnostic{
            DiagnosticCode::E0414, argument.range,
            callee.kind == Callee::Kind::StandardFunction
                ? fmt::format("input '{}' of {} is given twice", shown, callee.name)
                : fmt::format("'{}' is given twice", shown)};
        diagnostic.notes.push_back({first->second->range, "given first here"});
        check.diagnostics.report(std::move(diagnostic));
    }
}

} // namespace

void check_repeated_parameters(const PouUnderCheck& check) {
    for (const ast::Expression* call : check.body.calls()) {
        check_call(check, std::get<ast::CallExpression>(call->node));
    }
}

} // namespace eposp::compiler::checks
