#include "eposp/device/signal_wire.hpp"

#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/process_image.hpp"
#include "text_words.hpp"

#include <cstdio>
#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr std::string_view kForms =
    "a wire's end is a process image bit or word (%QX0.3, %IX2.0, %QW16, %IW16) or an EPOS2's "
    "'internal|node N digital input|digital output|analog input N'";

// The EPOS2 24/5's connectors (EPOS2 FW spec 8.2.56 - 8.2.63).
constexpr unsigned kEpos2DigitalInputs = 6;
constexpr unsigned kEpos2DigitalOutputs = 4;
constexpr unsigned kEpos2AnalogInputs = 2;
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

core::Result<SignalEnd> epos2_end(std::vector<std::string> words) {
    SignalEnd end;
    end.device = SignalEnd::Device::Epos2;
    if (words.size() == 4 && lower(words[0]) == "internal") {
        end.port = kInternalPort;
        end.node = 1;
        words.erase(words.begin());
    } else if (words.size() == 5 && lower(words[0]) == "node") {
        const auto node = number(words[1]);
        if (!node || *node < 1 || *node > 127) {
            return core::Error{"a node is 1..127"};
        }
        end.port = kExternalPort;
        end.node = static_cast<canopen::NodeId>(*node);
        words.erase(words.begin(), words.begin() + 2);
    } else {
        return core::Error{std::string(kForms)};
    }
    const std::string kind = lower(words[0]);
    const std::string direction = lower(words[1]);
    const auto index = number(words[2]);
    if ((kind != "digital" && kind != "analog") ||
        (direction != "input" && direction != "output") || !index) {
        return core::Error{std::string(kForms)};
    }
    end.kind = kind == "digital" ? SignalEnd::Kind::Digital : SignalEnd::Kind::Analog;
    end.direction =
        direction == "input" ? SignalEnd::Direction::Input : SignalEnd::Direction::Output;
    end.number = *index;
    const unsigned last =
        end.kind == SignalEnd::Kind::Analog
            ? (end.direction == SignalEnd::Direction::Input ? kEpos2AnalogInputs : 0)
        : end.direction == SignalEnd::Direction::Input ? kEpos2DigitalInputs
                                                       : kEpos2DigitalOutputs;
    if (last == 0) {
        return core::Error{"an EPOS2's analog output is not a signal of the simulation"};
    }
    if (end.number < 1 || end.number > last) {
        return core::Error{fmt::format("an EPOS2 24/5 has {} {}s 1..{}", kind, direction, last)};
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
    return epos2_end(std::move(words));
}

std::string to_string(const SignalEnd& end) {
    const bool input = end.direction == SignalEnd::Direction::Input;
    if (end.device == SignalEnd::Device::ProcessImage) {
        return end.kind == SignalEnd::Kind::Digital
                   ? fmt::format("%{}X{}.{}", input ? 'I' : 'Q', end.byte, end.bit)
                   : fmt::format("%{}W{}", input ? 'I' : 'Q', end.number);
    }
    const std::string drive =
        end.port == kInternalPort ? std::string("internal") : fmt::format("node {}", end.node);
    return fmt::format("{} {} {} {}", drive,
                       end.kind == SignalEnd::Kind::Digital ? "digital" : "analog",
                       input ? "input" : "output", end.number);
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
