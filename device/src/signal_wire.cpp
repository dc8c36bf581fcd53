#include "eposp/device/signal_wire.hpp"

#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/process_image.hpp"
#include "text_words.hpp"

#include <cstdio>
#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr std::string_view kForms =
    "a wire's end is a process image bit or word (%QX0.3, %IX2.0, %QW16, %IW16), an EPOS2's "
    "'internal|node N digital input|digital output|analog input N' or an ESCON2's 'escon2 NAME "
    "[high-speed] digital input|digital output N' or 'escon2 NAME analog input|output N'";

// The pins of each drive: the EPOS2 24/5 (EPOS2 FW spec 8.2.56 - 8.2.63; its analog output is
// not a signal of the simulation), the ESCON2 (ESCON2 FW spec chapter 4).
struct Pins {
    std::string_view device;
    unsigned digital_inputs, high_speed_digital_inputs;
    unsigned digital_outputs, high_speed_digital_outputs;
    unsigned analog_inputs, analog_outputs;
};
constexpr Pins kEpos2Pins{"an EPOS2 24/5", 6, 0, 4, 0, 2, 0};
constexpr Pins kEscon2Pins{"an ESCON2", 4, 4, 2, 1, 2, 2};

constexpr std::uint32_t kLastWord = vm::kProcessImageSize / 2 - 1;

std::optional<SignalEnd> process_image_end(const std::string& word) {
    if (word.size() < 4 || word[0] != '%') {
        return std::nullopt;
    }
    SignalEnd end;
    const char area = static_cast<char>(std::toupper(static_cast<unsigned char>(word[1])));
    const char size = static_cast<char>(std::toupper(static_cast<unsigned char>(word[2])));
    if ((area != 'I' && area != 'Q') || (size != 'X' && size != 'W')) {
        return std::nullopt;
    }
    end.direction = area == 'I' ? SignalEnd::Direction::Input : SignalEnd::Direction::Output;
    unsigned byte = 0;
    unsigned bit = 0;
    char rest = 0;
    if (size == 'X') {
        if (std::sscanf(word.c_str() + 3, "%u.%u%c", &byte, &bit, &rest) != 2 ||
            byte >= vm::kProcessImageSize || bit > 7) {
            return std::nullopt;
        }
        end.kind = SignalEnd::Kind::Digital;
        end.byte = byte;
        end.bit = static_cast<std::uint8_t>(bit);
        return end;
    }
    const auto index = number(word.substr(3));
    if (!index || *index > kLastWord) {
        return std::nullopt;
    }
    end.kind = SignalEnd::Kind::Analog;
    end.number = *index;
    return end;
}

// "[high-speed] digital|analog input|output N" of a drive with `pins`.
std::optional<std::string> read_pin(std::vector<std::string> words, const Pins& pins,
                                    SignalEnd& end) {
    const bool high_speed = !words.empty() && lower(words.front()) == "high-speed";
    if (high_speed) {
        words.erase(words.begin());
    }
    if (words.size() != 3) {
        return std::string(kForms);
    }
    const std::string kind = lower(words[0]);
    const std::string direction = lower(words[1]);
    const auto index = number(words[2]);
    if ((kind != "digital" && kind != "analog") ||
        (direction != "input" && direction != "output") || !index ||
        (high_speed && kind != "digital")) {
        return std::string(kForms);
    }
    end.kind = kind == "digital" ? SignalEnd::Kind::Digital : SignalEnd::Kind::Analog;
    end.direction =
        direction == "input" ? SignalEnd::Direction::Input : SignalEnd::Direction::Output;
    const bool input = end.direction == SignalEnd::Direction::Input;
    const unsigned regular = end.kind == SignalEnd::Kind::Analog
                                 ? (input ? pins.analog_inputs : pins.analog_outputs)
                                 : (input ? pins.digital_inputs : pins.digital_outputs);
    const unsigned last =
        !high_speed ? regular
                    : (input ? pins.high_speed_digital_inputs : pins.high_speed_digital_outputs);
    const std::string pin = (high_speed ? "high-speed " : "") + kind + " " + direction;
    if (last == 0) {
        return fmt::format("{} has no {}", pins.device, pin);
    }
    if (*index < 1 || *index > last) {
        return last == 1 ? fmt::format("{} has one {}, number 1", pins.device, pin)
                         : fmt::format("{} has {}s 1..{}", pins.device, pin, last);
    }
    end.number = high_speed ? regular + *index : *index;
    return std::nullopt;
}

core::Result<SignalEnd> drive_end(std::vector<std::string> words) {
    SignalEnd end;
    const std::string device = words.empty() ? std::string() : lower(words.front());
    std::size_t taken = 0;
    if (device == "internal") {
        end.device = SignalEnd::Device::Epos2;
        end.port = kInternalPort;
        end.node = 1;
        taken = 1;
    } else if (device == "node" && words.size() > 1) {
        const auto node = number(words[1]);
        if (!node || *node < 1 || *node > 127) {
            return core::Error{"a node is 1..127"};
        }
        end.device = SignalEnd::Device::Epos2;
        end.port = kExternalPort;
        end.node = static_cast<canopen::NodeId>(*node);
        taken = 2;
    } else if (device == "escon2" && words.size() > 1) {
        end.device = SignalEnd::Device::Escon2;
        end.name = words[1];
        taken = 2;
    } else {
        return core::Error{std::string(kForms)};
    }
    words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(taken));
    if (auto problem =
            read_pin(std::move(words),
                     end.device == SignalEnd::Device::Escon2 ? kEscon2Pins : kEpos2Pins, end)) {
        return core::Error{*problem};
    }
    return end;
}

} // namespace

core::Result<SignalEnd> parse_signal_end(std::string_view text) {
    std::vector<std::string> words = words_of(text);
    if (words.size() == 1) {
        if (auto end = process_image_end(words.front())) {
            return *end;
        }
        return core::Error{fmt::format("{}; a bit is %IXbyte.bit with byte 0..{}, a word %IWn "
                                       "with n 0..{}",
                                       kForms, vm::kProcessImageSize - 1, kLastWord)};
    }
    return drive_end(std::move(words));
}

std::string to_string(const SignalEnd& end) {
    const bool input = end.direction == SignalEnd::Direction::Input;
    if (end.device == SignalEnd::Device::ProcessImage) {
        return end.kind == SignalEnd::Kind::Digital
                   ? fmt::format("%{}X{}.{}", input ? 'I' : 'Q', end.byte, end.bit)
                   : fmt::format("%{}W{}", input ? 'I' : 'Q', end.number);
    }
    const bool escon2 = end.device == SignalEnd::Device::Escon2;
    const std::string drive = escon2                      ? "escon2 " + end.name
                              : end.port == kInternalPort ? std::string("internal")
                                                          : fmt::format("node {}", end.node);
    const Pins& pins = escon2 ? kEscon2Pins : kEpos2Pins;
    const unsigned regular = input ? pins.digital_inputs : pins.digital_outputs;
    const bool high_speed = end.kind == SignalEnd::Kind::Digital && end.number > regular;
    return fmt::format("{} {}{} {} {}", drive, high_speed ? "high-speed " : "",
                       end.kind == SignalEnd::Kind::Digital ? "digital" : "analog",
                       input ? "input" : "output", high_speed ? end.number - regular : end.number);
}

std::optional<std::string> wire_problem(const SignalWire& wire) {
    if (wire.from.direction != SignalEnd::Direction::Output) {
        return fmt::format("'{}' is an input: a wire runs from an output", to_string(wire.from));
    }
    if (wire.to.direction != SignalEnd::Direction::Input) {
        return fmt::format("'{}' is an output: a wire runs to an input", to_string(wire.to));
    }
    if (wire.from.kind != wire.to.kind) {
        return fmt::format("'{}' is {} but '{}' is {}", to_string(wire.from),
                           wire.from.kind == SignalEnd::Kind::Digital ? "digital" : "analog",
                           to_string(wire.to),
                           wire.to.kind == SignalEnd::Kind::Digital ? "digital" : "analog");
    }
    return std::nullopt;
}

} // namespace eposp::device
