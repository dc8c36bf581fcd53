// EN and ENO (IEC 61131-3 ed. 3, 6.6.1.2.2, table 18) on every call: user functions, function
// block instances and standard functions alike. With EN := FALSE the call is not executed and
// ENO is FALSE; otherwise ENO is TRUE after the call (a function that fails stops the task, so
// it never returns with ENO FALSE).

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

#include <fmt/format.h>

namespace eposp::compiler::codegen {

using vm::Opcode;

bool is_enable_argument(const ast::Argument& argument) {
    if (!argument.name) {
        return false;
    }
    const std::string name = sema::fold_case(argument.name->name);
    return name == "EN" || name == "ENO";
}

std::optional<PouGenerator::Enable> PouGenerator::enable_of(const ast::CallExpression& node) {
    Enable enable;
    bool ok = true;
    const ast::Argument* positional = nullptr;
    for (const ast::Argument& argument : node.arguments) {
        if (!argument.name && positional == nullptr) {
            positional = &argument;
        }
        if (!is_enable_argument(argument)) {
            continue;
        }
        const bool en = sema::fold_case(argument.name->name) == "EN";
        const auto kind = en ? ast::Argument::Kind::Input : ast::Argument::Kind::Output;
        if (argument.kind != kind) {
            program_.refused_by_checks(DiagnosticCode::E0415); // checks/call_forms.cpp
            ok = false;
        }
        (en ? enable.en : enable.eno) = &argument;
    }
    // EN and ENO belong to the formal form of a call (6.6.1.2.2).
    if (positional != nullptr && (enable.en != nullptr || enable.eno != nullptr)) {
        program_.refused_by_checks(DiagnosticCode::E0415);
        ok = false;
    }
    return ok ? std::optional(enable) : std::nullopt;
}

bool PouGenerator::with_enable(const Enable& enable, const std::function<void()>& body,
                               const std::function<void()>& skipped) {
    const sema::Type& boolean = types_.elementary(ast::ElementaryType::Bool);
    std::optional<Place> eno;
    if (enable.eno != nullptr) {
        eno = place(*enable.eno->value);
        if (!eno) {
            return false;
        }
        if (eno->type != &boolean) {
            program_.refused_by_checks(DiagnosticCode::E0301); // types/call_typing.cpp
            return false;
        }
        if (!eno->writable) {
            program_.refused_by_checks(DiagnosticCode::E0401); // checks/writable_targets.cpp
            return false;
        }
    }
    const auto set_eno = [&](std::uint8_t bit) {
        if (eno) {
            store(*eno, Value{program_.constant({&bit, &bit + 1}, 1), &boolean});
        }
    };
    if (enable.en == nullptr) {
        body();
        set_eno(1);
        return true;
    }
    const auto condition = value_as(*enable.en->value, boolean);
    if (!condition) {
        return false;
    }
    const vm::Label skip = builder_.label();
    const vm::Label end = builder_.label();
    builder_.jump(Opcode::Jf, skip, condition->operand);
    body();
    set_eno(1);
    builder_.jump(Opcode::Jmp, end);
    bind(skip);
    if (skipped) {
        skipped();
    }
    set_eno(0);
    bind(end);
    return true;
}

std::optional<Value> PouGenerator::call(const ast::Expression& expression, const sema::Type* hint,
                                        const Destination* dest) {
    const auto enable = enable_of(std::get<ast::CallExpression>(expression.node));
    if (!enable) {
        return std::nullopt;
    }
    if (enable->en == nullptr && enable->eno == nullptr) {
        return call_enabled(expression, hint, dest);
    }
    // Inside an expression the call's value goes to a temporary that exists on both paths; a
    // skipped call leaves it at its type's zero (an empty string), so what follows reads a
    // defined value. `y := F(EN := c)` alone is an assignment() that EN skips as a whole.
    std::optional<Value> result;
    const bool ok = with_enable(
        *enable, [&] { result = call_enabled(expression, hint, nullptr); },
        [&] {
            if (result && result->type != nullptr && is_temporary(result->operand)) {
                clear(result->operand, *result->type);
            }
        });
    return ok ? result : std::nullopt;
}

} // namespace eposp::compiler::codegen
