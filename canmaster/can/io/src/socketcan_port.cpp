#include "eposp/can/io/socketcan_port.hpp"

#include "eposp/can/io/socketcan_error_frame.hpp"

#include <algorithm>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

namespace eposp::can::io {
namespace {

Frame from_kernel(const can_frame& raw) {
    Frame frame;
    frame.extended = (raw.can_id & CAN_EFF_FLAG) != 0;
    frame.remote = (raw.can_id & CAN_RTR_FLAG) != 0;
    frame.error = (raw.can_id & CAN_ERR_FLAG) != 0;
    frame.id = raw.can_id & (frame.extended || frame.error ? CAN_EFF_MASK : CAN_SFF_MASK);
    frame.dlc = std::min<std::uint8_t>(raw.len, kMaxDataLength);
    std::copy_n(raw.data, kMaxDataLength, frame.data.begin());
    return frame;
}

can_frame to_kernel(const Frame& frame) {
    can_frame raw{};
    raw.can_id =
        frame.id | (frame.extended ? CAN_EFF_FLAG : 0U) | (frame.remote ? CAN_RTR_FLAG : 0U);
    raw.len = frame.dlc;
    const auto payload = frame.payload();
    std::copy(payload.begin(), payload.end(), raw.data);
    return raw;
}

std::string errno_text(int error) {
    return std::strerror(error);
}

} // namespace

/// Waits for the socket to become readable and reads every frame waiting. Shared with the
/// pending wait, so that a wait completing after the port is gone finds a detached reader
/// instead of a destroyed port.
class SocketCanPort::Reader : public std::enable_shared_from_this<Reader> {
public:
    Reader(boost::asio::io_context& io, int socket, SocketCanPort& port)
        : descriptor_(io, socket), port_(&port) {}

    void start() { wait(); }

    void detach() {
        port_ = nullptr;
        boost::system::error_code ignored; // closing a socket has nothing to report back
        descriptor_.close(ignored);
    }

    bool usable() const { return !failed_ && descriptor_.is_open(); }
    int socket() { return descriptor_.native_handle(); }

private:
    void wait() {
        descriptor_.async_wait(boost::asio::posix::descriptor_base::wait_read,
                               [self = shared_from_this()](boost::system::error_code error) {
                                   if (!error) {
                                       self->read_waiting_frames();
                                   }
                               });
    }

    void read_waiting_frames() {
        while (port_) {
            can_frame raw{};
            const ssize_t n = ::read(descriptor_.native_handle(), &raw, sizeof raw);
            if (n == static_cast<ssize_t>(sizeof raw)) {
                port_->receive(from_kernel(raw)); // may destroy the port, which detaches us
                continue;
            }
            if (n < 0 && errno == EINTR) {
                continue;
            }
            // EAGAIN: all read. ENETDOWN: the interface went down and may come up again.
            if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != ENETDOWN) {
                failed_ = true;
                return;
            }
            break;
        }
        if (port_) {
            wait();
        }
    }

    boost::asio::posix::stream_descriptor descriptor_;
    SocketCanPort* port_;
    bool failed_ = false;
};

core::Result<std::unique_ptr<SocketCanPort>> SocketCanPort::open(core::EventLoop& loop,
                                                                 std::string interface) {
    if (interface.empty() || interface.size() >= IFNAMSIZ) {
        return core::Error{fmt::format("'{}' is not a network interface name", interface)};
    }
    const int socket = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (socket < 0) {
        if (errno == EAFNOSUPPORT || errno == EPROTONOSUPPORT) {
            return core::Error{
                "this kernel has no AF_CAN support (SocketCAN needs the can and can_raw modules)"};
        }
        return core::Error{fmt::format("cannot create a CAN socket: {}", errno_text(errno))};
    }
    const auto fail = [socket](std::string message) {
        ::close(socket);
        return core::Error{std::move(message)};
    };
    const unsigned index = ::if_nametoindex(interface.c_str());
    if (index == 0) {
        return fail(fmt::format("no such CAN interface {}", interface));
    }
    const can_err_mask_t errors = CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_RESTARTED;
    if (::setsockopt(socket, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errors, sizeof errors) < 0) {
        return fail(
            fmt::format("cannot enable error frames on {}: {}", interface, errno_text(errno)));
    }
    sockaddr_can address{};
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    if (::bind(socket, reinterpret_cast<const sockaddr*>(&address), sizeof address) < 0) {
        if (errno == ENODEV) {
            return fail(fmt::format("{} is not a CAN interface", interface));
        }
        return fail(fmt::format("cannot bind to {}: {}", interface, errno_text(errno)));
    }
    return std::unique_ptr<SocketCanPort>(new SocketCanPort(loop, std::move(interface), socket));
}

SocketCanPort::SocketCanPort(core::EventLoop& loop, std::string interface, int socket)
    : interface_(std::move(interface)),
      reader_(std::make_shared<Reader>(loop.io(), socket, *this)) {
    reader_->start();
}

SocketCanPort::~SocketCanPort() {
    reader_->detach();
}

SendStatus SocketCanPort::send(const Frame& frame) {
    if (!frame.valid()) {
        return SendStatus::InvalidFrame;
    }
    if (!reader_->usable()) {
        return SendStatus::Disconnected;
    }
    if (state_ == ErrorState::BusOff) {
        return SendStatus::BusOff;
    }
    const can_frame raw = to_kernel(frame);
    ssize_t n = 0;
    do {
        n = ::write(reader_->socket(), &raw, sizeof raw);
    } while (n < 0 && errno == EINTR);
    if (n == static_cast<ssize_t>(sizeof raw)) {
        return SendStatus::Queued;
    }
    // The kernel refuses with ENOBUFS when the interface's queue is full, EAGAIN when the
    // socket's send buffer is.
    if (n < 0 && (errno == ENOBUFS || errno == EAGAIN || errno == EWOULDBLOCK)) {
        return SendStatus::TxOverflow;
    }
    return SendStatus::Disconnected;
}

void SocketCanPort::receive(const Frame& frame) {
    if (!frame.error) {
        deliver(frame);
        return;
    }
    const auto reported = error_state_reported_by(frame);
    if (reported && *reported != state_) {
        state_ = *reported;
        notify_error_state(state_);
    }
}

} // namespace eposp::can::io
