#include "eposp/can/candump_replay.hpp"

namespace eposp::can {

CandumpReplay::CandumpReplay(core::EventLoop& loop, Port& port, std::vector<CandumpRecord> records,
                             ReplayOptions options)
    : loop_(loop), port_(port), records_(std::move(records)), options_(std::move(options)),
      start_(options_.start.value_or(loop.now())) {
    schedule_next();
}

bool CandumpReplay::plays(const CandumpRecord& record) const {
    return !record.frame.error &&
           (options_.interface_name.empty() || record.interface_name == options_.interface_name);
}

// One timer at a time, so a long log costs one pending event, not one per frame.
void CandumpReplay::schedule_next() {
    while (next_ < records_.size() && !plays(records_[next_])) {
        ++report_.skipped;
        ++next_;
    }
    if (next_ == records_.size()) {
        // Posted, so that on_finished never runs inside the constructor.
        timer_ = core::ScopedTimer(loop_, loop_.post([this] { finish(); }));
        return;
    }
    const TraceTime time = records_[next_].time;
    if (!first_time_) {
        first_time_ = time;
    }
    timer_ =
        core::ScopedTimer(loop_, loop_.at(start_ + (time - *first_time_), [this] { send_next(); }));
}

void CandumpReplay::send_next() {
    if (port_.send(records_[next_].frame) == SendStatus::Queued) {
        ++report_.sent;
    } else {
        ++report_.refused;
    }
    ++next_;
    schedule_next();
}

void CandumpReplay::finish() {
    finished_ = true;
    if (options_.on_finished) {
        options_.on_finished(report_);
    }
}

} // namespace eposp::can
