#pragma once

#include "eposp/canopen/sdo_block_receiver.hpp"
#include "eposp/canopen/sdo_block_sender.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/sdo_transmit_queue.hpp"
#include "eposp/canopen/sdo_watchdog.hpp"

#include <functional>
#include <optional>

namespace eposp::canopen {

/// One transfer of the SDO client with one server: the client's half of the protocols of CiA
/// 301 7.2.4.3 as a state machine fed by the server's responses and a timeout. It checks every
/// response (command specifier, multiplexer echo, toggle bit, block size, sequence number, CRC,
/// size indicator) and aborts the transfer on the first violation.
class SdoClientTransfer {
public:
    /// Told once when a transfer ends, after the transfer is idle again (so it may start the
    /// next one): AbortCode::None, and for an upload the value in take_value().
    using Done = std::function<void(AbortCode code)>;

    /// Messages go out through `queue`; the segments of block downloads straight through
    /// `port`, paced by the block sender.
    SdoClientTransfer(core::EventLoop& loop, can::Port& port, SdoTransmitQueue& queue,
                      const SdoClientConfig& config, Done done);

    void start_upload(std::uint32_t request_cob_id, sdo::Multiplexer mux,
                      const SdoRequestOptions& options);
    void start_download(std::uint32_t request_cob_id, sdo::Multiplexer mux, Bytes value,
                        const SdoRequestOptions& options);
    /// A response of this transfer's server; only while busy().
    void on_message(std::span<const std::uint8_t, sdo::kMessageSize> bytes);
    /// Aborts the running transfer: sends the abort message with `code` and ends with it.
    void abort(AbortCode code);

    bool busy() const { return state_ != State::Idle; }
    /// The uploaded value, once.
    Bytes take_value() { return std::move(data_); }

private:
    enum class State {
        Idle,
        InitiateDownload,
        DownloadSegment,
        InitiateUpload,
        UploadSegment,
        BlockDownloadInitiate,
        BlockDownloadSubBlock,
        BlockDownloadEnd,
        BlockUploadInitiate,
        BlockUploadSubBlock,
        BlockUploadEnd,
    };
    using MessageBytes = std::span<const std::uint8_t, sdo::kMessageSize>;

    void begin(std::uint32_t request_cob_id, sdo::Multiplexer mux, const SdoRequestOptions& options,
               State state);
    /// What to do with a response in the current state: 0 when handled.
    AbortCode handle(MessageBytes bytes);
    AbortCode initiate_download_response(MessageBytes bytes);
    AbortCode download_segment_response(MessageBytes bytes);
    AbortCode initiate_upload_response(MessageBytes bytes);
    AbortCode upload_segment(MessageBytes bytes);
    AbortCode block_download_initiate_response(MessageBytes bytes);
    AbortCode block_download_acknowledge(MessageBytes bytes);
    AbortCode block_upload_initiate_response(MessageBytes bytes);
    AbortCode block_upload_segment(MessageBytes bytes);
    AbortCode block_upload_end(MessageBytes bytes);

    bool initiating_block_transfer() const;
    /// The server refused block transfer: the same request again, segmented.
    void retry_segmented();
    AbortCode check_multiplexer(MessageBytes bytes) const;
    AbortCode check_size(bool finished) const;
    void send_download_segment();
    void send(const sdo::Message& message);
    void end(AbortCode code);

    SdoTransmitQueue& queue_;
    const SdoClientConfig& config_;
    Done done_;

    State state_ = State::Idle;
    std::uint32_t request_cob_id_ = 0;
    sdo::Multiplexer mux_;
    SdoRequestOptions options_;
    bool toggle_ = false;
    bool expedited_ = false;
    bool server_crc_ = false;
    std::optional<std::uint32_t> indicated_size_;
    Bytes data_; ///< the value being downloaded or uploaded
    std::size_t offset_ = 0;
    SdoWatchdog watchdog_;
    SdoBlockSender block_sender_;
    SdoBlockReceiver block_receiver_;
};

} // namespace eposp::canopen
