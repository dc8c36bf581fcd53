#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/canopen/nmt_state.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace eposp::canopen {

/// An EMCY another node sent (CiA 301 7.2.7.3.1).
struct Emergency {
    NodeId node = 0;
    std::uint16_t error_code = 0;
    std::uint8_t error_register = 0;
    std::array<std::uint8_t, 5> manufacturer_data{};
    friend bool operator==(const Emergency&, const Emergency&) = default;
};

/// The EMCY consumer: tells its listeners of every EMCY received on the pre-defined
/// identifiers 0x81..0xFF (0x80 + node-ID; CiA 301 7.3.5), eight bytes, in pre-operational and
/// operational (CiA 301 7.3.2.2). Other frames are ignored.
class EmcyConsumer {
public:
    using Listener = std::function<void(const Emergency&)>;

    void on_frame(const can::Frame& frame);
    void set_nmt_state(NmtState state) { state_ = state; }
    void on_emergency(Listener listener);

private:
    NmtState state_ = NmtState::Initialising;
    std::vector<Listener> listeners_;
};

} // namespace eposp::canopen
