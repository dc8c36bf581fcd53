// Statements of IEC 61131-3 ed. 3, 7.3.3 (table 72).

#include "../lower/if_conversion.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::codegen {

using vm::Opcode;
using vm::Operand;

void PouGenerator::statements(const ast::StatementList& list) {
    for (const ast::Statement& statement : list) {
        this->statement(statement);
    }
}

void PouGenerator::statement(const ast::Statement& statement) {
    builder_.line(statement.range.begin.line);
    const std::uint32_t mark = frame_top_; // temporaries live for one statement
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                assignment(node);
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                call(*node.call, nullptr, nullptr);
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                if_statement(node);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                case_statement(node);
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                for_statement(node, statement.range);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                while_statement(node);
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                repeat_statement(node);
            } else if constexpr (std::is_same_v<T, ast::ExitStatement> ||
                                 std::is_same_v<T, ast::ContinueStatement>) {
                if (!loops_.empty()) { // outside a loop: E0405 (checks/loop_exits.cpp)
                    builder_.jump(Opcode::Jmp, std::is_same_v<T, ast::ExitStatement>
                                                   ? loops_.back().exit
                                                   : loops_.back().next);
                }
            } else if constexpr (std::is_same_v<T, ast::ReturnStatement>) {
                builder_.jump(Opcode::Jmp, end_);
            }
        },
        statement.node);
    release(mark);
}

void PouGenerator::bit_assignment(const ast::BitAccessExpression& target,
                                  const ast::Expression& value) {
    const auto word_place = place(*target.object);
    const auto word = word_place ? bit_word(target) : std::nullopt;
    const auto bit =
        word ? value_as(value, types_.elementary(ast::ElementaryType::Bool)) : std::nullopt;
    if (!bit) {
        return;
    }
    if (!word_place->writable) {
        program_.refused_by_checks(DiagnosticCode::E0401); // checks/writable_targets.cpp
        return;
    }
    // word := (word AND NOT mask) OR (BOOL_TO_<word>(bit) << n)
    const sema::Type& type = *word->type;
    const Operand cleared = temp(type);
    emit(op_width("And", type), cleared, word->operand, bit_mask(type, target.bit, true));
    const Operand shifted_bit = temp(type);
    emit(program_.opcodes().get("Cvt", "Bool" + std::string(type_suffix(sema::scalar_of(type)))),
         shifted_bit, bit->operand);
    const std::uint8_t count[4] = {static_cast<std::uint8_t>(target.bit), 0, 0, 0};
    emit(op_width("Shl", type), shifted_bit, shifted_bit, program_.constant({count, count + 4}, 4));
    emit(op_width("Or", type), cleared, cleared, shifted_bit);
    store(*word_place, *value_as(Value{cleared, &type}, *word_place->type));
}

void PouGenerator::assignment(const ast::AssignmentStatement& node) {
    if (const auto* bit = std::get_if<ast::BitAccessExpression>(&node.target->node)) {
        bit_assignment(*bit, *node.value);
        return;
    }
    const auto target = place(*node.target);
    if (!target) {
        eval(*node.value, nullptr); // still check the right-hand side
        return;
    }
    if (!target->writable) {
        program_.refused_by_checks(DiagnosticCode::E0401); // checks/writable_targets.cpp
        return;
    }
    if (target->type->kind == sema::TypeKind::Instance || target->type->conformant) {
        return; // refused by the checks (E0412, checks/whole_assignments.cpp)
    }
    const Destination dest{target->operand, target->type};
    const Destination* into = target->kind == Place::Kind::Direct ? &dest : nullptr;
    const auto* call_node = std::get_if<ast::CallExpression>(&node.value->node);
    const auto enable = call_node != nullptr ? enable_of(*call_node) : std::optional(Enable{});
    if (!enable) {
        return;
    }
    if (enable->en == nullptr && enable->eno == nullptr) {
        if (const auto value = value_as(*node.value, *target->type, into)) {
            store(*target, *value);
        }
        return;
    }
    // `y := F(EN := c, ...)`: a call that EN skips leaves y as it was (IEC 61131-3 ed. 3,
    // 6.6.1.2.2), so EN guards the whole assignment.
    with_enable(*enable, [&] {
        auto value = function_value(call_enabled(*node.value, target->type, into));
        if (value) {
            value = value_as(*value, *target->type, into);
        }
        if (value) {
            store(*target, *value);
        }
    });
}

void PouGenerator::if_statement(const ast::IfStatement& node) {
    if (select_statement(node)) {
        return;
    }
    const vm::Label end = builder_.label();
    for (std::size_t i = 0; i < node.branches.size(); ++i) {
        const ast::ConditionalBlock& block = node.branches[i];
        const vm::Label next = builder_.label();
        // The condition's temporaries live on through the branch, which may reuse them.
        branch(*block.condition, false, next);
        statements(block.body);
        if (i + 1 < node.branches.size() || !node.else_body.empty()) {
            builder_.jump(Opcode::Jmp, end);
        }
        bind(next);
    }
    statements(node.else_body);
    bind(end);
}

bool PouGenerator::is_for_variable(const Place& place) const {
    return place.kind == Place::Kind::Direct &&
           std::find(for_variables_.begin(), for_variables_.end(), place.operand.raw) !=
               for_variables_.end();
}

bool PouGenerator::select_statement(const ast::IfStatement& node) {
    if (!program_.if_conversion()) {
        return false;
    }
    const auto form = lower::select_form(node);
    if (!form) {
        return false;
    }
    // A plain local, instance or global variable of a scalar type that nothing here forbids
    // assigning: the assignment statement keeps the checks and warnings of the other cases.
    const auto& name = std::get<ast::NameExpression>(form->target->node).name;
    const sema::Symbol* symbol = model_.resolved(name);
    if (symbol == nullptr || symbol->kind != sema::SymbolKind::Variable ||
        symbol->section == ast::VarSectionKind::Input) {
        return false;
    }
    if (!locals_.contains(sema::fold_case(symbol->name)) && !program_.global(symbol->name)) {
        return false; // the assignment reports it
    }
    const auto target = variable(*symbol);
    if (!target || target->kind != Place::Kind::Direct || !target->writable ||
        !sema::is_scalar(*target->type) || target->type->range || is_for_variable(*target)) {
        return false;
    }
    const sema::Type& type = *target->type;
    const auto aliases_target = [&](const Value& value) {
        return value.operand.base() == target->operand.base() &&
               value.operand.offset() < target->operand.offset() + type.size &&
               target->operand.offset() < value.operand.offset() + value.type->size;
    };
    // The condition and the chosen value are read after the target may have been written.
    const auto apart = [&](std::optional<Value> value) -> std::optional<Value> {
        if (value && aliases_target(*value)) {
            const Operand copy = temp(*value->type);
            move(copy, *value->type, *value);
            value->operand = copy;
        }
        return value;
    };
    const auto condition = apart(condition_value(*form->condition));
    const auto chosen = condition ? apart(value_as(*form->chosen, type)) : std::nullopt;
    if (!chosen) {
        return true; // reported
    }
    if (form->otherwise != nullptr) {
        const Destination into{target->operand, &type};
        const auto other = value_as(*form->otherwise, type, &into);
        if (!other) {
            return true;
        }
        store(*target, *other);
    }
    emit(program_.opcodes().get("CMov", width_suffix(sema::scalar_of(type))), target->operand,
         condition->operand, chosen->operand);
    return true;
}

void PouGenerator::case_statement(const ast::CaseStatement& node) {
    // 7.3.3.3.3: the selector is evaluated once, then compared with the labels in order.
    auto selector = eval(*node.selector, nullptr);
    if (!selector) {
        return;
    }
    const sema::Type& type = *selector->type;
    if (!sema::is_integer(type) && !sema::is_bit_string(type) &&
        type.kind != sema::TypeKind::Enum) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/statement_typing.cpp
        return;
    }
    const vm::Label end = builder_.label();
    std::vector<vm::Label> bodies;
    std::vector<CaseRange> ranges;
    // Every value of the selector's type is a label: a ULINT or LWORD selector's labels are
    // folded and ordered as unsigned 64-bit numbers (their bits kept in CaseRange).
    const bool unsigned64 = sema::scalar_of(type) == vm::Scalar::U64;
    const auto fold = [&](const ast::Expression& label) -> std::optional<std::int64_t> {
        if (!unsigned64) {
            return program_.typed().constants().fold_integer(label);
        }
        const auto bits = program_.typed().constants().fold_unsigned(label);
        return bits ? std::optional(static_cast<std::int64_t>(*bits)) : std::nullopt;
    };
    for (const ast::CaseBranch& branch_node : node.branches) {
        bodies.push_back(builder_.label());
        for (const ast::CaseLabel& label : branch_node.labels) {
            const auto low_value = fold(*label.low);
            const auto high_value = label.high ? fold(*label.high) : low_value;
            if (!low_value || !high_value) {
                const bool constant =
                    program_.typed().constants().fold_unsigned(*label.low) &&
                    (!label.high || program_.typed().constants().fold_unsigned(*label.high));
                program_.refused_by_checks(
                    constant ? DiagnosticCode::E0301
                             : DiagnosticCode::E0313); // types/statement_typing.cpp
                continue;
            }
            const auto low = value_as(*label.low, type);
            const auto high = label.high ? value_as(*label.high, type) : low;
            if (low && high) {
                ranges.push_back({*low_value, *high_value, low->operand, high->operand,
                                  bodies.back(), !label.high});
            }
        }
    }
    const vm::Label otherwise = builder_.label();
    if (!jump_table(selector->operand, type, ranges, otherwise)) {
        compare_chain(selector->operand, type, ranges);
    }
    bind(otherwise);
    statements(node.else_body);
    builder_.jump(Opcode::Jmp, end);
    for (std::size_t i = 0; i < node.branches.size(); ++i) {
        bind(bodies[i]);
        statements(node.branches[i].body);
        if (i + 1 < node.branches.size()) {
            builder_.jump(Opcode::Jmp, end);
        }
    }
    bind(end);
}

void PouGenerator::compare_chain(Operand selector, const sema::Type& type,
                                 const std::vector<CaseRange>& ranges) {
    const std::string_view suffix = type_suffix(sema::scalar_of(type));
    for (const CaseRange& range : ranges) {
        if (range.single) {
            builder_.jump(op_width("JEq", type), range.body, selector, range.low_operand);
            continue;
        }
        const vm::Label skip = builder_.label();
        builder_.jump(program_.opcodes().get("JLt", suffix), skip, selector, range.low_operand);
        builder_.jump(program_.opcodes().get("JLe", suffix), range.body, selector,
                      range.high_operand);
        bind(skip);
    }
}

bool PouGenerator::jump_table(Operand selector, const sema::Type& type,
                              const std::vector<CaseRange>& ranges, vm::Label otherwise) {
    // A table pays when it replaces several compares and is mostly labels, not holes.
    constexpr std::int64_t kMinValues = 3;
    constexpr std::int64_t kMaxEntries = 1024;
    std::optional<Opcode> op;
    switch (sema::scalar_of(type)) {
    case vm::Scalar::I16:
        op = Opcode::JTabI16;
        break;
    case vm::Scalar::U16:
        op = Opcode::JTabU16;
        break;
    case vm::Scalar::I32:
    case vm::Scalar::U32:
        op = Opcode::JTab32;
        break;
    default:
        break;
    }
    if (!op || ranges.empty()) {
        return false;
    }
    // Labels of a 16- or 32-bit selector: no difference below overflows 64 bits.
    std::int64_t low = ranges.front().low;
    std::int64_t high = ranges.front().high;
    std::int64_t values = 0;
    for (const CaseRange& range : ranges) {
        low = std::min(low, range.low);
        high = std::max(high, range.high);
        values += range.high - range.low + 1;
    }
    const std::int64_t entries = high - low + 1;
    if (values < kMinValues || entries > kMaxEntries || entries > 2 * values) {
        return false;
    }
    std::vector<vm::Label> targets(static_cast<std::size_t>(entries), otherwise);
    // Ranges come in label order; an earlier label wins, as in the compare chain.
    for (auto range = ranges.rbegin(); range != ranges.rend(); ++range) {
        for (std::int64_t v = range->low; v <= range->high; ++v) {
            targets[static_cast<std::size_t>(v - low)] = range->body;
        }
    }
    // low is a value of the selector's type, so it fits 32 bits modulo 2^32.
    const auto table =
        builder_.jump_table(static_cast<std::int32_t>(static_cast<std::uint32_t>(low)), targets);
    builder_.jump(*op, otherwise, selector, Operand::imm(table));
    return true;
}

void PouGenerator::for_statement(const ast::ForStatement& node, const SourceRange& range) {
    const sema::Symbol* symbol = model_.resolved(node.control_variable);
    const auto control = symbol != nullptr ? variable(*symbol) : std::nullopt;
    if (!control) {
        return;
    }
    const sema::Type& type = *control->type;
    if (!sema::is_integer(type) || control->kind != Place::Kind::Direct || !control->writable) {
        return; // refused by the checks (E0403, checks/for_loops.cpp)
    }
    // A constant step (the usual case) uses the For<I> back-edge; another a general loop.
    std::int64_t step = 1;
    bool constant_step = true;
    if (node.by) {
        const auto folded = program_.typed().constants().fold_integer(*node.by);
        constant_step = folded && *folded >= INT16_MIN && *folded <= INT16_MAX;
        step = folded.value_or(0);
        if ((folded && *folded == 0) || (constant_step && !sema::is_signed(type) && step < 0)) {
            return; // a step the checks stage refuses (E0404, checks/for_loops.cpp)
        }
    }
    const Destination dest{control->operand, &type};
    const auto from = value_as(*node.from, type, &dest);
    if (!from) {
        return;
    }
    move(control->operand, type, *from);
    // The limit and step are evaluated once (the loop's own copies), unless constant. They
    // are not values of the control variable, so a subrange does not apply to them.
    const sema::Type& counter = types_.unranged(type);
    auto once = [&](const ast::Expression& expression) -> std::optional<Value> {
        auto value = value_as(expression, counter);
        const bool constant = value && value->operand.base() == vm::Base::Static &&
                              std::holds_alternative<ast::LiteralExpression>(expression.node);
        if (value && !constant && !is_temporary(value->operand)) {
            const Operand copy = temp(counter);
            move(copy, counter, *value);
            value = Value{copy, &counter};
        }
        return value;
    };
    const auto limit = once(*node.to);
    const auto computed_step = limit && !constant_step ? once(*node.by) : std::nullopt;
    if (!limit || (!constant_step && !computed_step)) {
        return;
    }
    const std::string_view suffix = type_suffix(sema::scalar_of(type));
    const vm::Opcode less = program_.opcodes().get("JLt", suffix);
    const Loop loop{builder_.label(), builder_.label()};
    const vm::Label body = builder_.label();
    const vm::Label check = builder_.label();
    if (constant_step) {
        if (step > 0) {
            builder_.jump(less, loop.exit, limit->operand, control->operand);
        } else {
            builder_.jump(less, loop.exit, control->operand, limit->operand);
        }
    } else {
        // Up while the step is >= 0, down otherwise: the sign is known only when running.
        bind(check);
        const vm::Label down = builder_.label();
        builder_.jump(less, down, computed_step->operand,
                      program_.constant(std::vector<std::uint8_t>(type.size, 0), type.align));
        builder_.jump(less, loop.exit, limit->operand, control->operand);
        builder_.jump(Opcode::Jmp, body);
        bind(down);
        builder_.jump(less, loop.exit, control->operand, limit->operand);
    }
    bind(body);
    // A subrange control variable is checked on entering the body, unless a constant limit
    // inside the range keeps every value the body sees inside it.
    const auto constant_limit = program_.typed().constants().fold_integer(*node.to);
    if (type.range && !(constant_step && constant_limit &&
                        (step > 0 ? *constant_limit <= type.range->upper
                                  : *constant_limit >= type.range->lower))) {
        checked(Value{control->operand, &counter}, type);
    }
    loops_.push_back(loop);
    for_variables_.push_back(control->operand.raw);
    statements(node.body);
    for_variables_.pop_back();
    loops_.pop_back();
    bind(loop.next);
    builder_.line(range.begin.line);
    cache_.clear(); // the back-edge writes the control variable
    if (constant_step) {
        builder_.for_loop(program_.opcodes().get("For", suffix), body, control->operand,
                          limit->operand, static_cast<std::int16_t>(step));
    } else {
        // As For<I>: a step past the end of the type (the sum wraps around) ends the loop.
        const Operand next = temp(counter);
        emit(op_width("Add", type), next, control->operand, computed_step->operand);
        const vm::Label down = builder_.label();
        const vm::Label advance = builder_.label();
        const vm::Label wrapped = builder_.label();
        builder_.jump(less, down, computed_step->operand,
                      program_.constant(std::vector<std::uint8_t>(type.size, 0), type.align));
        builder_.jump(less, wrapped, next, control->operand);
        builder_.jump(Opcode::Jmp, advance);
        bind(down);
        builder_.jump(less, wrapped, control->operand, next);
        bind(advance);
        move(control->operand, counter, Value{next, &counter});
        builder_.jump(Opcode::Jmp, check);
        bind(wrapped);
        move(control->operand, counter, Value{next, &counter});
    }
    bind(loop.exit);
    if (type.range) {
        step_back_into_range(control->operand, type,
                             constant_step ? integer_constant(counter, step)
                                           : computed_step->operand);
    }
}

void PouGenerator::while_statement(const ast::WhileStatement& node) {
    conditional_loop(node.body, *node.condition, true, true);
}

void PouGenerator::repeat_statement(const ast::RepeatStatement& node) {
    conditional_loop(node.body, *node.until, false, false);
}

void PouGenerator::conditional_loop(const ast::StatementList& body_statements,
                                    const ast::Expression& condition, bool repeat_when,
                                    bool test_first) {
    // The condition sits after the body (one branch per iteration); WHILE enters at it.
    const Loop loop{builder_.label(), builder_.label()};
    const vm::Label body = builder_.label();
    if (test_first) {
        builder_.jump(Opcode::Jmp, loop.next);
    }
    bind(body);
    loops_.push_back(loop);
    statements(body_statements);
    loops_.pop_back();
    bind(loop.next);
    const std::uint32_t mark = frame_top_;
    branch(condition, repeat_when, body);
    release(mark);
    bind(loop.exit);
}

} // namespace eposp::compiler::codegen
