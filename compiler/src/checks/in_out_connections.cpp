// E0413: a VAR_IN_OUT has no value of its own, so every call connects it (IEC 61131-3 ed. 3,
// 6.6.1.2.2; an FB keeps the reference only for the call, as CODESYS requires), and so does a
// native function's ANY input, which the host reads through the argument's address.

#include "calls.hpp"
#include "pou_checks.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <vector>

namespace eposp::compiler::checks {
namespace {

// Whether `field` of the called POU has no value unless the call gives one.
bool needs_argument(const sema::Field& field, bool native) {
    return field.declaration != nullptr &&
           (field.section == ast::VarSectionKind::InOut ||
            (native && field.section == ast::VarSectionKind::Input && field.type->generic));
}

void check_call(const PouUnderCheck& check, const ast::Expression& expression,
                const ast::CallExpression& call) {
    const Callee callee = callee_of(check.program, call);
    if (callee.frame == nullptr || callee.pou == nullptr) {
        return;
    }
    const bool instance = callee.kind == Callee::Kind::Instance;
    const bool native = !instance && check.calls.is_native(*callee.pou);
    std::vector<const sema::Field*> given;
    std::size_t positional = 0;
    for (const ast::Argument& argument : call.arguments) {
        if (!is_enable_argument(argument)) {
            // An FB call's positional arguments connect nothing (E0415).
            given.push_back(instance && !argument.name
                                ? nullptr
                                : sema::formal_parameter(*callee.frame, argument, positional));
        }
    }
    for (const sema::Field& field : callee.frame->fields) {
        if (!needs_argument(field, native) ||
            std::find(given.begin(), given.end(), &field) != given.end()) {
            continue;
        }
        const std::string& pou = instance ? callee.frame->name : callee.pou->name.name;
        check.diagnostics.error(
            DiagnosticCode::E0413, instance ? call.callee->range : expression.range,
            native ? fmt::format("{} '{}' of '{}' must be given",
                                 field.section == ast::VarSectionKind::InOut ? "the VAR_IN_OUT"
                                                                             : "the ANY input",
                                 field.name, pou)
                   : fmt::format("VAR_IN_OUT '{}' of '{}' must be connected", field.name, pou));
    }
}

} // namespace

void check_in_out_connections(const PouUnderCheck& check) {
    for (const ast::Expression* call : check.body.calls()) {
        check_call(check, *call, std::get<ast::CallExpression>(call->node));
    }
}

} // namespace eposp::compiler::checks
