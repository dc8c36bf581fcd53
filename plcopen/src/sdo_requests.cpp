#include "eposp/plcopen/sdo_requests.hpp"

namespace eposp::plcopen {

namespace {

/// More requests than blocks could ever have in flight at once.
constexpr std::size_t kRemembered = 1024;

} // namespace

SdoRequests::SdoRequests(AxisLink& link) : link_(link), alive_(std::make_shared<bool>(true)) {}

std::uint32_t SdoRequests::start(const std::function<void(SdoDone done)>& begin) {
    std::uint32_t request = next_++;
    if (request == 0) {
        request = next_++;
    }
    replies_[request] = std::nullopt;
    order_.push_back(request);
    if (order_.size() > kRemembered) {
        replies_.erase(order_.front());
        order_.pop_front();
    }
    std::weak_ptr<bool> alive = alive_;
    begin([this, alive, request](const SdoReply& reply) {
        if (!alive.expired()) {
            if (const auto it = replies_.find(request); it != replies_.end()) {
                it->second = reply;
            }
        }
    });
    return request;
}

bool SdoRequests::pending(std::uint32_t request) const {
    const auto it = replies_.find(request);
    return it != replies_.end() && !it->second;
}

std::optional<SdoReply> SdoRequests::take(std::uint32_t request) {
    const auto it = replies_.find(request);
    if (it == replies_.end() || !it->second) {
        return std::nullopt;
    }
    const SdoReply reply = *it->second;
    replies_.erase(it);
    std::erase(order_, request);
    return reply;
}

} // namespace eposp::plcopen
