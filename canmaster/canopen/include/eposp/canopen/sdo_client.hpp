#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/sdo_protocol.hpp"
#include "eposp/canopen/sdo_transmit_queue.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/event_loop.hpp"

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>

namespace eposp::canopen {

struct SdoClientConfig {
    /// A transfer whose server makes no progress for this long is aborted with 0x05040000.
    core::Duration timeout = std::chrono::seconds(1);
    /// Segments per sub-block the client asks servers for in block uploads (1..127).
    std::uint8_t block_size = sdo::kMaxBlockSize;
    /// Uploads of more bytes are aborted with 0x05040005 (out of memory).
    std::size_t max_upload_size = 16 * 1024 * 1024;
    /// When the port's transmit queue is full (many servers at once, a block download), the
    /// frames that did not fit follow after this delay.
    core::Duration retry_delay = std::chrono::milliseconds(1);
};

/// How a value that does not fit an expedited transfer travels. Downloads of up to 4 bytes are
/// always expedited; for uploads the server chooses between expedited and segmented.
enum class SdoProtocol : std::uint8_t {
    Segmented, ///< CiA 301 7.2.4.3.2 / 7.2.4.3.5: what every server supports
    /// CiA 301 7.2.4.3.8 / 7.2.4.3.12: fewer frames for large values, with a CRC. A server that
    /// refuses the block initiate with 0x05040001 (no block transfer) gets the request again,
    /// segmented.
    Block,
};

struct SdoRequestOptions {
    SdoProtocol protocol = SdoProtocol::Segmented;
    /// Block uploads: a value of at most this many bytes may come by the plain upload protocol
    /// instead (the protocol switch threshold, pst; 0 forbids the switch).
    std::uint8_t protocol_switch_threshold = sdo::kExpeditedSize;
    /// Overrides SdoClientConfig::timeout for this request (a flash write that takes long).
    std::optional<core::Duration> timeout{};
    /// Expedited downloads of 4 bytes: false sends them without a size (CiA 301 7.2.4.3.3, e = 1,
    /// s = 0), so that the server takes as many bytes as the object's type has. A gateway does
    /// this for a service tool's 4-byte WriteObject, whose target's type it does not know.
    bool size_indicated = true;
};

struct SdoRequestId {
    std::uint64_t value = 0;
    explicit operator bool() const { return value != 0; }
    friend bool operator==(SdoRequestId, SdoRequestId) = default;
};

/// The SDO client side of a master (CiA 301 7.2.4): reads (uploads) and writes (downloads)
/// objects of up to 127 servers through one port, each request completing by callback with the
/// abort code (AbortCode::None on success). Requests to one server are queued and run one at a
/// time, as CiA 301 allows only one transfer per SDO; servers are served concurrently. Every
/// protocol violation by a server aborts the transfer with its code, which is sent to the server
/// and given to the callback. Every callback is called exactly once (unless the client is
/// destroyed first), never from inside upload() or download().
class SdoClient {
public:
    using UploadCallback = std::function<void(AbortCode code, Bytes value)>;
    using DownloadCallback = std::function<void(AbortCode code)>;

    SdoClient(core::EventLoop& loop, can::Port& port, SdoClientConfig config = {});
    ~SdoClient();
    SdoClient(const SdoClient&) = delete;
    SdoClient& operator=(const SdoClient&) = delete;

    /// Feeds a received frame; frames that are no response of a running transfer are ignored.
    void on_frame(const can::Frame& frame);

    /// Reads object `index`:`sub_index` of the server of `node` (1..127; anything else is a
    /// programming error, std::invalid_argument).
    SdoRequestId upload(NodeId node, std::uint16_t index, std::uint8_t sub_index,
                        UploadCallback done, SdoRequestOptions options = {});
    /// Writes `value` to object `index`:`sub_index` of the server of `node`.
    SdoRequestId download(NodeId node, std::uint16_t index, std::uint8_t sub_index, Bytes value,
                          DownloadCallback done, SdoRequestOptions options = {});

    /// Ends a request with `reason`, which its callback receives: a queued one is dropped, a
    /// running one is aborted with `reason` sent to the server. False when the request already
    /// completed.
    bool cancel(SdoRequestId id, AbortCode reason = AbortCode::GeneralError);
    /// Cancels every request to `node` (a node that disappeared); returns how many.
    std::size_t cancel_all(NodeId node, AbortCode reason = AbortCode::GeneralError);

    /// The COB-IDs of the server of `node` as the SDO client parameter 0x1280 sub-indices 1 and
    /// 2 hold them (bit 29: 29-bit identifier; bit 31: not valid, so that requests fail with
    /// 0x060A0023). Defaults: 0x600 + node and 0x580 + node. Takes effect with the next transfer.
    void set_cob_ids(NodeId node, std::uint32_t request, std::uint32_t response);

    /// Requests to `node` queued or running.
    std::size_t pending(NodeId node) const;
    /// A transfer with the server of `node` is running.
    bool busy(NodeId node) const;

private:
    struct Request;
    struct Channel;

    Channel& channel(NodeId node);
    const Channel* find_channel(NodeId node) const;
    SdoRequestId enqueue(NodeId node, Request request);
    void schedule_start(Channel& channel);
    void start_next(Channel& channel);
    /// The running transfer of `channel` ended: its request completes, the next one starts.
    void complete(Channel& channel, AbortCode code);
    void finish(Channel& channel, AbortCode code);
    static void notify(Request& request, AbortCode code, Bytes value);

    core::EventLoop& loop_;
    can::Port& port_;
    SdoClientConfig config_;
    SdoTransmitQueue transmit_queue_;
    std::uint64_t next_id_ = 1;
    std::array<std::unique_ptr<Channel>, 128> channels_; ///< by node-ID, made on first use
    std::unordered_map<std::uint32_t, NodeId> by_response_cob_id_;
};

} // namespace eposp::canopen
