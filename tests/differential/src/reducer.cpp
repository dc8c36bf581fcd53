#include "eposp/differential/reducer.hpp"

#include <cstddef>
#include <vector>

namespace eposp::differential {
namespace {

/// Walks statements and expressions in source order (outer before inner, so that the first
/// changes tried remove the most) and applies a change to the `target`-th candidate.
class Edit {
public:
    enum class Kind { Drop, Unwrap, Replace };
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
            if (kind_ == Kind::Unwrap && block[i].droppable && unwrap(block, i)) {
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

    /// Replaces the statement by the statements of one of its blocks (an IF by its THEN part, a
    /// loop by its body, a CASE by one arm); each block is a candidate.
    bool unwrap(Block& block, std::size_t i) {
        std::vector<const Block*> inner;
        for (const auto& segment : block[i].segments) {
            for (const auto& candidate : segment.block) {
                inner.push_back(&candidate);
            }
        }
        for (const Block* candidate : inner) {
            if (seen_++ != target_) {
                continue;
            }
            // A CASE arm (`1:` and its statements) is a statement of its own: take what it holds.
            const Block* statements = candidate;
            while (statements->size() == 1 && statements->front().segments.size() <= 2 &&
                   !statements->front().segments.front().block.empty() &&
                   statements->front().segments.front().expr.empty()) {
                statements = &statements->front().segments.front().block.front();
            }
            Block replacement = *statements;
            block.erase(block.begin() + static_cast<std::ptrdiff_t>(i));
            block.insert(block.begin() + static_cast<std::ptrdiff_t>(i), replacement.begin(),
                         replacement.end());
            return true;
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
        changed = pass(program, Edit::Kind::Unwrap, interesting) || changed;
        changed = pass(program, Edit::Kind::Replace, interesting) || changed;
    }
    return program;
}

} // namespace eposp::differential
