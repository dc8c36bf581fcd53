#include "eposp/test/moving_epos2_network.hpp"

#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <chrono>

namespace eposp::test {

using namespace std::chrono_literals;

MovingEpos2Network::MovingEpos2Network(core::EventLoop& loop, std::size_t count)
    : loop_(loop), network_(make_epos2_network(loop, count, {})),
      master_(network_.bus->connect("master")) {
    master_->on_receive([](const can::Frame&) {});
    // The master's configuration, written the way its SDOs would leave it.
    for (auto& drive : network_.drives) {
        auto& od = drive->objects();
        const auto node = drive->node().node_id();
        od.set_as(0x1802, 2, std::uint8_t{1});
        od.set_as(0x1802, 1, std::uint32_t{0x4000'0380U + node});
        drive->node().pdo().reload();
        od.set_as(0x6081, 0, std::uint32_t{1000});
        od.set_as(0x6083, 0, std::uint32_t{10000});
        od.set_as(0x6084, 0, std::uint32_t{10000});
    }
    master_->send(can::Frame::data_frame(canopen::kNmtCanId, {0x01, 0x00}));
    for (const int word : {0x0006, 0x0007, 0x000F}) { // shutdown, switch on, enable
        send_rpdo(static_cast<std::uint16_t>(word), 0);
        loop_.run_for(5ms);
    }
}

void MovingEpos2Network::send_rpdo(std::uint16_t controlword, std::int32_t target) {
    for (auto& drive : network_.drives) {
        const auto t = canopen::encode(target);
        master_->send(can::Frame::data_frame(0x400U + drive->node().node_id(),
                                             {static_cast<std::uint8_t>(controlword),
                                              static_cast<std::uint8_t>(controlword >> 8), t[0],
                                              t[1], t[2], t[3]}));
    }
}

void MovingEpos2Network::run_millisecond() {
    if (millisecond_ % 500 == 0) {
        send_rpdo(0x003F, (millisecond_ / 500) % 2 == 0 ? 20000 : 0); // new set-point, at once
    } else if (millisecond_ % 500 == 1) {
        send_rpdo(0x000F, 0);
    }
    master_->send(can::Frame::data_frame(0x080, {}));
    loop_.run_for(1ms);
    ++millisecond_;
}

} // namespace eposp::test
