#pragma once

#include "eposp/plcopen/axis_link.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace eposp::plcopen {

/// SDO transfers that blocks start in one call and collect in a later one: the reply is kept
/// by request number until the block takes it, so a block keeps only that number in its
/// instance. Replies nobody collects (a block no longer called) are forgotten after a while.
class SdoRequests {
public:
    explicit SdoRequests(AxisLink& link);

    /// Starts a transfer of an axis' drive or of any node; its number is never 0.
    template <typename Target>
    std::uint32_t read(Target target, std::uint16_t index, std::uint8_t sub_index) {
        return start([=, this](SdoDone done) { link_.read(target, index, sub_index, done); });
    }
    template <typename Target>
    std::uint32_t write(Target target, std::uint16_t index, std::uint8_t sub_index,
                        std::uint32_t value, std::uint8_t size) {
        return start(
            [=, this](SdoDone done) { link_.write(target, index, sub_index, value, size, done); });
    }
    /// The reply of `request` once it has come (and forgets it); nullopt while it has not.
    std::optional<SdoReply> take(std::uint32_t request);
    /// The transfer has not replied yet (false once taken, or forgotten).
    bool pending(std::uint32_t request) const;

private:
    /// Numbers the transfer `begin` starts and keeps its reply.
    std::uint32_t start(const std::function<void(SdoDone done)>& begin);

    AxisLink& link_;
    std::uint32_t next_ = 1;
    std::map<std::uint32_t, std::optional<SdoReply>> replies_;
    std::deque<std::uint32_t> order_; ///< to forget the oldest first
    std::shared_ptr<bool> alive_;
};

} // namespace eposp::plcopen
