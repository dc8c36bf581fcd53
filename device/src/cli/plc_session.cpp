#include "plc_session.hpp"

#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"
#include "eposp/vm/value_format.hpp"

namespace eposp::device::cli {

PlcSession::PlcSession() {
    vm::stdlib::register_standard_library(natives_);
    // TON, TOF, TP and the RTC see the loop's virtual time.
    vm::stdlib::register_clock(natives_, [this] { return loop_.now().time_since_epoch().count(); });
}

core::Result<std::unique_ptr<PlcSession>> PlcSession::open(vm::Image image) {
    std::unique_ptr<PlcSession> session(new PlcSession());
    auto program = vm::link(std::move(image), session->natives_);
    if (!program) {
        return core::Error{program.error()};
    }
    session->program_.emplace(std::move(*program));
    session->machine_.emplace(*session->program_);
    session->scheduler_.emplace(session->loop_, *session->machine_);
    return session;
}

core::Result<std::string> PlcSession::value_of(const std::string& path) const {
    const auto location = vm::lookup_variable(image(), path);
    if (!location) {
        return core::Error{location.error()};
    }
    return vm::format_value(image(), machine_->memory(), *location);
}

} // namespace eposp::device::cli
