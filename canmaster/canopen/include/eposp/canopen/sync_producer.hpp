#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace eposp::canopen {

/// The SYNC producer (CiA 301 7.2.5; EPOS P FW spec 10.5/10.6/10.14), on the objects of
/// add_sync_objects().
///
/// While 0x1005 has the generate bit and 0x1006 is non-zero, it sends a SYNC every 0x1006 µs
/// in pre-operational and operational. With a counter overflow value (0x1019) of 2..240 the
/// frame carries one byte, the counter, which starts at 1 and after the overflow value starts
/// again at 1; with 0 the frame is empty. A change of these objects restarts the cycle from the
/// write (first SYNC one period later, counter 1), as does leaving stopped or a reset.
class SyncProducer {
public:
    /// A SYNC this node sent: a node does not receive its own frames, so the node hands it to
    /// its own SYNC consumer through this.
    using SentListener = std::function<void(const can::Frame&)>;

    SyncProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od);
    ~SyncProducer();
    SyncProducer(const SyncProducer&) = delete;
    SyncProducer& operator=(const SyncProducer&) = delete;

    void set_nmt_state(NmtState state);
    bool producing() const { return timer_.pending(); }
    void on_sent(SentListener listener);

private:
    struct Config {
        std::uint32_t cob_id = 0;
        std::uint32_t period_us = 0;
        std::uint8_t overflow = 0;
        bool enabled = false; ///< generate bit, non-zero period and an NMT state that sends
        friend bool operator==(const Config&, const Config&) = default;
    };

    Config read_config() const;
    void update();
    void send();

    core::EventLoop& loop_;
    can::Port& port_;
    ObjectDictionary& od_;
    NmtState state_ = NmtState::Initialising;
    Config config_;
    std::uint8_t counter_ = 1;
    core::ScopedTimer timer_;
    std::vector<SentListener> listeners_;
    std::vector<ObjectDictionary::ListenerId> od_listeners_;
};

} // namespace eposp::canopen
