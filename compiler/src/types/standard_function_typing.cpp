// The standard functions of IEC 61131-3 ed. 3, tables 22-36, typed by the ANY_* signature of their
// family in the manifest (vm/stdlib/manifest.hpp).

#include "constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "expression_typer.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

using vm::stdlib::Family;

} // namespace

const sema::Type* ExpressionTyper::named_type(const ast::Expression& expression) {
    const auto* name = std::get_if<ast::NameExpression>(&expression.node);
    if (name == nullptr) {
        return nullptr;
    }
    if (const sema::Symbol* symbol = model_.resolved(name->name)) {
        const bool type = symbol->kind == sema::SymbolKind::Type ||
                          symbol->kind == sema::SymbolKind::StandardFunctionBlock ||
                          (symbol->kind == sema::SymbolKind::Pou &&
                           symbol->pou->kind == ast::PouKind::FunctionBlock);
        return type ? program_.types().named(*symbol) : nullptr;
    }
    // An elementary type's name, which name resolution left unbound.
    const auto elementary = ast::elementary_type_from_name(name->name.name);
    if (!elementary) {
        return nullptr;
    }
    return *elementary == E::String || *elementary == E::Wstring
               ? &program_.types().string(80, *elementary == E::Wstring)
               : &this->elementary(*elementary);
}

const sema::Type* ExpressionTyper::standard_call(const ast::Expression& expression,
                                                 const ast::CallExpression& node,
                                                 const std::string& name,
                                                 const sema::Type* expected) {
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(name);
    if (function == nullptr) {
        return fail(DiagnosticCode::E0504, expression.range,
                    fmt::format("the typing stage does not know {} yet", name));
    }
    inputs(node); // EN and ENO
    for (const ast::Argument& argument : node.arguments) {
        if (argument.kind == ast::Argument::Kind::Output && argument.name &&
            sema::fold_case(argument.name->name) != "ENO") {
            return fail(DiagnosticCode::E0210, argument.range,
                        fmt::format("{} has no outputs", name));
        }
    }
    std::vector<const ast::Expression*> values;
    const auto arguments = standard_arguments(name, node);
    for (const ast::Argument& argument : node.arguments) {
        // An input that names no input of this function, or one past those given.
        if (argument.name &&
            std::find(arguments.begin(), arguments.end(), &argument) == arguments.end()) {
            const std::string input = sema::fold_case(argument.name->name);
            const auto same = [&](const ast::Argument& other) {
                return &other != &argument && other.name &&
                       sema::fold_case(other.name->name) == input;
            };
            if (std::any_of(node.arguments.begin(), node.arguments.end(), same)) {
                return nullptr; // an input given twice: the checking stage's (E0414)
            }
            if (input != "EN" && input != "ENO") {
                return fail(DiagnosticCode::E0210, argument.range,
                            fmt::format("{} has no input '{}' here", name, argument.name->name));
            }
        }
    }
    for (const ast::Argument* argument : arguments) {
        if (argument == nullptr) {
            // A gap: an input named twice (the checking stage's E0414) or one past the others.
            const auto named = std::find_if(arguments.rbegin(), arguments.rend(),
                                            [](const ast::Argument* a) { return a; });
            if (named != arguments.rend()) {
                return fail(DiagnosticCode::E0210, (*named)->range,
                            fmt::format("{} has no input '{}' here", name,
                                        (*named)->name ? (*named)->name->name : "?"));
            }
            return nullptr;
        }
        values.push_back(argument->value.get());
    }
    const SourceRange& range = expression.range;
    const auto count = [&](std::size_t low, std::size_t high) {
        if (values.size() < low || values.size() > high) {
            diagnostics_.error(DiagnosticCode::E0306, range,
                               fmt::format("{} takes {} inputs, not {}", name, low, values.size()));
            return false;
        }
        return true;
    };
    // `context`: the type an untyped literal takes where it fits (else its own, DINT or wider).
    const auto integer = [&](const ast::Expression& value, E context = E::Dint) {
        const sema::Type* type = this->type(value, &elementary(context));
        if (type != nullptr && !sema::is_integer(program_.types().unranged(*type))) {
            diagnostics_.error(DiagnosticCode::E0305, value.range,
                               fmt::format("{} needs an integer here, not {}", name, type->name));
        }
    };
    const auto string = [&](const ast::Expression& value) {
        const sema::Type* type = this->type(value, nullptr);
        if (type != nullptr && type->kind != sema::TypeKind::String) {
            diagnostics_.error(
                DiagnosticCode::E0305, value.range,
                fmt::format("{} needs a STRING or WSTRING here, not {}", name, type->name));
            return static_cast<const sema::Type*>(nullptr);
        }
        return type;
    };
    CallTarget target{.kind = CallKind::StandardFunction, .name = name};
    if (!count(function->min_inputs, function->max_inputs)) {
        return nullptr;
    }
    const sema::Type* result = nullptr;
    const Family family = function->family;
    switch (family) {
    case Family::Absolute:
    case Family::Move:
    case Family::Real:
        if (family != Family::Real || function->max_inputs == 1) {
            const bool real = family == Family::Real;
            const sema::Type* operand =
                type(*values[0], real && (expected == nullptr || !sema::is_real(*expected))
                                     ? &elementary(E::Lreal)
                                     : expected);
            if (operand == nullptr) {
                return nullptr;
            }
            operand = &program_.types().unranged(*operand);
            if (real && !sema::is_real(*operand)) {
                return fail(DiagnosticCode::E0305, range,
                            fmt::format("{} needs a REAL or LREAL, not {}", name, operand->name));
            }
            if (family == Family::Absolute && !sema::is_numeric(*operand)) {
                return fail(DiagnosticCode::E0305, range,
                            fmt::format("ABS needs a number, not {}", operand->name));
            }
            target.operand = result = operand;
            break;
        }
        [[fallthrough]];
    case Family::Power: {
        const sema::Type* real =
            expected != nullptr && sema::is_real(*expected) ? expected : &elementary(E::Lreal);
        const sema::Type* base =
            family == Family::Real ? unify(values, real, range) : type(*values[0], real);
        if (family == Family::Power) {
            const sema::Type* exponent = type(*values[1], nullptr);
            if (exponent != nullptr && !sema::is_numeric(program_.types().unranged(*exponent))) {
                return fail(DiagnosticCode::E0305, values[1]->range,
                            fmt::format("{} needs a number here, not {}", name, exponent->name));
            }
        }
        if (base == nullptr) {
            return nullptr;
        }
        target.operand = result = sema::is_real(*base) ? base : &elementary(E::Lreal);
        if (family == Family::Power) {
            power_input(*values[1], *result);
        }
        break;
    }
    case Family::Arithmetic:
    case Family::Logic:
    case Family::Extreme:
    case Family::Limit: {
        const sema::Type* first = nullptr;
        if (family == Family::Arithmetic && !is_untyped_literal(*values[0])) {
            first = type(*values[0], expected);
            if (first == nullptr) {
                for (std::size_t i = 1; i < values.size(); ++i) {
                    type(*values[i], nullptr);
                }
                return nullptr;
            }
            if (function->operation != vm::stdlib::Operation::Modulo &&
                sema::is_time_like(program_.types().unranged(*first))) {
                return time_call(expression, *function, values, *first);
            }
        }
        result = unify(values, expected, range, first);
        // MAX, MIN and LIMIT compare: elementary values or strings (table 28).
        if (result != nullptr && (family == Family::Extreme || family == Family::Limit) &&
            ((!sema::is_scalar(*result) && result->kind != sema::TypeKind::String) ||
             result->kind == sema::TypeKind::Reference)) {
            return fail(
                DiagnosticCode::E0305, range,
                fmt::format("{} needs values of an elementary type, not {}", name, result->name));
        }
        if (result != nullptr && family == Family::Arithmetic && !sema::is_numeric(*result) &&
            !sema::is_bit_string(*result)) {
            return fail(DiagnosticCode::E0305, range,
                        fmt::format("{} needs numbers, not {}", name, result->name));
        }
        // AND, OR and XOR take what the operators do; NOT an integer as well.
        if (result != nullptr && family == Family::Logic && !sema::is_bool(*result) &&
            !sema::is_bit_string(*result) &&
            (function->operation != vm::stdlib::Operation::Not || !sema::is_integer(*result))) {
            return fail(DiagnosticCode::E0304, range,
                        function->operation == vm::stdlib::Operation::Not
                            ? fmt::format("NOT needs a BOOL or bit string, not {}", result->name)
                            : fmt::format("AND, OR and XOR need BOOL or bit strings, not {}",
                                          result->name));
        }
        target.operand = result;
        break;
    }
    case Family::Comparison:
        target.operand = unify(values, nullptr, range);
        result = target.operand != nullptr ? &elementary(E::Bool) : nullptr;
        break;
    case Family::Shift:
        target.operand = result = type(*values[0], expected);
        if (result != nullptr && !sema::is_bit_string(program_.types().unranged(*result)) &&
            !sema::is_integer(program_.types().unranged(*result))) {
            return fail(DiagnosticCode::E0305, range,
                        fmt::format("{} needs a bit string, not {}", name, result->name));
        }
        // The count is taken unsigned (codegen: the VM's count is a UDINT).
        integer(*values[1], E::Udint);
        break;
    case Family::Select:
        condition(*values[0]);
        target.operand = result = unify({values[1], values[2]}, expected, range);
        break;
    case Family::Multiplex:
        integer(*values[0]);
        target.operand = result = unify(
            std::vector<const ast::Expression*>(values.begin() + 1, values.end()), expected, range);
        break;
    case Family::Text: {
        // Table 36: the texts first, then the lengths and positions (ANY_INT). The result
        // holds whatever the inputs can make (vm::stdlib::TextResult).
        std::uint32_t capacity = 0;
        bool wide = false;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i >= function->texts) {
                integer(*values[i]);
                continue;
            }
            const sema::Type* text = string(*values[i]);
            if (text == nullptr) {
                return nullptr;
            }
            if (i > 0 && text->wide != wide) {
                return fail(DiagnosticCode::E0305, values[i]->range,
                            fmt::format("{} needs a {} here, not {}", name,
                                        wide ? "WSTRING" : "STRING", text->name));
            }
            wide = text->wide;
            capacity = vm::stdlib::text_capacity(function->text_result, capacity, text->capacity);
        }
        result = function->text_result == vm::stdlib::TextResult::Count
                     ? &elementary(E::Int)
                     : &program_.types().string(capacity, wide);
        break;
    }
    case Family::Bound: {
        const sema::Type* array = type(*values[0], nullptr);
        type(*values[1], &elementary(E::Dint));
        if (array != nullptr && array->kind != sema::TypeKind::Array) {
            return fail(DiagnosticCode::E0305, values[0]->range,
                        fmt::format("{} needs an array, not {}", name, array->name));
        }
        const auto dimension = program_.constants().fold_integer(*values[1]);
        if (array != nullptr &&
            (!dimension || *dimension < 1 ||
             *dimension > static_cast<std::int64_t>(array->dimensions.size()))) {
            return fail(DiagnosticCode::E0313, values[1]->range,
                        fmt::format("the dimension must be a constant from 1 to {}",
                                    array->dimensions.size()));
        }
        result = &elementary(E::Dint);
        break;
    }
    case Family::Time: {
        // Table 30: fixed signatures; MUL_TIME and DIV_TIME scale by any number.
        const vm::stdlib::TimeRule& time = function->time;
        expect(*values[0], elementary(elementary_of(time.first)), "a time");
        if (!time.scaled) {
            expect(*values[1], elementary(elementary_of(time.second)), "a time");
        } else {
            const sema::Type* factor = type(*values[1], &elementary(E::Lint));
            if (factor != nullptr && !sema::is_numeric(*factor)) {
                return fail(DiagnosticCode::E0305, range,
                            fmt::format("{} scales by a number, not {}", name, factor->name));
            }
        }
        target.operand = &elementary(elementary_of(time.first));
        result = &elementary(elementary_of(time.result));
        break;
    }
    case Family::Address:
    case Family::Size: {
        const sema::Type* named = family == Family::Size ? named_type(*values[0]) : nullptr;
        const sema::Type* object = named != nullptr ? named : type(*values[0], nullptr);
        if (object == nullptr) {
            return nullptr;
        }
        // ADR is an address for any POINTER TO; SIZEOF is a constant of the smallest unsigned
        // type that holds it, as in CODESYS, so that it fits a UINT parameter as well as a DINT
        // (docs/st-language.md, references and pointers). An ARRAY[*] has no size here: the
        // checking stage refuses its SIZEOF (E0417).
        result = family == Family::Address ? &program_.types().reference(nullptr)
                 : object->size <= 0xFF    ? &elementary(E::Usint)
                 : object->size <= 0xFFFF  ? &elementary(E::Uint)
                                           : &elementary(E::Udint);
        if (family == Family::Size && !object->conformant) {
            program_.set_constant(expression, std::uint64_t{object->size});
        }
        break;
    }
    case Family::Truncate: // typed as a conversion (expression_typer.cpp)
        return fail(DiagnosticCode::E0504, range,
                    fmt::format("the typing stage does not know {} yet", name));
    }
    if (result == nullptr) {
        return nullptr;
    }
    target.result = result;
    program_.set_call(expression, target);
    return result;
}

const sema::Type* ExpressionTyper::time_call(const ast::Expression& expression,
                                             const vm::stdlib::StandardFunction& function,
                                             const std::vector<const ast::Expression*>& values,
                                             const sema::Type& first) {
    // Table 30's note: ADD, SUB, MUL and DIV on times are the row of table 30 their operator
    // takes (ADD(t, lt) is ADD_LTIME), called as that row is. ADD and MUL are extensible
    // (table 24): ADD(tod, t1, t2) is (tod + t1) + t2, each step a row.
    const std::string name(function.name);
    const auto type_from = [&](std::size_t i) {
        for (; i < values.size(); ++i) {
            type(*values[i], nullptr);
        }
    };
    const bool scaled = function.operation == vm::stdlib::Operation::Multiply ||
                        function.operation == vm::stdlib::Operation::Divide;
    const sema::Type* result = &first;
    const vm::stdlib::StandardFunction* row = nullptr;
    for (std::size_t i = 1; i < values.size(); ++i) {
        const sema::Type* next = type(*values[i], scaled ? &elementary(E::Lint) : nullptr);
        if (next == nullptr) {
            type_from(i + 1);
            return nullptr;
        }
        row = time_row(function.operation, *result, *next);
        if (row == nullptr) {
            type_from(i + 1);
            return fail(DiagnosticCode::E0305, expression.range,
                        fmt::format("{} is not defined on {} and {} (IEC 61131-3 table 30)", name,
                                    result->name, next->name));
        }
        result = &elementary(elementary_of(row->time.result));
    }
    // The last step's row: the earlier ones are of the same kind, short or long, and every time
    // is nanoseconds in 64 bits, so that code generation and the folder take it for each step.
    program_.set_call(expression, CallTarget{.kind = CallKind::StandardFunction,
                                             .name = std::string(row->name),
                                             .operand = &elementary(elementary_of(row->time.first)),
                                             .result = result});
    return result;
}

} // namespace eposp::compiler::types
