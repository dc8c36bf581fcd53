#include "eposp/can/pcap_writer.hpp"

#include "pcap_format.hpp"

#include <array>
#include <chrono>
#include <cstdint>

namespace eposp::can {
namespace {

// Fixed little-endian output, so a run gives the same bytes on every host; readers take the
// byte order from the magic number.
template <std::size_t N>
class LittleEndianBuffer {
public:
    void put16(std::uint16_t value) {
        put_byte(value);
        put_byte(value >> 8);
    }
    void put32(std::uint32_t value) {
        put16(static_cast<std::uint16_t>(value));
        put16(static_cast<std::uint16_t>(value >> 16));
    }
    void put_bytes(std::span<const std::uint8_t> bytes) {
        for (const std::uint8_t byte : bytes) {
            put_byte(byte);
        }
    }
    std::string_view view() const { return {bytes_.data(), size_}; }

private:
    void put_byte(unsigned value) { bytes_.at(size_++) = static_cast<char>(value & 0xFF); }

    std::array<char, N> bytes_{};
    std::size_t size_ = 0;
};

} // namespace

PcapWriter::PcapWriter(TraceOutput output) : output_(std::move(output)) {
    LittleEndianBuffer<pcap::kFileHeaderSize> header;
    header.put32(pcap::kNanosecondMagic);
    header.put16(pcap::kVersionMajor);
    header.put16(pcap::kVersionMinor);
    header.put32(0); // time zone offset: always 0 (UTC)
    header.put32(0); // timestamp accuracy: always 0
    header.put32(pcap::kSnapLength);
    header.put32(pcap::kLinkTypeCanSocketCan);
    output_.write(header.view());
}

void PcapWriter::record(TraceTime time, std::string_view /*interface_name*/, const Frame& frame) {
    const auto since_epoch = time.time_since_epoch();
    const auto seconds = std::chrono::floor<std::chrono::seconds>(since_epoch);
    const auto nanoseconds = since_epoch - seconds;
    LittleEndianBuffer<pcap::kRecordHeaderSize + pcap::kCanFrameSize> record;
    // 32-bit seconds as the format has them: enough until 2106.
    record.put32(static_cast<std::uint32_t>(seconds.count()));
    record.put32(static_cast<std::uint32_t>(nanoseconds.count()));
    record.put32(pcap::kCanFrameSize); // captured length
    record.put32(pcap::kCanFrameSize); // original length
    record.put_bytes(pcap::encode_can_frame(frame));
    output_.write(record.view());
}

} // namespace eposp::can
