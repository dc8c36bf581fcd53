#pragma once

#include "eposp/test/epos2_network.hpp"

#include <cstdint>

namespace eposp::test {

/// N EPOS2s on one virtual bus, operational and enabled in Profile Position Mode, TPDO 3
/// (statusword, position) on every SYNC; a master sends SYNC at 1 kHz and a new target by RPDO 3
/// to every drive each 500 ms (20000 qc and back: the drives are always moving). The speed
/// benchmark of docs/performance.md runs it, and a test pins its wire events bit for bit.
class MovingEpos2Network {
public:
    MovingEpos2Network(core::EventLoop& loop, std::size_t count);

    /// The master's frames of this millisecond, then the loop runs for it.
    void run_millisecond();

    can::VirtualBus& bus() { return *network_.bus; }
    const Epos2Network& network() const { return network_; }

private:
    void send_rpdo(std::uint16_t controlword, std::int32_t target);

    core::EventLoop& loop_;
    Epos2Network network_;
    std::unique_ptr<can::VirtualPort> master_;
    std::int64_t millisecond_ = 0;
};

} // namespace eposp::test
