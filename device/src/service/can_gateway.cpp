#include "can_gateway.hpp"

#include "../network_port.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/nmt_protocol.hpp"

#include <algorithm>

namespace eposp::device {
namespace {

using service::Answer;

constexpr std::uint16_t kHighestBaseId = 0x7FF;

Answer answer(canopen::AbortCode abort) {
    return Answer{static_cast<std::uint32_t>(abort), {}};
}
Answer answer(std::uint32_t error) {
    return Answer{error, {}};
}

// A frame handed to the port: refused ones (bus-off, a full queue) are a general error.
Answer sent(can::SendStatus status) {
    return status == can::SendStatus::Queued ? answer(service::error::kNone)
                                             : answer(canopen::AbortCode::GeneralError);
}

Answer data_answer(const can::Frame& frame) {
    Answer result{service::error::kNone, {}};
    result.data.assign(frame.data.begin(), frame.data.end()); // all 8 bytes, zeros past the DLC
    return result;
}

bool valid_nmt_command(std::uint16_t command) {
    using canopen::NmtCommand;
    for (const NmtCommand known :
         {NmtCommand::Start, NmtCommand::Stop, NmtCommand::EnterPreOperational,
          NmtCommand::ResetNode, NmtCommand::ResetCommunication}) {
        if (command == static_cast<std::uint16_t>(known)) {
            return true;
        }
    }
    return false;
}

} // namespace

struct CanGateway::Wait {
    NetworkPort* port = nullptr;
    NetworkPort::FrameObserverId observer = 0;
    core::ScopedTimer timeout;
    Done done;
};

CanGateway::CanGateway(core::EventLoop& loop, const ServiceParts& parts)
    : loop_(loop), parts_(parts) {}

CanGateway::~CanGateway() {
    end_wait();
    if (lss_port_) {
        lss_port_->stop_observing(lss_observer_);
    }
}

void CanGateway::abandon() {
    end_wait();
}

void CanGateway::end_wait() {
    if (wait_) {
        wait_->port->stop_observing(wait_->observer);
        wait_.reset();
    }
}

void CanGateway::send_nmt(const service::SendNmtService& request, Done done) {
    NetworkPort* port = resolve_port(parts_, request.network);
    if (!port || request.node > canopen::kMaxNodeId) {
        return done(answer(service::error::kWrongNodeId));
    }
    if (!valid_nmt_command(request.command)) {
        return done(answer(canopen::AbortCode::InvalidValue));
    }
    const auto status = port->nmt().send(static_cast<canopen::NmtCommand>(request.command),
                                         static_cast<canopen::NodeId>(request.node));
    done(sent(status));
}

void CanGateway::send_frame(const service::SendCanFrame& request, Done done) {
    NetworkPort* port = resolve_port(parts_, request.network);
    if (!port) {
        return done(answer(service::error::kWrongNodeId));
    }
    if (request.cob_id > kHighestBaseId || request.length > can::kMaxDataLength) {
        return done(answer(canopen::AbortCode::InvalidValue));
    }
    const std::span<const std::uint8_t> payload(request.data.data(), request.length);
    done(sent(port->send(can::Frame::data_frame(request.cob_id, payload))));
}

void CanGateway::request_frame(const service::RequestCanFrame& request, Done done) {
    NetworkPort* port = resolve_port(parts_, request.network);
    if (!port) {
        return done(answer(service::error::kWrongNodeId));
    }
    if (request.cob_id > kHighestBaseId || request.length > can::kMaxDataLength) {
        return done(answer(canopen::AbortCode::InvalidValue));
    }
    const can::SendStatus status = port->send(
        can::Frame::remote_frame(request.cob_id, static_cast<std::uint8_t>(request.length)));
    if (status != can::SendStatus::Queued) {
        return done(sent(status));
    }
    wait_for(
        *port,
        [cob_id = request.cob_id](const can::Frame& frame) {
            return !frame.remote && !frame.extended && frame.id == cob_id;
        },
        kRemoteFrameTimeout, std::move(done));
}

void CanGateway::send_lss(const service::SendLssFrame& request, Done done) {
    NetworkPort* port = resolve_port(parts_, request.network);
    if (!port) {
        return done(answer(service::error::kWrongNodeId));
    }
    keep_lss_responses(*port);
    lss_responses_.clear(); // a response now answers this request
    done(sent(port->send(can::Frame::data_frame(canopen::kLssMasterCobId, request.data))));
}

void CanGateway::keep_lss_responses(NetworkPort& port) {
    if (lss_port_ == &port) {
        return;
    }
    if (lss_port_) {
        lss_port_->stop_observing(lss_observer_);
    }
    lss_port_ = &port;
    lss_observer_ = port.observe_frames([this](const can::Frame& frame) {
        if (frame.remote || frame.extended || frame.id != canopen::kLssSlaveCobId) {
            return;
        }
        if (wait_ && wait_->port == lss_port_) {
            return; // read_lss's wait takes it
        }
        if (lss_responses_.size() == kLssResponsesKept) {
            lss_responses_.pop_front();
        }
        lss_responses_.push_back(frame);
    });
}

void CanGateway::read_lss(const service::ReadLssFrame& request, Done done) {
    NetworkPort* port = resolve_port(parts_, request.network);
    if (!port) {
        return done(answer(service::error::kWrongNodeId));
    }
    if (lss_port_ == port && !lss_responses_.empty()) {
        const can::Frame response = lss_responses_.front();
        lss_responses_.pop_front();
        return done(data_answer(response));
    }
    wait_for(
        *port,
        [](const can::Frame& frame) {
            return !frame.remote && !frame.extended && frame.id == canopen::kLssSlaveCobId;
        },
        std::chrono::milliseconds(request.timeout_ms), std::move(done));
}

void CanGateway::wait_for(NetworkPort& port, std::function<bool(const can::Frame&)> match,
                          core::Duration timeout, Done done) {
    end_wait();
    wait_ = std::make_unique<Wait>();
    wait_->port = &port;
    wait_->done = std::move(done);
    wait_->observer =
        port.observe_frames([this, match = std::move(match)](const can::Frame& frame) {
            if (wait_ && match(frame)) {
                Done finished = std::move(wait_->done);
                end_wait();
                finished(data_answer(frame));
            }
        });
    wait_->timeout = core::ScopedTimer(loop_, loop_.after(timeout, [this] {
        Done finished = std::move(wait_->done);
        end_wait();
        finished(answer(canopen::AbortCode::SdoTimeout));
    }));
}

} // namespace eposp::device
