#include "signal_wires.hpp"

#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "eposp/vm/process_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace eposp::device {
namespace {

constexpr core::Duration kSamplePeriod = std::chrono::milliseconds(1);

// A process image word is an INT in the DS-405 objects' byte order (CiA 301: little-endian).
std::int16_t read_word(std::span<const std::uint8_t> bytes, std::uint32_t word) {
    const std::uint32_t at = 2 * word;
    return static_cast<std::int16_t>(bytes[at] | (bytes[at + 1] << 8));
}

std::int16_t saturated(std::int32_t millivolts) {
    return static_cast<std::int16_t>(std::clamp<std::int32_t>(millivolts, INT16_MIN, INT16_MAX));
}

} // namespace

SignalWires::SignalWires(core::EventLoop& loop, canopen::ObjectDictionary& objects,
                         vm::ProcessImage& image, Drives drives)
    : loop_(loop), objects_(objects), image_(image), drives_(std::move(drives)) {}

void SignalWires::add(const std::vector<SignalWire>& wires) {
    for (const SignalWire& wire : wires) {
        connections_.push_back({source(wire.from), sink(wire.to)});
    }
    if (!connections_.empty() && !timer_.pending()) {
        timer_ = core::ScopedTimer(loop_, loop_.every(kSamplePeriod, [this] { sample(); }));
    }
}

std::function<std::int32_t()> SignalWires::source(const SignalEnd& end) {
    if (end.device == SignalEnd::Device::ProcessImage) {
        if (end.kind == SignalEnd::Kind::Digital) {
            return [this, end] {
                return (image_.outputs()[end.byte] >> end.bit) & 1;
            };
        }
        return [this, end] {
            return std::int32_t{read_word(image_.outputs(), end.number)};
        };
    }
    if (end.device == SignalEnd::Device::Escon2) {
        drives::escon2::Escon2Drive& drive = drives_.escon2(end.name);
        if (end.kind == SignalEnd::Kind::Digital) {
            return [&drive, output = end.number] {
                return std::int32_t{drive.digital_output(output)};
            };
        }
        return [&drive, output = end.number] {
            return static_cast<std::int32_t>(std::lround(drive.analog_output(output) * 1000.0));
        };
    }
    drives::epos2::Epos2Drive& drive = drives_.epos2(end.port, end.node);
    return [&drive, output = end.number] {
        return std::int32_t{drive.digital_output(output)};
    };
}

std::function<void(std::int32_t)> SignalWires::sink(const SignalEnd& end) {
    if (end.device == SignalEnd::Device::ProcessImage) {
        if (end.kind == SignalEnd::Kind::Digital) {
            return [this, end](std::int32_t level) {
                const std::uint8_t byte = image_.inputs()[end.byte];
                const auto mask = static_cast<std::uint8_t>(1U << end.bit);
                const std::array bytes{
                    static_cast<std::uint8_t>(level != 0 ? byte | mask : byte & ~mask)};
                write_inputs(end.byte, bytes);
            };
        }
        return [this, end](std::int32_t millivolts) {
            const auto raw = static_cast<std::uint16_t>(saturated(millivolts));
            const std::array bytes{static_cast<std::uint8_t>(raw & 0xFF),
                                   static_cast<std::uint8_t>(raw >> 8)};
            write_inputs(2 * end.number, bytes);
        };
    }
    if (end.device == SignalEnd::Device::Escon2) {
        drives::escon2::Escon2Drive& drive = drives_.escon2(end.name);
        if (end.kind == SignalEnd::Kind::Digital) {
            return [&drive, input = end.number](std::int32_t level) {
                drive.set_digital_input(input, level != 0);
            };
        }
        return [&drive, input = end.number](std::int32_t millivolts) {
            drive.set_analog_input(input, static_cast<double>(millivolts) / 1000.0);
        };
    }
    drives::epos2::Epos2Drive& drive = drives_.epos2(end.port, end.node);
    if (end.kind == SignalEnd::Kind::Digital) {
        return [&drive, input = end.number](std::int32_t level) {
            drive.set_digital_input(input, level != 0);
        };
    }
    return [&drive,
            input = static_cast<drives::epos2::AnalogInput>(end.number)](std::int32_t millivolts) {
        drive.set_analog_input(input, saturated(millivolts));
    };
}

void SignalWires::write_inputs(std::uint32_t first, std::span<const std::uint8_t> bytes) {
    std::map<std::pair<std::uint16_t, std::uint8_t>, canopen::Bytes> changed;
    for (std::uint32_t i = 0; i < bytes.size(); ++i) {
        const std::uint32_t at = first + i;
        const auto entry = vm::object_entry_of(vm::IoArea::Input, at);
        const auto place = image_.entry(entry->index, entry->sub_index);
        const auto start = static_cast<std::uint32_t>(place->data() - image_.inputs().data());
        if (image_.inputs()[at] == bytes[i]) {
            continue;
        }
        auto [value, fresh] = changed.try_emplace({entry->index, entry->sub_index});
        if (fresh) {
            value->second.assign(place->begin(), place->end());
        }
        value->second[at - start] = bytes[i];
    }
    for (const auto& [entry, value] : changed) {
        objects_.set(entry.first, entry.second, value);
    }
}

void SignalWires::sample() {
    for (const Connection& connection : connections_) {
        connection.sink(connection.source());
    }
}

} // namespace eposp::device
