#include "image_passes.hpp"

#include "back_edge_duplication.hpp"
#include "call_inlining.hpp"
#include "jump_threading.hpp"

namespace eposp::compiler::lower {

void optimise_image(vm::Image& image) {
    // Back-edges first, so that an inlined body is a copy of its callee as it finally runs.
    thread_jumps(image);
    duplicate_back_edges(image);
    inline_leaf_calls(image);
    thread_jumps(image);
}

} // namespace eposp::compiler::lower
