#include "eposp/can/pcap_reader.hpp"

#include "pcap_format.hpp"
#include "trace_file.hpp"

#include <chrono>
#include <fmt/format.h>
#include <iterator>
#include <span>

namespace eposp::can {
namespace {

constexpr std::uint32_t kPcapngMagic = 0x0A0D'0D0A;
constexpr std::uint32_t kNanosecondsPerSecond = 1'000'000'000;
constexpr std::uint32_t kMicrosecondsPerSecond = 1'000'000;

core::Error error(std::string message) {
    return core::Error{std::move(message)};
}

// Takes fields off the front of the file in its byte order; callers check remaining() first.
class FieldReader {
public:
    explicit FieldReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    void set_byte_order(std::endian order) { order_ = order; }
    std::size_t remaining() const { return bytes_.size(); }

    std::span<const std::uint8_t> take(std::size_t count) {
        const auto taken = bytes_.first(count);
        bytes_ = bytes_.subspan(count);
        return taken;
    }
    std::uint16_t u16() { return static_cast<std::uint16_t>(load(take(2))); }
    std::uint32_t u32() { return load(take(4)); }

private:
    std::uint32_t load(std::span<const std::uint8_t> field) const {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < field.size(); ++i) {
            const std::size_t shift = order_ == std::endian::little ? i : field.size() - 1 - i;
            value |= std::uint32_t{field[i]} << (8 * shift);
        }
        return value;
    }

    std::span<const std::uint8_t> bytes_;
    std::endian order_ = std::endian::little;
};

bool is_pcap_magic(std::uint32_t magic) {
    return magic == pcap::kMicrosecondMagic || magic == pcap::kNanosecondMagic;
}

core::Result<PcapHeader> read_header(FieldReader& in) {
    if (in.remaining() < pcap::kFileHeaderSize) {
        return error("too short for a pcap file header");
    }
    PcapHeader header;
    const auto magic_bytes = in.take(4);
    for (const std::endian order : {std::endian::little, std::endian::big}) {
        FieldReader magic(magic_bytes);
        magic.set_byte_order(order);
        if (const std::uint32_t value = magic.u32(); is_pcap_magic(value)) {
            header.magic = value;
            header.byte_order = order;
        }
    }
    if (header.magic == 0) {
        FieldReader magic(magic_bytes);
        const std::uint32_t value = magic.u32();
        return error(value == kPcapngMagic
                         ? std::string("a pcapng file; only classic pcap is supported")
                         : fmt::format("not a pcap file (magic 0x{:08X})", value));
    }
    in.set_byte_order(header.byte_order);
    header.version_major = in.u16();
    header.version_minor = in.u16();
    in.take(8); // time zone and accuracy: unused, 0 in practice
    header.snap_length = in.u32();
    header.link_type = in.u32();
    if (header.version_major != pcap::kVersionMajor ||
        header.version_minor != pcap::kVersionMinor) {
        return error(fmt::format("pcap version {}.{} is not 2.4", header.version_major,
                                 header.version_minor));
    }
    if (header.snap_length == 0) {
        return error("snap length is 0");
    }
    if (header.link_type != pcap::kLinkTypeCanSocketCan) {
        return error(
            fmt::format("link type {} is not LINKTYPE_CAN_SOCKETCAN (227)", header.link_type));
    }
    return header;
}

core::Result<PcapRecord> read_record(FieldReader& in, const PcapHeader& header) {
    if (in.remaining() < pcap::kRecordHeaderSize) {
        return error("record header is cut short");
    }
    const std::uint32_t seconds = in.u32();
    const std::uint32_t fraction = in.u32();
    const std::uint32_t captured = in.u32();
    const std::uint32_t original = in.u32();
    const bool nanoseconds = header.magic == pcap::kNanosecondMagic;
    if (fraction >= (nanoseconds ? kNanosecondsPerSecond : kMicrosecondsPerSecond)) {
        return error(fmt::format("sub-second timestamp {} is out of range", fraction));
    }
    if (captured > header.snap_length) {
        return error(fmt::format("captured length {} is above the snap length {}", captured,
                                 header.snap_length));
    }
    if (captured != original) {
        return error(fmt::format("truncated: {} of {} bytes captured", captured, original));
    }
    if (captured > in.remaining()) {
        return error(fmt::format("packet data of {} bytes is cut short", captured));
    }
    auto frame = pcap::decode_can_frame(in.take(captured));
    if (!frame) {
        return core::Error{frame.error()};
    }
    const core::Duration sub_second =
        nanoseconds ? core::Duration(fraction) : std::chrono::microseconds(fraction);
    return PcapRecord{TraceTime(std::chrono::seconds(seconds) + sub_second), captured, *frame};
}

} // namespace

core::Result<PcapCapture> read_pcap(std::istream& in) {
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    if (in.bad()) {
        return error("read error");
    }
    FieldReader fields(bytes);
    auto header = read_header(fields);
    if (!header) {
        return core::Error{header.error()};
    }
    PcapCapture capture{*header, {}};
    while (fields.remaining() > 0) {
        auto record = read_record(fields, capture.header);
        if (!record) {
            return error(fmt::format("record {}: {}", capture.records.size() + 1, record.error()));
        }
        capture.records.push_back(*record);
    }
    return capture;
}

core::Result<PcapCapture> read_pcap_file(const std::filesystem::path& path) {
    auto file = open_trace_file(path);
    if (!file) {
        return core::Error{file.error()};
    }
    auto capture = read_pcap(*file);
    if (!capture) {
        return error(fmt::format("{}: {}", path.string(), capture.error()));
    }
    return capture;
}

} // namespace eposp::can
