// NativeArgs::call_site and callers: the source locations of a native call and of the calls
// that led to it, named as run-time errors name them (run_end.cpp). Computed only when a host
// asks, from what both engines keep anyway: the instruction and the task's call stack.

#include "eposp/vm/native.hpp"
#include "source_location.hpp"

namespace eposp::vm {
namespace {

NativeCallSite site(const Image& image, std::uint32_t pou, std::uint32_t instruction) {
    return {image.pous[pou].name, detail::line_at(image.pous[pou], instruction)};
}

/// Where the call at `instruction` is, and how many callers remain below it: a native block's
/// body has no source, so a call in it is at the block's call in its caller.
struct Located {
    NativeCallSite site;
    std::uint32_t depth = 0;
    std::optional<NativeCallSite> inlined_into; ///< the POU a copied-in body sits in
};

Located locate_call(const NativeCallContext& context) {
    const Image& image = *context.image;
    std::uint32_t instruction = context.instruction;
    std::uint32_t pou = detail::pou_at(image, instruction);
    std::uint32_t depth = context.depth;
    const std::uint32_t outer = pou;
    const std::uint32_t outer_instruction = instruction;
    const auto native = detail::locate(image, pou, instruction);
    if (!native && image.pous[pou].lines.empty() && depth > 0) {
        const Activation& caller = context.calls[--depth];
        return locate_call({context.image, context.calls, depth, caller.pc - 1});
    }
    Located located{site(image, pou, instruction), depth, std::nullopt};
    if (pou != outer) {
        located.inlined_into = site(image, outer, outer_instruction);
    }
    return located;
}

} // namespace

NativeCallSite NativeArgs::call_site() const {
    if (context_ == nullptr || context_->image == nullptr) {
        return {};
    }
    return locate_call(*context_).site;
}

std::vector<NativeCallSite> NativeArgs::callers() const {
    std::vector<NativeCallSite> sites;
    if (context_ == nullptr || context_->image == nullptr) {
        return sites;
    }
    Located located = locate_call(*context_);
    while (true) {
        if (located.inlined_into) {
            sites.push_back(std::move(*located.inlined_into));
        }
        if (located.depth == 0) {
            return sites;
        }
        const Activation& caller = context_->calls[located.depth - 1];
        located = locate_call({context_->image, context_->calls, located.depth - 1, caller.pc - 1});
        sites.push_back(located.site);
    }
}

} // namespace eposp::vm
