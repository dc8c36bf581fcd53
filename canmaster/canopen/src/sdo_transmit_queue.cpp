#include "eposp/canopen/sdo_transmit_queue.hpp"

namespace eposp::canopen {

SdoTransmitQueue::SdoTransmitQueue(core::EventLoop& loop, can::Port& port,
                                   core::Duration retry_delay)
    : loop_(loop), port_(port), retry_delay_(retry_delay) {}

void SdoTransmitQueue::send(const can::Frame& frame) {
    if (backlog_.empty() && port_.send(frame) != can::SendStatus::TxOverflow) {
        return;
    }
    backlog_.push_back(frame);
    if (!retry_.pending()) {
        retry_ = core::ScopedTimer(loop_, loop_.after(retry_delay_, [this] { drain(); }));
    }
}

void SdoTransmitQueue::drain() {
    while (!backlog_.empty()) {
        if (port_.send(backlog_.front()) == can::SendStatus::TxOverflow) {
            retry_ = core::ScopedTimer(loop_, loop_.after(retry_delay_, [this] { drain(); }));
            return;
        }
        backlog_.pop_front();
    }
}

} // namespace eposp::canopen
