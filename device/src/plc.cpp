#include "eposp/device/plc.hpp"

#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"

namespace eposp::device {
namespace {

vm::NativeRegistry plc_natives(core::EventLoop& loop) {
    vm::NativeRegistry natives;
    vm::stdlib::register_standard_library(natives);
    vm::stdlib::register_clock(natives, [&loop] { return loop.now().time_since_epoch().count(); });
    return natives;
}

} // namespace

Plc::Plc(core::EventLoop& loop, vm::RuntimeConfig config)
    : loop_(loop), natives_(plc_natives(loop)),
      runtime_(loop, natives_, std::move(config), [this](std::uint16_t code, std::string text) {
          errors_.push_back({loop_.now(), code, std::move(text)});
          if (error_handler_) {
              error_handler_(errors_.back());
          }
      }) {}

} // namespace eposp::device
