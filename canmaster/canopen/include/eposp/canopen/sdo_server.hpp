#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/sdo_block_receiver.hpp"
#include "eposp/canopen/sdo_block_sender.hpp"
#include "eposp/canopen/sdo_protocol.hpp"
#include "eposp/canopen/sdo_watchdog.hpp"
#include "eposp/core/event_loop.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace eposp::canopen {

struct SdoServerConfig {
    /// A transfer that makes no progress for this long is aborted with 0x05040000. CiA 301
    /// leaves the time to the device; 1 s is what many devices use.
    core::Duration timeout = std::chrono::seconds(1);
    /// Segments per sub-block the server asks for in block downloads (1..127).
    std::uint8_t block_size = sdo::kMaxBlockSize;
    /// When the transmit queue is full during a block upload, the rest of the sub-block follows
    /// after this delay.
    core::Duration retry_delay = std::chrono::milliseconds(1);
};

/// The default SDO server of a node (CiA 301 7.2.4): requests on COB-ID 0x600 + node-ID,
/// responses on 0x580 + node-ID; expedited, segmented and block transfers both ways.
///
/// - Every access goes through the dictionary's remote read() / write(), whose abort code goes
///   back unchanged. A download is also checked with ObjectDictionary::check_write_size() at its
///   initiate request and as its data grows, so that a refused value ends before all its data
///   travelled. DOMAIN objects take values of any size up to their SubObject::max_length.
/// - One transfer at a time: a new initiate request ends the running transfer without a reply
///   and is served (the client gave the old one up); an abort from the client ends it silently.
/// - SDOs exist only in NMT pre-operational and operational (CiA 301 7.3.2.2); in the other
///   states every frame is ignored.
class SdoServer {
public:
    SdoServer(core::EventLoop& loop, can::Port& port, ObjectDictionary& dictionary, NodeId node,
              SdoServerConfig config = {});
    SdoServer(const SdoServer&) = delete;
    SdoServer& operator=(const SdoServer&) = delete;

    /// Feeds a received frame; frames other than this server's requests are ignored.
    void on_frame(const can::Frame& frame);
    /// Adds the identifiers of the frames on_frame() takes now (FrameRouter).
    void receive_keys(ReceiveKeys& keys) const;
    /// The node's NMT state; the server starts in pre-operational. Leaving pre-operational and
    /// operational drops a running transfer without a reply.
    void set_nmt_state(NmtState state);

    /// A transfer is running.
    bool busy() const { return state_ != State::Idle; }
    /// A node-ID LSS configured, at the node's reset communication: the default COB-IDs follow
    /// it (CiA 301 7.3.5); a running transfer ends without a reply.
    void set_node_id(NodeId node);
    std::uint32_t request_cob_id() const { return request_cob_id_; }
    std::uint32_t response_cob_id() const { return response_cob_id_; }

private:
    enum class State {
        Idle,
        DownloadSegments,
        UploadSegments,
        BlockDownloadSubBlock,
        BlockDownloadEnd,
        BlockUploadStart,
        BlockUploadSubBlock,
        BlockUploadEnd,
    };
    using MessageBytes = std::span<const std::uint8_t, sdo::kMessageSize>;

    void initiate(MessageBytes bytes);
    void continue_transfer(MessageBytes bytes);
    void initiate_download(MessageBytes bytes);
    void download_segment(MessageBytes bytes);
    void initiate_upload();
    void respond_upload();
    void upload_segment(MessageBytes bytes);
    void initiate_block_download(MessageBytes bytes);
    void block_download_segment(MessageBytes bytes);
    void end_block_download(MessageBytes bytes);
    void initiate_block_upload(MessageBytes bytes);
    void acknowledge_block_upload(MessageBytes bytes);

    /// What the dictionary would say to a write of `indicated` bytes, before any data travels.
    AbortCode check_download(std::optional<std::uint32_t> indicated) const;
    /// Starts collecting the data of a segmented or block download.
    void begin_download(std::optional<std::uint32_t> indicated);
    /// Received data of at least `at_least` bytes against the size indicator (CiA 301: the
    /// size indicated is the size that follows) or, without one, the object's longest value.
    AbortCode check_download_progress(std::size_t at_least, bool finished) const;
    void write_download();
    void begin_transfer(State state);
    void send(const sdo::Message& message);
    void abort(AbortCode code);
    /// Ends the transfer in progress; a download that had not handed its value over tells the
    /// dictionary (ObjectDictionary::write_aborted) with `reason`.
    void end_transfer(AbortCode reason);
    void finish();

    can::Port& port_;
    ObjectDictionary& dictionary_;
    SdoServerConfig config_;
    std::uint32_t request_cob_id_;
    std::uint32_t response_cob_id_;
    bool enabled_ = true;

    State state_ = State::Idle;
    sdo::Multiplexer mux_;
    bool toggle_ = false;
    bool client_crc_ = false;
    std::optional<std::uint32_t> indicated_size_;
    Bytes data_; ///< the value being uploaded or downloaded; its capacity is kept between transfers
    std::size_t upload_offset_ = 0;
    std::uint8_t upload_block_size_ = 0;
    SdoWatchdog watchdog_;
    SdoBlockSender block_sender_;
    SdoBlockReceiver block_receiver_;
};

/// Adds the default SDO server's parameter object 0x1200 (CiA 301 7.5.2.33; EPOS2 firmware
/// specification 8.2.17): sub-indices 1 and 2 hold the request and response COB-IDs, read-only.
void add_sdo_server_objects(ObjectDictionary& dictionary, NodeId node);

} // namespace eposp::canopen
