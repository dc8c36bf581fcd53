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

// verify()'s runtime: the same limits, no RETAIN store (a verification never touches it).
vm::RuntimeConfig scratch_config(const vm::RuntimeConfig& config) {
    vm::RuntimeConfig scratch;
    scratch.cost = config.cost;
    scratch.watchdog_instructions = config.watchdog_instructions;
    scratch.safe_state = config.safe_state;
    scratch.retain_capacity = config.retain_capacity;
    scratch.engine = config.engine;
    return scratch;
}

} // namespace

Plc::Plc(core::EventLoop& loop, vm::RuntimeConfig config)
    : loop_(loop), natives_(plc_natives(loop)), scratch_config_(scratch_config(config)),
      runtime_(loop, natives_, std::move(config), [this](std::uint16_t code, std::string text) {
          errors_.push_back({loop_.now(), code, std::move(text)});
          if (error_handler_) {
              error_handler_(errors_.back());
          }
      }) {}

std::optional<core::Error> Plc::load(vm::Image image) {
    if (load_observer_ != nullptr) {
        if (auto refusal = load_observer_->check(image)) {
            return refusal;
        }
    }
    if (auto refusal = runtime_.load(std::move(image))) {
        return refusal;
    }
    if (load_observer_ != nullptr) {
        load_observer_->loaded(runtime_.image());
    }
    return std::nullopt;
}

std::optional<core::Error> Plc::verify(vm::Image image) const {
    if (load_observer_ != nullptr) {
        if (auto refusal = load_observer_->check(image)) {
            return refusal;
        }
    }
    vm::PlcRuntime scratch(loop_, natives_, scratch_config_, [](std::uint16_t, std::string) {});
    return scratch.load(std::move(image));
}

} // namespace eposp::device
