#include "eposp/service/commands.hpp"

#include <algorithm>

namespace eposp::service {
namespace {

// Reads the parameters of a frame in order; any read past the end marks the frame as short.
class ParameterReader {
public:
    explicit ParameterReader(std::span<const std::uint8_t> data) : data_(data) {}

    std::uint8_t u8() { return position_ < data_.size() ? data_[position_++] : fail(); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | u8() << 8); }
    std::uint32_t u32() { return u16() | static_cast<std::uint32_t>(u16()) << 16; }
    template <std::size_t N>
    std::array<std::uint8_t, N> bytes() {
        std::array<std::uint8_t, N> out{};
        std::ranges::generate(out, [this] { return u8(); });
        return out;
    }
    /// Whether every byte was read (a padding byte of an odd length may stay).
    bool exactly_consumed(bool padded) const {
        const std::size_t expected = padded ? position_ + position_ % 2 : position_;
        return !short_ && expected == data_.size();
    }

private:
    std::uint8_t fail() {
        short_ = true;
        return 0;
    }
    std::span<const std::uint8_t> data_;
    std::size_t position_ = 0;
    bool short_ = false;
};

class ParameterWriter {
public:
    void u8(std::uint8_t value) { data_.push_back(value); }
    void u16(std::uint16_t value) {
        u8(static_cast<std::uint8_t>(value));
        u8(static_cast<std::uint8_t>(value >> 8));
    }
    void u32(std::uint32_t value) {
        u16(static_cast<std::uint16_t>(value));
        u16(static_cast<std::uint16_t>(value >> 16));
    }
    void bytes(std::span<const std::uint8_t> values) {
        data_.insert(data_.end(), values.begin(), values.end());
    }
    std::vector<std::uint8_t> words() && {
        if (data_.size() % 2 != 0) {
            data_.push_back(0);
        }
        return std::move(data_);
    }

private:
    std::vector<std::uint8_t> data_;
};

// The network-addressed opcode of each plain one (EPOS2 P generation, v2).
struct NetworkPair {
    OpCode plain;
    std::uint8_t network_addressed;
};
constexpr std::array<NetworkPair, 11> kNetworkOpcodes{{
    {OpCode::ReadObject, 0x40},
    {OpCode::InitiateSegmentedRead, 0x41},
    {OpCode::SegmentRead, 0x42},
    {OpCode::WriteObject, 0x48},
    {OpCode::InitiateSegmentedWrite, 0x49},
    {OpCode::SegmentWrite, 0x4A},
    {OpCode::SendNmtService, 0x4B},
    {OpCode::SendCanFrame, 0x50},
    {OpCode::RequestCanFrame, 0x51},
    {OpCode::SendLssFrame, 0x54},
    {OpCode::ReadLssFrame, 0x55},
}};

std::optional<Network> read_network(ParameterReader& in, bool network_addressed) {
    if (!network_addressed) {
        return std::nullopt;
    }
    return static_cast<Network>(in.u16());
}

ObjectAddress read_object(ParameterReader& in, bool network_addressed) {
    ObjectAddress object;
    object.network = read_network(in, network_addressed);
    object.index = in.u16();
    object.sub_index = in.u8();
    object.node = in.u8();
    return object;
}

void write_network(ParameterWriter& out, std::optional<Network> network) {
    if (network) {
        out.u16(static_cast<std::uint16_t>(*network));
    }
}

void write_object(ParameterWriter& out, const ObjectAddress& object) {
    write_network(out, object.network);
    out.u16(object.index);
    out.u8(object.sub_index);
    out.u8(object.node);
}

// The plain opcode of a command and whether it came network-addressed.
struct Command {
    OpCode plain{};
    bool network_addressed = false;
};

std::optional<Command> command_of(std::uint8_t opcode) {
    for (const auto& pair : kNetworkOpcodes) {
        if (static_cast<std::uint8_t>(pair.plain) == opcode) {
            return Command{pair.plain, false};
        }
        if (pair.network_addressed == opcode) {
            return Command{pair.plain, true};
        }
    }
    return std::nullopt;
}

std::optional<Request> read_request(ParameterReader& in, Command command, bool& padded) {
    const bool net = command.network_addressed;
    switch (command.plain) {
    case OpCode::ReadObject:
        return ReadObject{read_object(in, net)};
    case OpCode::WriteObject: {
        WriteObject write;
        write.object = read_object(in, net);
        write.value = in.bytes<4>();
        return write;
    }
    case OpCode::InitiateSegmentedRead:
        return InitiateSegmentedRead{read_object(in, net)};
    case OpCode::InitiateSegmentedWrite: {
        InitiateSegmentedWrite write;
        write.object = read_object(in, net);
        write.length = in.u32();
        return write;
    }
    case OpCode::SegmentRead: {
        SegmentRead read;
        read.network = read_network(in, net);
        read.toggle = SegmentControl::decode(in.u8()).toggle;
        in.u8(); // a byte without meaning, to fill the word
        return read;
    }
    case OpCode::SegmentWrite: {
        SegmentWrite write;
        write.network = read_network(in, net);
        write.control = SegmentControl::decode(in.u8());
        for (std::size_t i = 0; i < write.control.length; ++i) {
            write.data.push_back(in.u8());
        }
        padded = true;
        return write;
    }
    case OpCode::SendNmtService: {
        SendNmtService nmt;
        nmt.network = read_network(in, net);
        nmt.node = in.u16();
        nmt.command = in.u16();
        return nmt;
    }
    case OpCode::SendCanFrame: {
        SendCanFrame send;
        send.network = read_network(in, net);
        send.cob_id = in.u16();
        send.length = in.u16();
        send.data = in.bytes<8>();
        return send;
    }
    case OpCode::RequestCanFrame: {
        RequestCanFrame request;
        request.network = read_network(in, net);
        request.cob_id = in.u16();
        request.length = in.u16();
        return request;
    }
    case OpCode::SendLssFrame: {
        SendLssFrame send;
        send.network = read_network(in, net);
        send.data = in.bytes<8>();
        return send;
    }
    case OpCode::ReadLssFrame: {
        ReadLssFrame read;
        read.network = read_network(in, net);
        read.timeout_ms = in.u16();
        return read;
    }
    default:
        return std::nullopt;
    }
}

std::uint8_t network_opcode(OpCode plain) {
    const auto pair = std::ranges::find(kNetworkOpcodes, plain, &NetworkPair::plain);
    return pair->network_addressed;
}

std::optional<Network> network_of(const Request& request) {
    return std::visit(
        [](const auto& command) -> std::optional<Network> {
            if constexpr (requires { command.object; }) {
                return command.object.network;
            } else {
                return command.network;
            }
        },
        request);
}

} // namespace

std::uint8_t SegmentControl::encode() const {
    return static_cast<std::uint8_t>((length & 0x3F) | (toggle ? 0x40 : 0) | (more ? 0x80 : 0));
}

SegmentControl SegmentControl::decode(std::uint8_t byte) {
    return {static_cast<std::uint8_t>(byte & 0x3F), (byte & 0x40) != 0, (byte & 0x80) != 0};
}

DecodedRequest decode_request(const Frame& frame) {
    const auto command = command_of(frame.opcode);
    if (!command) {
        return {std::nullopt, error::kIllegalCommand};
    }
    ParameterReader in(frame.data);
    bool padded = false;
    auto request = read_request(in, *command, padded);
    if (!request || !in.exactly_consumed(padded)) {
        return {std::nullopt, error::kLengthMismatch};
    }
    return {std::move(request), error::kNone};
}

Frame encode_request(const Request& request) {
    ParameterWriter out;
    const OpCode plain = std::visit(
        [&out](const auto& command) {
            using T = std::decay_t<decltype(command)>;
            if constexpr (std::is_same_v<T, ReadObject>) {
                write_object(out, command.object);
                return OpCode::ReadObject;
            } else if constexpr (std::is_same_v<T, WriteObject>) {
                write_object(out, command.object);
                out.bytes(command.value);
                return OpCode::WriteObject;
            } else if constexpr (std::is_same_v<T, InitiateSegmentedRead>) {
                write_object(out, command.object);
                return OpCode::InitiateSegmentedRead;
            } else if constexpr (std::is_same_v<T, InitiateSegmentedWrite>) {
                write_object(out, command.object);
                out.u32(command.length);
                return OpCode::InitiateSegmentedWrite;
            } else if constexpr (std::is_same_v<T, SegmentRead>) {
                write_network(out, command.network);
                out.u8(SegmentControl{0, command.toggle, false}.encode());
                out.u8(0);
                return OpCode::SegmentRead;
            } else if constexpr (std::is_same_v<T, SegmentWrite>) {
                write_network(out, command.network);
                out.u8(command.control.encode());
                out.bytes(command.data);
                return OpCode::SegmentWrite;
            } else if constexpr (std::is_same_v<T, SendNmtService>) {
                write_network(out, command.network);
                out.u16(command.node);
                out.u16(command.command);
                return OpCode::SendNmtService;
            } else if constexpr (std::is_same_v<T, SendCanFrame>) {
                write_network(out, command.network);
                out.u16(command.cob_id);
                out.u16(command.length);
                out.bytes(command.data);
                return OpCode::SendCanFrame;
            } else if constexpr (std::is_same_v<T, RequestCanFrame>) {
                write_network(out, command.network);
                out.u16(command.cob_id);
                out.u16(command.length);
                return OpCode::RequestCanFrame;
            } else if constexpr (std::is_same_v<T, SendLssFrame>) {
                write_network(out, command.network);
                out.bytes(command.data);
                return OpCode::SendLssFrame;
            } else {
                static_assert(std::is_same_v<T, ReadLssFrame>);
                write_network(out, command.network);
                out.u16(command.timeout_ms);
                return OpCode::ReadLssFrame;
            }
        },
        request);
    const std::uint8_t opcode =
        network_of(request) ? network_opcode(plain) : static_cast<std::uint8_t>(plain);
    return Frame{opcode, std::move(out).words()};
}

bool answered_on_v1(std::uint8_t opcode) {
    return opcode != static_cast<std::uint8_t>(OpCode::SendNmtService) &&
           opcode != static_cast<std::uint8_t>(OpCode::SendCanFrame) &&
           opcode != static_cast<std::uint8_t>(OpCode::SendLssFrame);
}

Frame encode_answer(const Answer& answer) {
    ParameterWriter out;
    out.u32(answer.error);
    out.bytes(answer.data);
    return Frame{kAnswerOpCode, std::move(out).words()};
}

std::optional<Answer> decode_answer(const Frame& frame) {
    if (frame.data.size() < 4) {
        return std::nullopt;
    }
    ParameterReader in(frame.data);
    Answer answer{in.u32(), {}};
    answer.data.assign(frame.data.begin() + 4, frame.data.end());
    return answer;
}

} // namespace eposp::service
