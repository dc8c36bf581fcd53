// The selection functions of IEC 61131-3 ed. 3, 6.6.2.5.9 (table 32): MOVE, SEL, MAX, MIN,
// LIMIT and MUX, on every elementary type; strings compare lexicographically (6.6.2.5.10).

#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;
using vm::Opcode;
using vm::Operand;
using vm::stdlib::Family;

void PouGenerator::jump_if_at_most(const Value& a, const Value& b, vm::Label target) {
    if (a.type->kind == sema::TypeKind::String) {
        const auto at_most = compare(ast::BinaryOperator::LessEqual, a, b, nullptr);
        builder_.jump(Opcode::Jt, target, at_most->operand);
        return;
    }
    std::string_view suffix = type_suffix(sema::scalar_of(*a.type));
    if (suffix == "Bool") {
        suffix = "U8";
    }
    builder_.jump(program_.opcodes().get("JLe", suffix), target, a.operand, b.operand);
}

std::optional<Value> PouGenerator::selection(const types::CallTarget& target,
                                             const Arguments& arguments, const sema::Type* hint,
                                             const Destination* dest) {
    // The inputs' count is the manifest's, checked by the typing stage.
    const vm::stdlib::StandardFunction& function = *vm::stdlib::find_standard_function(target.name);
    const Family family = function.family;
    const std::size_t first = family == Family::Select || family == Family::Multiplex ? 1 : 0;
    if (family == Family::Move) {
        return eval(*arguments[0]->value, hint, dest);
    }
    if (target.operand == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0303); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    std::optional<Value> selector;
    if (family == Family::Select) {
        selector = value_as(*arguments[0]->value, types_.elementary(E::Bool));
    } else if (family == Family::Multiplex) {
        selector = as_dint(*arguments[0]->value);
    }
    if (first == 1 && !selector) {
        return std::nullopt;
    }
    // The values as the common type the typing stage gave the inputs: a literal laid out in
    // it, a string kept at its own capacity (it is copied into the result's).
    const sema::Type& type = *target.operand;
    std::vector<std::optional<Value>> values(arguments.size());
    for (std::size_t i = first; i < arguments.size(); ++i) {
        values[i] = eval(*arguments[i]->value, &type);
        if (!values[i]) {
            return std::nullopt;
        }
        values[i] = convert(*values[i], type, nullptr);
    }
    // The destination when no argument lives there (so none is overwritten before it is
    // read), else a temporary of its own (an argument's may be shared with the value cache).
    bool dest_free = dest != nullptr && dest->type == &type;
    for (std::size_t i = first; dest_free && i < arguments.size(); ++i) {
        dest_free = values[i]->operand.raw != dest->operand.raw;
    }
    const Value result{dest_free ? dest->operand : temp(type), &type};
    const vm::Label done = builder_.label();
    if (family == Family::Select) {
        const vm::Label one = builder_.label();
        builder_.jump(Opcode::Jt, one, selector->operand);
        move(result.operand, type, *values[1]);
        builder_.jump(Opcode::Jmp, done);
        bind(one);
        move(result.operand, type, *values[2]);
    } else if (family == Family::Multiplex) {
        // 6.6.2.5.9: K selects IN0..INn; out of range gives IN0 here.
        move(result.operand, type, *values[1]);
        for (std::size_t i = 2; i < arguments.size(); ++i) {
            const vm::Label next = builder_.label();
            const std::int32_t k = static_cast<std::int32_t>(i - 1);
            builder_.jump(Opcode::JNe32, next, selector->operand,
                          program_.constant({static_cast<std::uint8_t>(k), 0, 0, 0}, 4));
            move(result.operand, type, *values[i]);
            builder_.jump(Opcode::Jmp, done);
            bind(next);
        }
    } else if (family == Family::Limit) {
        const Value& low = *values[0];
        const Value& in = *values[1];
        const Value& high = *values[2];
        const vm::Label above_low = builder_.label();
        move(result.operand, type, in);
        jump_if_at_most(low, result, above_low);
        move(result.operand, type, low);
        builder_.jump(Opcode::Jmp, done);
        bind(above_low);
        jump_if_at_most(result, high, done);
        move(result.operand, type, high);
    } else {
        move(result.operand, type, *values[0]);
        const bool maximum = function.operation == vm::stdlib::Operation::Maximum;
        for (std::size_t i = 1; i < arguments.size(); ++i) {
            const vm::Label keep = builder_.label();
            jump_if_at_most(maximum ? *values[i] : result, maximum ? result : *values[i], keep);
            move(result.operand, type, *values[i]);
            bind(keep);
        }
    }
    bind(done);
    return result;
}

} // namespace eposp::compiler::codegen
