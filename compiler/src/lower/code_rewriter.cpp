#include "code_rewriter.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

namespace eposp::compiler::lower {

namespace {

/// POU indices in code order, if their bodies tile the code without gaps.
std::optional<std::vector<std::uint32_t>> pous_in_code_order(const vm::Image& image) {
    std::vector<std::uint32_t> order(image.pous.size());
    std::iota(order.begin(), order.end(), 0U);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return image.pous[a].code_begin < image.pous[b].code_begin;
    });
    std::uint32_t next = 0;
    for (const std::uint32_t p : order) {
        if (image.pous[p].code_begin != next) {
            return std::nullopt;
        }
        next = image.pous[p].code_end;
    }
    return next == image.code.size() ? std::optional(order) : std::nullopt;
}

} // namespace


void CodeSink::keep(const vm::Instruction& ins) {
    old_targets_.push_back(code_.size());
    code_.push_back(ins);
}

class CodeRewrite {
public:
    static void run(vm::Image& image, const Expand& expand) {
        const auto order = pous_in_code_order(image);
        if (!order) {
            return;
        }
        const CodeBefore before{image.code, image.pous};
        CodeSink sink;
        for (const std::uint32_t p : *order) {
            const vm::Pou& old = before.pous[p];
            vm::Pou& pou = image.pous[p];
            // moved[i - old.code_begin]: where old instruction i (or what replaced it) starts.
            std::vector<std::uint32_t> moved(old.code_end - old.code_begin + 1);
            sink.old_targets_.clear();
            const std::uint32_t begin = sink.here();
            for (std::uint32_t i = old.code_begin; i < old.code_end; ++i) {
                moved[i - old.code_begin] = sink.here();
                expand(before, pou, i, sink);
            }
            moved.back() = sink.here();
            const auto to = [&](std::uint32_t target) {
                return moved[target - old.code_begin];
            };
            for (const std::size_t at : sink.old_targets_) {
                retarget(sink.code_[at], image.jump_tables, to);
            }
            for (vm::LineEntry& line : pou.lines) {
                line.instruction = moved[line.instruction - old.code_begin];
            }
            // Copies recorded by an earlier pass move with their code.
            for (std::size_t c = 0; c < old.inlined.size(); ++c) {
                pou.inlined[c].begin = moved[old.inlined[c].begin - old.code_begin];
                pou.inlined[c].end = moved[old.inlined[c].end - old.code_begin];
            }
            std::sort(pou.inlined.begin(), pou.inlined.end(),
                      [](const vm::InlinedCall& a, const vm::InlinedCall& b) {
                          return a.begin < b.begin;
                      });
            pou.code_begin = begin;
            pou.code_end = sink.here();
        }
        image.code = std::move(sink.code_);
    }
};

void rewrite_code(vm::Image& image, const Expand& expand) {
    CodeRewrite::run(image, expand);
}

} // namespace eposp::compiler::lower
