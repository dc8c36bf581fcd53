#include "eposp/vm/stdlib/clock.hpp"

#include "library_parts.hpp"

#include <utility>

namespace eposp::vm::stdlib {

void register_clock(NativeRegistry& registry, std::function<std::int64_t()> now_ns) {
    add_standard(registry, clock_binding(),
                 [now = std::move(now_ns)](NativeArgs& args) { args.set_result(now()); });
}

} // namespace eposp::vm::stdlib
