#include "plc_session.hpp"

#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"

namespace eposp::device::cli {

core::Result<std::unique_ptr<PlcSession>> PlcSession::open(vm::Image image,
                                                           vm::RuntimeConfig config) {
    std::unique_ptr<PlcSession> session(new PlcSession());
    PlcSession& s = *session;
    vm::stdlib::register_standard_library(s.natives_);
    // TON, TOF, TP and the RTC see the loop's virtual time.
    vm::stdlib::register_clock(s.natives_,
                               [&s] { return s.loop_.now().time_since_epoch().count(); });
    s.runtime_ = std::make_unique<vm::PlcRuntime>(
        s.loop_, s.natives_, std::move(config), [&s](std::uint16_t code, std::string text) {
            s.errors_.push_back({s.loop_.now(), code, std::move(text)});
        });
    if (const auto error = s.runtime_->load(std::move(image))) {
        return *error;
    }
    return session;
}

} // namespace eposp::device::cli
