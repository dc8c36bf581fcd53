#include "eposp/plcopen/sdo_requests.hpp"

namespace eposp::plcopen {

namespace {

/// More requests than blocks could ever have in flight at once.
constexpr std::size_t kRemembered = 1024;

} // namespace

SdoRequests::SdoRequests(AxisLink& link) : link_(link), alive_(std::make_shared<bool>(true)) {}

std::uint32_t SdoRequests::track() {
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
    return request;
}

std::uint32_t SdoRequests::read(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index) {
    const std::uint32_t request = track();
    std::weak_ptr<bool> alive = alive_;
    link_.read(axis, index, sub_index, [this, alive, request](const SdoReply& reply) {
        if (!alive.expired()) {
            if (const auto it = replies_.find(request); it != replies_.end()) {
                it->second = reply;
            }
        }
    });
    return request;
}

std::uint32_t SdoRequests::write(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
                                 std::uint32_t value, std::uint8_t size) {
    const std::uint32_t request = track();
    std::weak_ptr<bool> alive = alive_;
    link_.write(axis, index, sub_index, value, size, [this, alive, request](const SdoReply& reply) {
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
