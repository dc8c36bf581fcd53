#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/port.hpp"
#include "eposp/canopen/cob_id.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace eposp::canopen {

/// What a receiver registers: a CAN identifier with its frame format, written like a COB-ID
/// entry's identifier bits (kCobIdExtended | 29 bits, or 11 bits alone).
using ReceiveKey = std::uint32_t;
using ReceiveKeys = std::vector<ReceiveKey>;

/// The key of the frames a COB-ID entry names (its valid / RTR / generate bits do not count).
constexpr ReceiveKey receive_key(std::uint32_t cob_id) {
    return (cob_id & kCobIdExtended) | can_id(cob_id);
}
constexpr ReceiveKey receive_key(const can::Frame& frame) {
    return frame.extended ? kCobIdExtended | frame.id : frame.id;
}

/// Which service hears which frame: a table keyed by identifier, as lely-core's CAN network
/// keeps its receivers, so a received frame reaches only the services that take its identifier
/// instead of every one of them. A receiver says which keys it takes now; the table asks again
/// before the next frame after invalidate() (a COB-ID or the node-ID changed). Error frames
/// reach no receiver. A receiver is a service whose on_frame() the table calls directly, as
/// CANopenNode's receive buffers call their service's function: every SYNC passes here on every
/// node, and a std::function would add a hop to each.
class FrameRouter {
public:
    using KeySource = std::function<void(ReceiveKeys& keys)>;

    /// `receiver.on_frame(frame)` gets every frame whose key `keys` lists, once however often it
    /// lists it. The receiver must outlive the router.
    template <typename Receiver>
    void add(KeySource keys, Receiver& receiver) {
        add(std::move(keys), &receiver, [](void* target, const can::Frame& frame) {
            static_cast<Receiver*>(target)->on_frame(frame);
        });
    }
    /// The receivers' keys may have changed.
    void invalidate();
    /// Keeps `port`'s acceptance filter to the table's 11-bit identifiers, so that the port
    /// hands over only frames some receiver takes: every frame while the table waits to be
    /// made again (the next dispatch makes it), its identifiers once made.
    void filter(can::Port& port);
    /// Hands `frame` to the receivers of its key, in the order they were added.
    void dispatch(const can::Frame& frame);

private:
    using Call = void (*)(void* receiver, const can::Frame& frame);
    struct Receiver {
        KeySource keys;
        void* target;
        Call call;
    };
    void add(KeySource keys, void* target, Call call);
    void rebuild();
    void update_filter();
    std::vector<std::size_t>& list_of(ReceiveKey key); ///< made empty when new

    std::vector<Receiver> receivers_;
    /// The receivers of each key, in the order they were added.
    std::vector<std::vector<std::size_t>> lists_;
    /// An 11-bit identifier's list as 1 + its position in lists_, 0: none. Every node looks up
    /// every frame on the bus, most of them someone else's: an array read, not a hash lookup.
    std::array<std::uint16_t, std::size_t{1} << 11> standard_{};
    std::unordered_map<ReceiveKey, std::size_t> extended_; ///< 29-bit keys, positions in lists_
    bool stale_ = true;
    can::Port* filtered_ = nullptr; ///< the port whose acceptance filter follows the table
    int depth_ = 0;                 ///< dispatches in progress
};

} // namespace eposp::canopen
