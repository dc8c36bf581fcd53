#include "eposp/canopen/sdo_client.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "sdo_client_transfer.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

namespace eposp::canopen {

namespace {

bool invalid(std::uint32_t cob_id) {
    return (cob_id & kCobIdInvalid) != 0;
}

/// Identifier and format of a COB-ID entry: what a received frame is looked up by.
std::uint32_t key_of(std::uint32_t cob_id) {
    return can_id(cob_id) | (cob_id & kCobIdExtended);
}

} // namespace

struct SdoClient::Request {
    SdoRequestId id;
    bool upload = false;
    sdo::Multiplexer mux;
    Bytes value;
    SdoRequestOptions options;
    UploadCallback on_upload;
    DownloadCallback on_download;
};

/// The client's side of the SDO connection with one server: its queue and its one transfer.
struct SdoClient::Channel {
    Channel(SdoClient& client, NodeId node)
        : request_cob_id(sdo::default_request_cob_id(node)),
          response_cob_id(sdo::default_response_cob_id(node)),
          transfer(client.loop_, client.port_, client.transmit_queue_, client.config_,
                   [&client, this](AbortCode code) { client.complete(*this, code); }) {}

    std::uint32_t request_cob_id;
    std::uint32_t response_cob_id;
    std::deque<Request> queue;
    std::optional<Request> current; ///< set while its transfer runs
    SdoClientTransfer transfer;
    core::ScopedTimer start;
};

SdoClient::SdoClient(core::EventLoop& loop, can::Port& port, SdoClientConfig config)
    : loop_(loop), port_(port), config_(config), transmit_queue_(loop, port, config.retry_delay) {}

SdoClient::~SdoClient() = default;

SdoClient::Channel& SdoClient::channel(NodeId node) {
    if (node == 0 || node >= channels_.size()) {
        throw std::invalid_argument("SdoClient: a server's node-ID is 1..127");
    }
    auto& slot = channels_[node];
    if (!slot) {
        slot = std::make_unique<Channel>(*this, node);
        by_response_cob_id_[key_of(slot->response_cob_id)] = node;
    }
    return *slot;
}

const SdoClient::Channel* SdoClient::find_channel(NodeId node) const {
    return node < channels_.size() ? channels_[node].get() : nullptr;
}

void SdoClient::on_frame(const can::Frame& frame) {
    const std::uint32_t key = frame.id | (frame.extended ? kCobIdExtended : 0);
    const auto it = by_response_cob_id_.find(key);
    if (it == by_response_cob_id_.end()) {
        return;
    }
    Channel& channel = *channels_[it->second];
    if (channel.transfer.busy() && sdo::is_message_on(frame, channel.response_cob_id)) {
        channel.transfer.on_message(sdo::bytes_of(frame));
    }
}

SdoRequestId SdoClient::upload(NodeId node, std::uint16_t index, std::uint8_t sub_index,
                               UploadCallback done, SdoRequestOptions options) {
    Request request;
    request.upload = true;
    request.mux = {index, sub_index};
    request.options = options;
    request.on_upload = std::move(done);
    return enqueue(node, std::move(request));
}

SdoRequestId SdoClient::download(NodeId node, std::uint16_t index, std::uint8_t sub_index,
                                 Bytes value, DownloadCallback done, SdoRequestOptions options) {
    Request request;
    request.mux = {index, sub_index};
    request.value = std::move(value);
    request.options = options;
    request.on_download = std::move(done);
    return enqueue(node, std::move(request));
}

SdoRequestId SdoClient::enqueue(NodeId node, Request request) {
    Channel& target = channel(node);
    request.id = SdoRequestId{next_id_++};
    const SdoRequestId id = request.id;
    target.queue.push_back(std::move(request));
    schedule_start(target);
    return id;
}

void SdoClient::schedule_start(Channel& target) {
    // Deferred, so that no callback runs inside upload() or download().
    if (!target.current && !target.start.pending()) {
        target.start =
            core::ScopedTimer(loop_, loop_.post([this, &target] { start_next(target); }));
    }
}

void SdoClient::start_next(Channel& target) {
    while (!target.current && !target.queue.empty()) {
        target.current = std::move(target.queue.front());
        target.queue.pop_front();
        Request& request = *target.current;
        if (invalid(target.request_cob_id) || invalid(target.response_cob_id)) {
            finish(target, AbortCode::ResourceNotAvailable);
        } else if (request.upload) {
            target.transfer.start_upload(target.request_cob_id, request.mux, request.options);
        } else {
            target.transfer.start_download(target.request_cob_id, request.mux,
                                           std::move(request.value), request.options);
        }
    }
}

void SdoClient::complete(Channel& target, AbortCode code) {
    finish(target, code);
    start_next(target);
}

void SdoClient::finish(Channel& target, AbortCode code) {
    Request request = std::move(*target.current);
    target.current.reset();
    Bytes value = target.transfer.take_value();
    notify(request, code, code == AbortCode::None ? std::move(value) : Bytes{});
}

void SdoClient::notify(Request& request, AbortCode code, Bytes value) {
    if (request.upload && request.on_upload) {
        request.on_upload(code, std::move(value));
    } else if (!request.upload && request.on_download) {
        request.on_download(code);
    }
}

bool SdoClient::cancel(SdoRequestId id, AbortCode reason) {
    for (const auto& slot : channels_) {
        if (!slot) {
            continue;
        }
        if (slot->current && slot->current->id == id) {
            slot->transfer.abort(reason); // ends through complete()
            return true;
        }
        const auto it = std::ranges::find(slot->queue, id, &Request::id);
        if (it != slot->queue.end()) {
            Request request = std::move(*it);
            slot->queue.erase(it);
            notify(request, reason, {});
            return true;
        }
    }
    return false;
}

std::size_t SdoClient::cancel_all(NodeId node, AbortCode reason) {
    Channel* target = node < channels_.size() ? channels_[node].get() : nullptr;
    if (!target) {
        return 0;
    }
    std::deque<Request> queued = std::move(target->queue);
    target->queue.clear();
    std::size_t count = queued.size();
    if (target->current) {
        ++count;
        target->transfer.abort(reason);
    }
    for (Request& request : queued) {
        notify(request, reason, {});
    }
    return count;
}

void SdoClient::set_cob_ids(NodeId node, std::uint32_t request, std::uint32_t response) {
    Channel& target = channel(node);
    if (const auto it = by_response_cob_id_.find(key_of(target.response_cob_id));
        it != by_response_cob_id_.end() && it->second == node) {
        by_response_cob_id_.erase(it);
    }
    target.request_cob_id = request;
    target.response_cob_id = response;
    if (!invalid(response)) {
        by_response_cob_id_[key_of(response)] = node;
    }
    // A connection changes its COB-IDs only while not in use (CiA 301 7.5.2.34): a running
    // transfer ends as on a connection that became unavailable (its abort still goes out on
    // the old COB-ID), and the next request uses the new ones.
    if (target.transfer.busy()) {
        target.transfer.abort(AbortCode::ResourceNotAvailable);
    }
}

std::size_t SdoClient::pending(NodeId node) const {
    const Channel* target = find_channel(node);
    return target ? target->queue.size() + (target->current ? 1 : 0) : 0;
}

bool SdoClient::busy(NodeId node) const {
    const Channel* target = find_channel(node);
    return target && target->transfer.busy();
}

} // namespace eposp::canopen
