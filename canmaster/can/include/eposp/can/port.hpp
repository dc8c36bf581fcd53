#pragma once

#include "eposp/can/frame.hpp"

#include <bitset>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace eposp::can {

/// The fault confinement state of a CAN controller (ISO 11898-1, 12.1.4), with the error
/// warning level controllers report besides (SocketCAN's CAN_STATE_ERROR_WARNING).
enum class ErrorState {
    Active,  ///< counters below 96: takes part normally, signals active error flags
    Warning, ///< a counter at 96..127: still error-active, but errors pile up
    Passive, ///< a counter above 127: still sends, waits 8 extra bits after transmitting
    BusOff,  ///< transmit counter above 255: takes no part in bus traffic until recovered
};
/// Active or Warning: the controller signals active error flags.
inline bool error_active(ErrorState state) {
    return state == ErrorState::Active || state == ErrorState::Warning;
}
std::string_view to_string(ErrorState state);

/// What became of a frame handed to Port::send().
enum class SendStatus {
    Queued,       ///< accepted for transmission
    TxOverflow,   ///< the transmit queue is full; the frame is lost
    BusOff,       ///< the controller is bus-off and sends nothing
    InvalidFrame, ///< identifier out of range, DLC above 8, or an error frame
    Disconnected, ///< the port is no longer attached to a bus
};
std::string_view to_string(SendStatus status);

/// A CAN controller as the software on a node sees it: it sends frames and is told of the
/// frames it receives and of changes of its error state. The virtual bus, SocketCAN and the
/// socketcand bridge all provide ports, so a node runs unchanged on each of them.
class Port {
public:
    using FrameHandler = std::function<void(const Frame&)>;
    using ErrorStateHandler = std::function<void(ErrorState)>;

    virtual ~Port() = default;

    virtual SendStatus send(const Frame& frame) = 0;
    /// A transmit abort: takes back the frames still waiting in the transmit queue for which
    /// `which` is true (e.g. CANopen synchronous PDOs once their window closed, CiA 301
    /// 7.5.2.8); a frame already on the wire goes on. Returns how many; a port that cannot abort
    /// (the queue is the kernel's or a server's) takes none back.
    virtual std::size_t withdraw(const std::function<bool(const Frame&)>& which);
    virtual ErrorState error_state() const = 0;
    virtual std::string_view name() const = 0;

    /// Called for every frame received, in bus order. A controller does not receive its own
    /// frames. A new handler takes every frame until it sets an acceptance filter.
    void on_receive(FrameHandler handler) {
        receive_handler_ = std::move(handler);
        accept_all();
    }

    /// One bit per 11-bit identifier.
    using StandardIds = std::bitset<std::size_t{1} << 11>;
    /// An acceptance filter, as a CAN controller has one: of the frames in 11-bit format only
    /// those whose identifier is in `ids` reach the receive handler (29-bit and error frames
    /// all do). The controller still receives the others: it acknowledges them, counts them
    /// and moves its error counters exactly as before; only the handler does not see them
    /// (on a bus of n nodes, most frames concern few of them).
    void accept_only(const StandardIds& ids) {
        accepted_ = ids;
        filtering_ = true;
        filter_changed();
    }
    void accept_all() {
        filtering_ = false;
        filter_changed();
    }
    /// Whether the handler sees a frame in 11-bit format with identifier `id`.
    bool accepts(std::uint32_t id) const {
        return !filtering_ || (id < accepted_.size() && accepted_[id]);
    }
    void on_error_state(ErrorStateHandler handler) { error_state_handler_ = std::move(handler); }

protected:
    /// After every change of the acceptance filter: a bus that hands each frame only to the
    /// controllers it concerns indexes their filters.
    virtual void filter_changed() {}
    void deliver(const Frame& frame) const {
        if (!frame.extended && !frame.error && !accepts(frame.id)) {
            return;
        }
        if (receive_handler_) {
            receive_handler_(frame);
        }
    }
    void notify_error_state(ErrorState state) const {
        if (error_state_handler_) {
            error_state_handler_(state);
        }
    }

private:
    FrameHandler receive_handler_;
    bool filtering_ = false;
    StandardIds accepted_;
    ErrorStateHandler error_state_handler_;
};

} // namespace eposp::can
