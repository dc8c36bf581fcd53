#include "frame_faults.hpp"

#include <algorithm>

namespace eposp::can {

std::uint64_t FrameFaults::add(FrameFault fault, Filter filter, std::uint64_t count) {
    const std::uint64_t id = next_id_++;
    if (count > 0) {
        entries_.push_back({id, fault, std::move(filter), count});
    }
    return id;
}

bool FrameFaults::cancel(std::uint64_t id) {
    return std::erase_if(entries_, [id](const Entry& entry) { return entry.id == id; }) > 0;
}

std::optional<FrameFault> FrameFaults::take_matching(const Frame& frame) {
    const auto entry = std::ranges::find_if(entries_, [&frame](const Entry& candidate) {
        return !candidate.filter || candidate.filter(frame);
    });
    if (entry == entries_.end()) {
        return std::nullopt;
    }
    const FrameFault fault = entry->fault;
    if (--entry->remaining == 0) {
        entries_.erase(entry);
    }
    return fault;
}

} // namespace eposp::can
