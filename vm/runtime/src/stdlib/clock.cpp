#include "eposp/vm/stdlib/clock.hpp"

#include <string>
#include <utility>

namespace eposp::vm::stdlib {

void register_clock(NativeRegistry& registry, std::function<std::int64_t()> now_ns) {
    registry.add(std::string(kClockNative), {true, Scalar::I64, {}},
                 [now = std::move(now_ns)](NativeArgs& args) { args.set_result(now()); });
}

} // namespace eposp::vm::stdlib
