#pragma once

#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"

#include <memory>
#include <string>

namespace eposp::can::io {

/// A Linux SocketCAN interface (can0, vcan0, ...) as a Port: a raw CAN socket read and written
/// without blocking on the loop's io_context. Error frames are enabled and turned into error
/// state changes (error-passive, bus-off, recovery); they are not delivered as frames. Like a
/// controller, the port does not receive the frames it sent itself, while other sockets on the
/// same host do (SocketCAN's local loopback).
class SocketCanPort final : public Port {
public:
    /// Opens `interface`, or says why not ("this kernel has no AF_CAN support", "no such CAN
    /// interface vcan0", ...).
    static core::Result<std::unique_ptr<SocketCanPort>> open(core::EventLoop& loop,
                                                             std::string interface);

    ~SocketCanPort() override;
    SocketCanPort(const SocketCanPort&) = delete;
    SocketCanPort& operator=(const SocketCanPort&) = delete;

    /// Hands the frame to the kernel without blocking: TxOverflow when its transmit queue is
    /// full, Disconnected when the interface is down.
    SendStatus send(const Frame& frame) override;
    ErrorState error_state() const override { return state_; }
    std::string_view name() const override { return interface_; }

private:
    class Reader;
    SocketCanPort(core::EventLoop& loop, std::string interface, int socket);
    void receive(const Frame& frame);

    std::string interface_;
    ErrorState state_ = ErrorState::Active;
    std::shared_ptr<Reader> reader_;
};

} // namespace eposp::can::io
