// A CANopen slave node (node.hpp) fed arbitrary frame sequences on a virtual bus while virtual
// time passes: whatever a master or a broken bus sends, the node must not crash, hang or trip a
// sanitizer, and what it sends must be valid frames.
//
// Input: records of
//   [wait] [flags] [identifier: 2 bytes, or 4 when extended] [dlc data bytes unless remote]
// wait: virtual time before the frame is sent, 0..199 ms, or 200..255 for (wait - 199) * 250 ms
// (long enough for heartbeat and guarding timeouts); flags: bit 7 extended, bit 6 remote, bits
// 0..3 the DLC (above 8 taken as 8); identifier big-endian. A truncated record ends the input.

#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/event_loop.hpp"
#include "fuzz_check.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace {

using namespace std::chrono_literals;
using namespace eposp;

constexpr canopen::NodeId kNode = 5;
constexpr std::size_t kMaxFrames = 512;
constexpr core::Duration kSettleTime = 2s;

/// Bounds the work of one input. Virtual time alone does not: CiA 301 leaves 0x1006 to the
/// network designer, and a SYNC every few microseconds is a valid configuration that makes
/// seconds of virtual time cost minutes of real time.
class EventBudget {
public:
    /// Runs `duration` of virtual time in steps; false once the budget is spent.
    bool run_for(core::EventLoop& loop, core::Duration duration) {
        const core::TimePoint end = loop.now() + duration;
        while (left_ > 0 && loop.now() < end) {
            const std::uint64_t events = loop.run_until(std::min(end, loop.now() + kStep));
            left_ -= std::min(events, left_);
        }
        return left_ > 0;
    }

private:
    static constexpr core::Duration kStep = 1ms;
    std::uint64_t left_ = 50'000;
};

/// Reads the records of an input one by one.
class FrameRecords {
public:
    explicit FrameRecords(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    struct Record {
        core::Duration wait;
        can::Frame frame;
    };
    std::optional<Record> next() {
        if (remaining() < 2) {
            return std::nullopt;
        }
        const std::uint8_t wait = take();
        const std::uint8_t flags = take();
        const bool extended = (flags & 0x80) != 0;
        const bool remote = (flags & 0x40) != 0;
        const auto dlc = std::min<std::uint8_t>(flags & 0x0F, can::kMaxDataLength);
        const std::size_t id_bytes = extended ? 4 : 2;
        const std::size_t data_bytes = remote ? 0 : dlc;
        if (remaining() < id_bytes + data_bytes) {
            return std::nullopt;
        }
        std::uint32_t id = 0;
        for (std::size_t i = 0; i < id_bytes; ++i) {
            id = (id << 8) | take();
        }
        id &= extended ? can::kMaxExtendedId : can::kMaxStandardId;
        Record record{wait < 200 ? core::Duration(std::chrono::milliseconds(wait))
                                 : core::Duration((wait - 199) * 250ms),
                      remote
                          ? can::Frame::remote_frame(id, dlc, extended)
                          : can::Frame::data_frame(id, bytes_.subspan(at_, data_bytes), extended)};
        at_ += data_bytes;
        return record;
    }

private:
    std::size_t remaining() const { return bytes_.size() - at_; }
    std::uint8_t take() { return bytes_[at_++]; }

    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

/// A device with mappable variables and strings to read and write, so that SDO (expedited,
/// segmented, block) and PDO traffic reach real objects.
canopen::ObjectDictionary device_dictionary() {
    using canopen::Access;
    using canopen::DataType;
    canopen::ObjectDictionary od;
    od.add_variable(0x2000, "Position", DataType::Unsigned32, Access::ReadWrite,
                    canopen::encode<std::uint32_t>(0))
        .pdo_mappable = true;
    od.add_variable(0x2001, "Command", DataType::Unsigned16, Access::ReadWrite,
                    canopen::encode<std::uint16_t>(0))
        .pdo_mappable = true;
    od.add_variable(0x2002, "Name", DataType::VisibleString, Access::ReadOnly,
                    canopen::encode_string("EPOS P fuzz node"));
    od.add_variable(0x2003, "Scratch", DataType::VisibleString, Access::ReadWrite,
                    canopen::encode_string("0123456789abcdef0123456789abcdef"));
    return od;
}

canopen::NodeConfig node_config() {
    canopen::NodeConfig config;
    config.node_id = kNode;
    config.device_type = 0x0002'0192;
    config.identity = {
        .vendor_id = 0xFB, .product_code = 0x1234, .revision_number = 2, .serial_number = 99};
    config.heartbeat_consumer_entries = 2;
    // Valid PDOs of every transmission kind (CiA 301 7.2.2), so that received SYNCs, RPDOs
    // and remote frames reach the PDO code; the fuzzer can still remap them over SDO.
    config.pdos = canopen::cia301_pdo_defaults(kNode, 2, 4);
    auto& rpdos = config.pdos->rpdos;
    rpdos[0] = {.cob_id = 0x205, .mapping = {0x2001'0010}};
    rpdos[1] = {.cob_id = 0x305, .transmission_type = 1, .mapping = {0x2000'0020}};
    auto& tpdos = config.pdos->tpdos;
    tpdos[0] = {.cob_id = 0x185, .transmission_type = 1, .mapping = {0x2000'0020}};
    tpdos[1] = {.cob_id = 0x285,
                .transmission_type = 0xFF,
                .inhibit_time = 10,
                .event_timer = 50,
                .mapping = {0x2001'0010}};
    tpdos[2] = {.cob_id = 0x385,
                .transmission_type = 3,
                .sync_start = 2,
                .mapping = {0x2001'0010, 0x2000'0020}};
    tpdos[3] = {.cob_id = 0x485, .transmission_type = 0xFD, .mapping = {0x2000'0020}};
    return config;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    core::EventLoop loop;
    can::VirtualBus bus(loop);
    bool sent_invalid_frame = false;
    bus.add_observer([&](const can::WireEvent& event) {
        if (event.sender == "node" && !event.frame.error && !event.frame.valid()) {
            sent_invalid_frame = true;
        }
    });
    const auto node_port = bus.connect("node");
    const auto master = bus.connect("master");
    canopen::ObjectDictionary od = device_dictionary();
    canopen::Node node(loop, *node_port, od, node_config());
    node.start();

    FrameRecords records({data, size});
    EventBudget budget;
    for (std::size_t count = 0; count < kMaxFrames; ++count) {
        const auto record = records.next();
        if (!record || !budget.run_for(loop, record->wait)) {
            break;
        }
        master->send(record->frame);
    }
    budget.run_for(loop, kSettleTime);
    fuzz::require(!sent_invalid_frame, "the node sends valid frames only");
    return 0;
}
