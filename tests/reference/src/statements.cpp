// Statements of IEC 61131-3 ed. 3, 7.3.3 (table 72).

#include "eposp/compiler/sema/symbol.hpp"
#include "evaluator.hpp"

namespace eposp::reference {

namespace {

// A scan that runs this many statements is taken for an endless loop.
constexpr std::uint64_t kStepBudget = 50'000'000;

} // namespace

void Evaluator::step() {
    if (++steps_ > kStepBudget) {
        throw Unsupported("a scan of more than 50 million statements (an endless loop?)");
    }
}

Evaluator::Flow Evaluator::statements(const ast::StatementList& list) {
    for (const ast::Statement& statement : list) {
        const Flow flow = this->statement(statement);
        if (flow != Flow::Next) {
            return flow;
        }
    }
    return Flow::Next;
}

Evaluator::Flow Evaluator::statement(const ast::Statement& statement) {
    step();
    line_ = static_cast<int>(statement.range.begin.line);
    return std::visit(
        [&](const auto& node) -> Flow {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                // The value first, then the place it goes.
                skipped_ = nullptr;
                const Value value = eval(*node.value);
                if (skipped_ == node.value.get()) {
                    return Flow::Next; // a call EN skipped leaves the target as it was
                }
                if (const auto* bit = std::get_if<ast::BitAccessExpression>(&node.target->node)) {
                    // 6.5.1.2 partial access: one bit of the variable changes.
                    Value& word = place(*bit->object);
                    const std::uint64_t mask = std::uint64_t{1} << bit->bit;
                    word = store(
                        integer(*word.type, value.bits != 0 ? word.bits | mask : word.bits & ~mask),
                        *word.type);
                    return Flow::Next;
                }
                Value& target = place(*node.target);
                target = store(value, *target.type);
                return Flow::Next;
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                eval(*node.call);
                return Flow::Next;
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    if (eval(*branch.condition).bits != 0) {
                        return statements(branch.body);
                    }
                }
                return statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                const Value selector = eval(*node.selector);
                for (const ast::CaseBranch& branch : node.branches) {
                    for (const ast::CaseLabel& label : branch.labels) {
                        const Value low = eval(*label.low);
                        const bool match = label.high ? order(selector, low) >= 0 &&
                                                            order(selector, eval(*label.high)) <= 0
                                                      : order(selector, low) == 0;
                        if (match) {
                            return statements(branch.body);
                        }
                    }
                }
                return statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                return for_loop(node);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                while (eval(*node.condition).bits != 0) {
                    const Flow flow = statements(node.body);
                    if (flow == Flow::Exit) {
                        break;
                    }
                    if (flow == Flow::Return) {
                        return flow;
                    }
                    step();
                }
                return Flow::Next;
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                while (true) {
                    const Flow flow = statements(node.body);
                    if (flow == Flow::Exit) {
                        break;
                    }
                    if (flow == Flow::Return) {
                        return flow;
                    }
                    if (eval(*node.until).bits != 0) {
                        break;
                    }
                    step();
                }
                return Flow::Next;
            } else if constexpr (std::is_same_v<T, ast::ExitStatement>) {
                return Flow::Exit;
            } else if constexpr (std::is_same_v<T, ast::ContinueStatement>) {
                return Flow::Continue;
            } else if constexpr (std::is_same_v<T, ast::ReturnStatement>) {
                return Flow::Return;
            } else {
                return Flow::Next;
            }
        },
        statement.node);
}

Evaluator::Flow Evaluator::for_loop(const ast::ForStatement& node) {
    // 7.3.3.4: the bounds and step are evaluated once; the control variable takes `from`,
    // the body runs while it has not passed `to`, and it is incremented after each run.
    Value* control = variable(node.control_variable);
    const sema::Type& type = *control->type;
    const Value from = store(eval(*node.from), type);
    const Value to = store(eval(*node.to), type);
    const Value by = node.by ? store(eval(*node.by), type) : integer(type, 1);
    const bool down = signed_type(type) && by.as_signed() < 0;
    *control = from;
    while (down ? order(*control, to) >= 0 : order(*control, to) <= 0) {
        const Flow flow = statements(node.body);
        if (flow == Flow::Exit) {
            return Flow::Next;
        }
        if (flow == Flow::Return) {
            return flow;
        }
        step();
        // A step past the end of the type ends the loop as one past `to` does, the variable
        // then wrapped around (docs/st-language.md): FOR i := 250 TO 255 on a USINT ends.
        const Value next = integer(type, control->bits + by.bits);
        const bool wrapped = down ? order(next, *control) > 0 : order(next, *control) < 0;
        // A subrange control variable keeps its last value rather than step past its range
        // (docs/st-language.md); a value inside `to` but outside the range is a fault.
        const bool passed = wrapped || (down ? order(next, to) < 0 : order(next, to) > 0);
        if (type.range && !type.range->contains(next.as_signed()) && passed) {
            return Flow::Next;
        }
        *control = store(next, type);
        if (wrapped) {
            return Flow::Next;
        }
    }
    return Flow::Next;
}

} // namespace eposp::reference
