#include "eposp/canopen/sdo_server.hpp"

#include "eposp/canopen/cob_id.hpp"

#include <algorithm>

namespace eposp::canopen {

using namespace sdo;

namespace {

// Upfront reservation for a download with a size indicator; a larger value grows as it arrives,
// so a wrong indicator costs no memory.
constexpr std::size_t kMaxReservation = 64 * 1024;

bool is_initiate(std::uint8_t byte0) {
    switch (command_specifier(byte0)) {
    case ccs::kInitiateDownload:
    case ccs::kInitiateUpload:
        return true;
    case ccs::kBlockUpload:
    case ccs::kBlockDownload:
        return block_subcommand(byte0) == block::kInitiate;
    default:
        return false;
    }
}

} // namespace

SdoServer::SdoServer(core::EventLoop& loop, can::Port& port, ObjectDictionary& dictionary,
                     NodeId node, SdoServerConfig config)
    : port_(port), dictionary_(dictionary), config_(config),
      request_cob_id_(default_request_cob_id(node)),
      response_cob_id_(default_response_cob_id(node)),
      watchdog_(loop, [this] { abort(AbortCode::SdoTimeout); }),
      block_sender_(loop, port, config.retry_delay) {
    config_.block_size = std::clamp<std::uint8_t>(config_.block_size, 1, kMaxBlockSize);
}

void SdoServer::set_node_id(NodeId node) {
    finish();
    request_cob_id_ = default_request_cob_id(node);
    response_cob_id_ = default_response_cob_id(node);
}

void SdoServer::set_nmt_state(NmtState state) {
    enabled_ = state == NmtState::PreOperational || state == NmtState::Operational;
    if (!enabled_) {
        finish();
    }
}

void SdoServer::receive_keys(ReceiveKeys& keys) const {
    keys.push_back(receive_key(request_cob_id_));
}

void SdoServer::on_frame(const can::Frame& frame) {
    if (!enabled_ || !is_message_on(frame, request_cob_id_)) {
        return;
    }
    const auto bytes = bytes_of(frame);
    const bool in_sub_block = state_ == State::BlockDownloadSubBlock;
    // CiA 301 7.2.4.3.17: an abort ends the transfer; it is never answered.
    if (in_sub_block ? bytes[0] == kAbortCommand : command_specifier(bytes[0]) == kAbort) {
        end_transfer(static_cast<AbortCode>(value_of(bytes)));
        return;
    }
    if (in_sub_block) {
        block_download_segment(bytes);
    } else if (is_initiate(bytes[0])) {
        initiate(bytes);
    } else {
        continue_transfer(bytes);
    }
}

void SdoServer::initiate(MessageBytes bytes) {
    // CiA 301 7.2.4.2: a new request ends the transfer in progress.
    end_transfer(AbortCode::CommandSpecifier);
    mux_ = multiplexer_of(bytes);
    switch (command_specifier(bytes[0])) {
    case ccs::kInitiateDownload:
        initiate_download(bytes);
        break;
    case ccs::kInitiateUpload:
        initiate_upload();
        break;
    case ccs::kBlockDownload:
        initiate_block_download(bytes);
        break;
    default:
        initiate_block_upload(bytes);
        break;
    }
}

void SdoServer::continue_transfer(MessageBytes bytes) {
    const std::uint8_t command = command_specifier(bytes[0]);
    const std::uint8_t subcommand = block_subcommand(bytes[0]);
    switch (state_) {
    case State::DownloadSegments:
        if (command == ccs::kDownloadSegment) {
            return download_segment(bytes);
        }
        break;
    case State::UploadSegments:
        if (command == ccs::kUploadSegment) {
            return upload_segment(bytes);
        }
        break;
    case State::BlockDownloadEnd:
        if (command == ccs::kBlockDownload) { // not an initiate, so the end request
            return end_block_download(bytes);
        }
        break;
    case State::BlockUploadStart:
        if (command == ccs::kBlockUpload && subcommand == block::kStartUpload) {
            state_ = State::BlockUploadSubBlock;
            watchdog_.kick();
            block_sender_.begin(response_cob_id_, data_);
            return block_sender_.send_block(upload_block_size_);
        }
        break;
    case State::BlockUploadSubBlock:
        if (command == ccs::kBlockUpload && subcommand == block::kAcknowledge) {
            return acknowledge_block_upload(bytes);
        }
        break;
    case State::BlockUploadEnd:
        if (command == ccs::kBlockUpload && subcommand == block::kEnd) {
            return finish();
        }
        break;
    case State::Idle:
        // Nothing runs, so the abort names what the frame's bytes 1..3 would address.
        mux_ = multiplexer_of(bytes);
        break;
    case State::BlockDownloadSubBlock:
        break; // handled before: every frame of a sub-block is a segment
    }
    abort(AbortCode::CommandSpecifier);
}

// CiA 301 7.2.4.3.2 ff.: download (client to server), expedited or segmented.

void SdoServer::initiate_download(MessageBytes bytes) {
    const bool expedited = (bytes[0] & 0x02) != 0;
    const bool size_indicated = (bytes[0] & 0x01) != 0;
    if (!expedited) {
        const auto indicated = size_indicated ? std::optional(value_of(bytes)) : std::nullopt;
        if (const AbortCode code = check_download(indicated); code != AbortCode::None) {
            return abort(code);
        }
        begin_download(indicated);
        begin_transfer(State::DownloadSegments);
        return send(message(initiate_command(scs::kInitiateDownload, 0, false, false), mux_));
    }
    // Without a size the 4 data bytes hold "an unspecified number of bytes": as many as the
    // object's type has, if that fits.
    std::size_t size = kExpeditedSize - ((bytes[0] >> 2) & 0x03);
    if (!size_indicated) {
        const SubObject* entry = dictionary_.find(mux_.index, mux_.sub_index);
        const auto fixed = entry ? fixed_size(entry->type) : std::nullopt;
        size = fixed && *fixed <= kExpeditedSize ? *fixed : kExpeditedSize;
    }
    const AbortCode code = dictionary_.write(mux_.index, mux_.sub_index, bytes.subspan(4, size));
    if (code != AbortCode::None) {
        return abort(code);
    }
    send(message(initiate_command(scs::kInitiateDownload, 0, false, false), mux_));
}

void SdoServer::download_segment(MessageBytes bytes) {
    if (toggle_of(bytes[0]) != toggle_) {
        return abort(AbortCode::ToggleBit);
    }
    const std::size_t unused = (bytes[0] >> 1) & 0x07;
    const bool last = (bytes[0] & 0x01) != 0;
    data_.insert(data_.end(), bytes.begin() + 1, bytes.end() - static_cast<std::ptrdiff_t>(unused));
    if (const AbortCode code = check_download_progress(data_.size(), last);
        code != AbortCode::None) {
        return abort(code);
    }
    const auto response = message(segment_command(scs::kDownloadSegment, toggle_), {});
    if (!last) {
        toggle_ = !toggle_;
        watchdog_.kick();
        return send(response);
    }
    // The last segment is confirmed only once the dictionary took the value; a value it
    // refused was handed over (it says why itself), so the transfer is over first.
    finish();
    const AbortCode code = dictionary_.write(mux_.index, mux_.sub_index, data_);
    if (code != AbortCode::None) {
        return abort(code);
    }
    send(response);
}

// CiA 301 7.2.4.3.5 ff.: upload (server to client), expedited or segmented.

void SdoServer::initiate_upload() {
    if (const AbortCode code = dictionary_.read(mux_.index, mux_.sub_index, data_);
        code != AbortCode::None) {
        return abort(code);
    }
    respond_upload();
}

void SdoServer::respond_upload() {
    // No bytes cannot be expedited (n is 0..3): an empty value goes as one empty segment.
    if (!data_.empty() && data_.size() <= kExpeditedSize) {
        Message response = message(
            initiate_command(scs::kInitiateUpload, kExpeditedSize - data_.size(), true, true),
            mux_);
        std::copy(data_.begin(), data_.end(), response.begin() + 4);
        return send(response);
    }
    upload_offset_ = 0;
    begin_transfer(State::UploadSegments);
    send(message(initiate_command(scs::kInitiateUpload, 0, false, true), mux_,
                 static_cast<std::uint32_t>(data_.size())));
}

void SdoServer::upload_segment(MessageBytes bytes) {
    if (toggle_of(bytes[0]) != toggle_) {
        return abort(AbortCode::ToggleBit);
    }
    const std::size_t size = std::min(kSegmentSize, data_.size() - upload_offset_);
    const auto chunk = std::span<const std::uint8_t>(data_).subspan(upload_offset_, size);
    upload_offset_ += size;
    const bool last = upload_offset_ == data_.size();
    const auto response = segment_message(
        segment_command(scs::kUploadSegment, toggle_, kSegmentSize - size, last), chunk);
    if (last) {
        finish();
    } else {
        toggle_ = !toggle_;
        watchdog_.kick();
    }
    send(response);
}

// CiA 301 7.2.4.3.8 ff.: block download.

void SdoServer::initiate_block_download(MessageBytes bytes) {
    const bool size_indicated = (bytes[0] & 0x02) != 0;
    const auto indicated = size_indicated ? std::optional(value_of(bytes)) : std::nullopt;
    if (const AbortCode code = check_download(indicated); code != AbortCode::None) {
        return abort(code);
    }
    client_crc_ = (bytes[0] & 0x04) != 0;
    begin_download(indicated);
    block_receiver_.begin(data_);
    block_receiver_.start_block(config_.block_size);
    begin_transfer(State::BlockDownloadSubBlock);
    send(message(block_initiate_command(scs::kBlockDownload, true), mux_, config_.block_size));
}

void SdoServer::block_download_segment(MessageBytes bytes) {
    const auto outcome = block_receiver_.on_segment(bytes);
    if (outcome == SdoBlockReceiver::Outcome::InvalidSequence) {
        return abort(AbortCode::InvalidSequenceNumber);
    }
    // The last segment may carry up to 7 bytes that are no data.
    const std::size_t at_least = data_.size() - std::min(data_.size(), kSegmentSize);
    if (const AbortCode code = check_download_progress(at_least, false); code != AbortCode::None) {
        return abort(code);
    }
    watchdog_.kick();
    if (outcome == SdoBlockReceiver::Outcome::BlockEnd) {
        const std::uint8_t acknowledged[] = {block_receiver_.ackseq(), config_.block_size};
        send(
            segment_message(block_command(scs::kBlockDownload, block::kAcknowledge), acknowledged));
        if (block_receiver_.last_received()) {
            state_ = State::BlockDownloadEnd;
        } else {
            block_receiver_.start_block(config_.block_size);
        }
    }
}

void SdoServer::end_block_download(MessageBytes bytes) {
    const std::size_t unused = (bytes[0] >> 2) & 0x07;
    data_.resize(data_.size() - std::min(unused, data_.size()));
    const auto crc = static_cast<std::uint16_t>(bytes[1] | bytes[2] << 8);
    if (client_crc_ && crc != block_crc(data_)) {
        return abort(AbortCode::CrcError);
    }
    if (const AbortCode code = check_download_progress(data_.size(), true);
        code != AbortCode::None) {
        return abort(code);
    }
    finish(); // the value is handed over, as above
    if (const AbortCode code = dictionary_.write(mux_.index, mux_.sub_index, data_);
        code != AbortCode::None) {
        return abort(code);
    }
    send(message(block_command(scs::kBlockDownload, block::kEnd), {}));
}

// CiA 301 7.2.4.3.12 ff.: block upload.

void SdoServer::initiate_block_upload(MessageBytes bytes) {
    const std::uint8_t block_size = bytes[4];
    const std::uint8_t protocol_switch_threshold = bytes[5];
    if (block_size == 0 || block_size > kMaxBlockSize) {
        return abort(AbortCode::InvalidBlockSize);
    }
    if (const AbortCode code = dictionary_.read(mux_.index, mux_.sub_index, data_);
        code != AbortCode::None) {
        return abort(code);
    }
    // A value up to the threshold (0: none) goes by the plain upload protocol instead.
    if (protocol_switch_threshold != 0 && data_.size() <= protocol_switch_threshold) {
        return respond_upload();
    }
    client_crc_ = (bytes[0] & 0x04) != 0;
    upload_block_size_ = block_size;
    begin_transfer(State::BlockUploadStart);
    send(message(block_initiate_command(scs::kBlockUpload, true, true), mux_,
                 static_cast<std::uint32_t>(data_.size())));
}

void SdoServer::acknowledge_block_upload(MessageBytes bytes) {
    const std::uint8_t ackseq = bytes[1];
    const std::uint8_t block_size = bytes[2];
    if (!block_sender_.acknowledge(ackseq)) {
        return abort(AbortCode::InvalidSequenceNumber);
    }
    if (block_size == 0 || block_size > kMaxBlockSize) {
        return abort(AbortCode::InvalidBlockSize);
    }
    watchdog_.kick();
    if (!block_sender_.complete()) {
        return block_sender_.send_block(block_size);
    }
    state_ = State::BlockUploadEnd;
    const std::uint16_t crc = client_crc_ ? block_crc(data_) : 0;
    const std::uint8_t crc_bytes[] = {static_cast<std::uint8_t>(crc),
                                      static_cast<std::uint8_t>(crc >> 8)};
    send(segment_message(
        block_end_command(scs::kBlockUpload, block_sender_.unused_in_last_segment()), crc_bytes));
}

// Shared steps.

AbortCode SdoServer::check_download(std::optional<std::uint32_t> indicated) const {
    // Without a size indicator only existence and access can be checked yet.
    const AbortCode code =
        dictionary_.check_write_size(mux_.index, mux_.sub_index, indicated.value_or(0));
    return !indicated && code == AbortCode::LengthTooLow ? AbortCode::None : code;
}

void SdoServer::begin_download(std::optional<std::uint32_t> indicated) {
    indicated_size_ = indicated;
    data_.clear();
    data_.reserve(std::min<std::size_t>(indicated.value_or(0), kMaxReservation));
}

AbortCode SdoServer::check_download_progress(std::size_t at_least, bool finished) const {
    if (indicated_size_) {
        if (at_least > *indicated_size_) {
            return AbortCode::LengthTooHigh;
        }
        return finished && at_least < *indicated_size_ ? AbortCode::LengthTooLow : AbortCode::None;
    }
    // Without a size indicator, a value that outgrows its object ends before all its data came.
    const AbortCode code = dictionary_.check_write_size(mux_.index, mux_.sub_index, at_least);
    return code == AbortCode::LengthTooHigh ? code : AbortCode::None;
}

void SdoServer::begin_transfer(State state) {
    state_ = state;
    toggle_ = false;
    watchdog_.start(config_.timeout);
}

void SdoServer::send(const Message& message) {
    port_.send(make_frame(response_cob_id_, message));
}

void SdoServer::abort(AbortCode code) {
    end_transfer(code);
    send(abort_message(mux_, code));
}

void SdoServer::end_transfer(AbortCode reason) {
    const bool downloading = state_ == State::DownloadSegments ||
                             state_ == State::BlockDownloadSubBlock ||
                             state_ == State::BlockDownloadEnd;
    finish();
    if (downloading) {
        dictionary_.write_aborted(mux_.index, mux_.sub_index, reason);
    }
}

void SdoServer::finish() {
    state_ = State::Idle;
    watchdog_.stop();
    block_sender_.stop();
}

void add_sdo_server_objects(ObjectDictionary& dictionary, NodeId node) {
    dictionary.add_object(0x1200, "SDO Server Parameter", ObjectCode::Record);
    dictionary.add_sub(0x1200, 1, "COB-ID SDO Client to Server", DataType::Unsigned32,
                       Access::ReadOnly, encode(default_request_cob_id(node)));
    dictionary.add_sub(0x1200, 2, "COB-ID SDO Server to Client", DataType::Unsigned32,
                       Access::ReadOnly, encode(default_response_cob_id(node)));
}

} // namespace eposp::canopen
