#include "eposp/differential/reducer.hpp"

#include <cstddef>
#include <optional>

namespace eposp::differential {
namespace {

/// Walks statements and expressions in source order (outer before inner, so that the first
/// changes tried remove the most) and applies a change to the `target`-th candidate.
class Edit {
public:
    enum class Kind { Drop, Replace };
    Edit(Kind kind, std::size_t target) : kind_(kind), target_(target) {}

    /// Applies the change; false if there are not that many candidates.
    bool apply(Block& block) { return visit(block); }
    /// How many candidates the block holds.
    std::size_t count(Block& block) {
        target_ = static_cast<std::size_t>(-1);
        visit(block);
        return seen_;
    }

private:
    bool visit(Block& block) {
        for (std::size_t i = 0; i < block.size(); ++i) {
            if (kind_ == Kind::Drop && block[i].droppable && seen_++ == target_) {
                block.erase(block.begin() + static_cast<std::ptrdiff_t>(i));
                return true;
            }
            for (auto& segment : block[i].segments) {
                for (auto& expr : segment.expr) {
                    if (visit(expr)) {
                        return true;
                    }
                }
                for (auto& inner : segment.block) {
                    if (visit(inner)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    bool visit(Expr& expr) {
        if (kind_ == Kind::Replace && !expr.replacement.empty() && seen_++ == target_) {
            expr = leaf(expr.replacement);
            return true;
        }
        for (auto& operand : expr.operands) {
            if (visit(operand)) {
                return true;
            }
        }
        return false;
    }

    Kind kind_;
    std::size_t target_;
    std::size_t seen_ = 0;
};

/// One pass of one kind of change over every candidate; true if any change was kept.
bool pass(Block& program, Edit::Kind kind, const Interesting& interesting) {
    bool changed = false;
    std::size_t target = 0;
    while (target < Edit(kind, 0).count(program)) {
        Block candidate = program;
        Edit(kind, target).apply(candidate);
        if (interesting(render(candidate))) {
            program = std::move(candidate);
            changed = true; // the next candidate now has the same number
        } else {
            ++target;
        }
    }
    return changed;
}

} // namespace

Block reduce(Block program, const Interesting& interesting) {
    bool changed = true;
    while (changed) {
        changed = pass(program, Edit::Kind::Drop, interesting);
        changed = pass(program, Edit::Kind::Replace, interesting) || changed;
    }
    return program;
}

} // namespace eposp::differential
