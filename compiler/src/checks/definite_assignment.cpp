// Definite assignment over the structured statements of IEC 61131-3 ed. 3, 7.3.3: a forward
// data-flow analysis whose state is the set of variables every path so far has assigned. Where
// paths join (after IF, CASE, a loop) the sets intersect; a path that left (RETURN, EXIT,
// CONTINUE) joins nothing until its target.

#include "definite_assignment.hpp"

#include "eposp/compiler/sema/symbol.hpp"
#include "written_variables.hpp"

#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <variant>

namespace eposp::compiler::checks {
namespace {

/// The variables definitely assigned at a point; an unreachable point assigns everything, the
/// identity of the intersection where paths join.
struct State {
    std::vector<bool> assigned;
    bool reachable = true;

    static State unreachable(std::size_t size) { return {std::vector<bool>(size, true), false}; }

    void join(const State& other) {
        if (!other.reachable) {
            return;
        }
        if (!reachable) {
            *this = other;
            return;
        }
        for (std::size_t i = 0; i < assigned.size(); ++i) {
            assigned[i] = assigned[i] && other.assigned[i];
        }
    }
};

bool named(const ast::Argument& argument, std::string_view name) {
    return argument.name && sema::fold_case(argument.name->name) == name;
}

bool is_bool_literal(const ast::Expression& expression, bool value) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    const auto* boolean = literal ? std::get_if<ast::BoolLiteral>(&literal->value) : nullptr;
    return boolean != nullptr && boolean->value == value;
}

class DefiniteAssignment {
public:
    DefiniteAssignment(const std::vector<std::string>& variables, const AssignmentFacts& facts)
        : facts_(facts), partial_(variables.size(), false), initial_read_(variables.size(), false),
          returns_(variables.size()) {
        for (std::size_t i = 0; i < variables.size(); ++i) {
            index_.emplace(variables[i], i);
        }
    }

    State start() const { return {std::vector<bool>(partial_.size(), false), true}; }

    State statements(const ast::StatementList& list, State state) {
        for (const ast::Statement& statement : list) {
            state = std::visit(
                [&](const auto& node) { return this->statement(node, statement, state); },
                statement.node);
        }
        return state;
    }

    std::vector<UnassignedPaths> result(const std::vector<std::string>& variables,
                                        const State& end) const {
        std::vector<UnassignedPaths> unassigned;
        for (std::size_t i = 0; i < variables.size(); ++i) {
            const bool at_end = end.reachable && !end.assigned[i];
            if (!partial_[i] && !initial_read_[i] && (at_end || !returns_[i].empty())) {
                unassigned.push_back({variables[i], returns_[i], at_end});
            }
        }
        return unassigned;
    }

private:
    struct Loop {
        State exits;     // joined at EXIT
        State continues; // joined at CONTINUE
    };

    State statement(const ast::AssignmentStatement& node, const ast::Statement&, State state) {
        expression(*node.value, state);
        target_parts(*node.target, state);
        // `x := F(EN := c)` leaves x as it was when c is FALSE (6.6.1.2.2).
        const auto* call = std::get_if<ast::CallExpression>(&node.value->node);
        written(*node.target, state, call == nullptr || !enabled_by_en(*call));
        return state;
    }
    State statement(const ast::CallStatement& node, const ast::Statement&, State state) {
        expression(*node.call, state);
        return state;
    }
    State statement(const ast::IfStatement& node, const ast::Statement&, State state) {
        State joined = unreachable();
        for (const ast::ConditionalBlock& branch : node.branches) {
            expression(*branch.condition, state); // ELSIF conditions run when those above fail
            joined.join(statements(branch.body, state));
        }
        joined.join(statements(node.else_body, state));
        return joined;
    }
    State statement(const ast::CaseStatement& node, const ast::Statement&, State state) {
        expression(*node.selector, state);
        State joined = unreachable();
        for (const ast::CaseBranch& branch : node.branches) {
            joined.join(statements(branch.body, state));
        }
        // With labels for every value the ELSE part (or skipping all branches) cannot happen.
        const bool exhaustive = facts_.exhaustive && facts_.exhaustive(node);
        const State otherwise = statements(node.else_body, exhaustive ? unreachable() : state);
        joined.join(otherwise);
        return joined;
    }
    State statement(const ast::ForStatement& node, const ast::Statement&, State state) {
        expression(*node.from, state);
        expression(*node.to, state);
        if (node.by) {
            expression(*node.by, state);
        }
        // 7.3.3.4.2: the control variable takes its initial value even if the body never runs.
        assign(sema::fold_case(node.control_variable.name), state);
        loop_body(node.body, state);
        return state; // the body may run zero times; EXIT leaves with at least this assigned
    }
    State statement(const ast::WhileStatement& node, const ast::Statement&, State state) {
        expression(*node.condition, state);
        const Loop loop = loop_body(node.body, state);
        return is_bool_literal(*node.condition, true) ? loop.exits : state;
    }
    State statement(const ast::RepeatStatement& node, const ast::Statement&, State state) {
        // The body runs at least once; UNTIL is reached at its end or by CONTINUE.
        loops_.push_back({unreachable(), unreachable()});
        State until = statements(node.body, state);
        until.join(loops_.back().continues);
        State after = loops_.back().exits;
        loops_.pop_back();
        expression(*node.until, until);
        if (!is_bool_literal(*node.until, false)) {
            after.join(until);
        }
        return after;
    }
    State statement(const ast::ExitStatement&, const ast::Statement&, const State& state) {
        if (!loops_.empty()) {
            loops_.back().exits.join(state);
        }
        return unreachable();
    }
    State statement(const ast::ContinueStatement&, const ast::Statement&, const State& state) {
        if (!loops_.empty()) {
            loops_.back().continues.join(state);
        }
        return unreachable();
    }
    State statement(const ast::ReturnStatement&, const ast::Statement& statement,
                    const State& state) {
        if (state.reachable) {
            for (std::size_t i = 0; i < returns_.size(); ++i) {
                if (!state.assigned[i]) {
                    returns_[i].push_back(statement.range);
                }
            }
        }
        return unreachable();
    }
    State statement(const ast::EmptyStatement&, const ast::Statement&, const State& state) {
        return state;
    }

    /// The body of a FOR or WHILE loop, entered with `state`; later iterations start with at
    /// least as much assigned, so one pass finds every RETURN left unassigned.
    Loop loop_body(const ast::StatementList& body, const State& state) {
        loops_.push_back({unreachable(), unreachable()});
        statements(body, state);
        Loop loop = std::move(loops_.back());
        loops_.pop_back();
        return loop;
    }

    // Calls can stand anywhere in an expression; IEC 61131-3 evaluates both operands of AND and
    // OR here, so every write in an expression happens when it is evaluated.
    void expression(const ast::Expression& node, State& state) {
        std::visit(
            [&](const auto& part) {
                using T = std::decay_t<decltype(part)>;
                if constexpr (std::is_same_v<T, ast::NameExpression>) {
                    read(part.name, state);
                } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                    call(part, state);
                } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                    escapes(*part.target);
                    target_parts(*part.target, state);
                } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                    expression(*part.operand, state);
                } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                    expression(*part.left, state);
                    expression(*part.right, state);
                } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                    expression(*part.array, state);
                    for (const auto& index : part.indices) {
                        expression(*index, state);
                    }
                } else if constexpr (std::is_same_v<T, ast::MemberExpression> ||
                                     std::is_same_v<T, ast::BitAccessExpression>) {
                    expression(*part.object, state);
                } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                    expression(*part.reference, state);
                }
            },
            node.node);
    }

    void call(const ast::CallExpression& node, State& state) {
        target_parts(*node.callee, state);
        escapes(*node.callee); // an instance called: its variables change
        const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node);
        const bool address = callee != nullptr && sema::fold_case(callee->name.name) == "ADR";
        // EN FALSE skips the call and its outputs; ENO is written either way (6.6.1.2.2).
        const bool enabled = !enabled_by_en(node);
        std::vector<std::pair<const ast::Expression*, bool>> writes; // after the call
        for (std::size_t i = 0; i < node.arguments.size(); ++i) {
            const ast::Argument& argument = node.arguments[i];
            const ast::Expression& value = *argument.value;
            if (argument.kind == ast::Argument::Kind::Output) {
                target_parts(value, state);
                writes.emplace_back(&value, enabled || named(argument, "ENO"));
            } else if (address) {
                target_parts(value, state);
                escapes(value);
            } else if (!named(argument, "EN") && facts_.may_write && facts_.may_write(node, i)) {
                target_parts(value, state);
                writes.emplace_back(&value, enabled);
            } else {
                expression(value, state);
            }
        }
        for (const auto& [target, definite] : writes) {
            written(*target, state, definite);
        }
    }

    /// What a write to `target` evaluates first: indices, and the reference of `p^`; the
    /// variable written is not read.
    void target_parts(const ast::Expression& target, State& state) {
        if (const auto* member = std::get_if<ast::MemberExpression>(&target.node)) {
            target_parts(*member->object, state);
        } else if (const auto* element = std::get_if<ast::IndexExpression>(&target.node)) {
            target_parts(*element->array, state);
            for (const auto& index : element->indices) {
                expression(*index, state);
            }
        } else if (const auto* bit = std::get_if<ast::BitAccessExpression>(&target.node)) {
            target_parts(*bit->object, state);
        } else if (!std::holds_alternative<ast::NameExpression>(target.node)) {
            expression(target, state);
        }
    }

    /// A read of a variable that a path may not have assigned yet: the body counts on its
    /// initial value (`Sum := Sum + a[i];` in a loop).
    void read(const ast::Identifier& name, const State& state) {
        if (const auto found = index_.find(sema::fold_case(name.name));
            found != index_.end() && state.reachable && !state.assigned[found->second]) {
            initial_read_[found->second] = true;
        }
    }

    static bool enabled_by_en(const ast::CallExpression& node) {
        for (const ast::Argument& argument : node.arguments) {
            if (argument.kind != ast::Argument::Kind::Output && named(argument, "EN")) {
                return true;
            }
        }
        return false;
    }

    /// `target` is written: the whole of a tracked variable (definitely when `definite`), or a
    /// part of one.
    void written(const ast::Expression& target, State& state, bool definite) {
        if (const auto* name = std::get_if<ast::NameExpression>(&target.node)) {
            if (definite) {
                assign(sema::fold_case(name->name.name), state);
            }
            return;
        }
        escapes(target);
    }

    /// A part of the variable under `target` is written, or its address or instance handed on.
    void escapes(const ast::Expression& target) {
        if (const auto* name = root_variable(target)) {
            if (const auto found = index_.find(sema::fold_case(name->name.name));
                found != index_.end()) {
                partial_[found->second] = true;
            }
        }
    }

    void assign(const std::string& name, State& state) const {
        if (const auto found = index_.find(name); found != index_.end()) {
            state.assigned[found->second] = true;
        }
    }

    State unreachable() const { return State::unreachable(partial_.size()); }

    const AssignmentFacts& facts_;
    std::unordered_map<std::string, std::size_t> index_;
    std::vector<bool> partial_;      // written in part, or its address or instance handed on
    std::vector<bool> initial_read_; // read where a path may not have assigned it
    std::vector<std::vector<SourceRange>> returns_;
    std::vector<Loop> loops_;
};

} // namespace

std::vector<UnassignedPaths> unassigned_paths(const ast::StatementList& body,
                                              const std::vector<std::string>& variables,
                                              const AssignmentFacts& facts) {
    DefiniteAssignment analysis(variables, facts);
    const State end = analysis.statements(body, analysis.start());
    return analysis.result(variables, end);
}

} // namespace eposp::compiler::checks
