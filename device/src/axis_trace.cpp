#include "eposp/device/axis_trace.hpp"

#include <fmt/format.h>

namespace eposp::device {

AxisTrace::AxisTrace(core::EventLoop& loop, can::TraceOutput output, std::vector<TracedAxis> axes,
                     core::Duration period)
    : loop_(loop), output_(std::move(output)), axes_(std::move(axes)) {
    output_.write(kHeader);
    sample();
    timer_ = core::ScopedTimer(loop_, loop_.every(period, [this] { sample(); }));
}

void AxisTrace::sample() {
    const auto ns = loop_.now().time_since_epoch().count();
    std::string rows;
    for (const TracedAxis& traced : axes_) {
        const canopen::ObjectDictionary& od = traced.drive->objects();
        fmt::format_to(std::back_inserter(rows), "{}.{:09},{},{},{},{},{},{},{},{},{},{}\n",
                       ns / 1'000'000'000, ns % 1'000'000'000, traced.axis,
                       od.get_as<std::uint16_t>(0x6041, 0), od.get_as<std::int8_t>(0x6061, 0),
                       od.get_as<std::int32_t>(0x607A, 0), od.get_as<std::int32_t>(0x6062, 0),
                       od.get_as<std::int32_t>(0x6064, 0), od.get_as<std::int32_t>(0x606B, 0),
                       od.get_as<std::int32_t>(0x606C, 0), od.get_as<std::int16_t>(0x6078, 0),
                       traced.driver != nullptr ? plcopen::name(traced.driver->state())
                                                : std::string_view{});
    }
    output_.write(rows);
}

} // namespace eposp::device
