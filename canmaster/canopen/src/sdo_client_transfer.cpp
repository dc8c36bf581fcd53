#include "sdo_client_transfer.hpp"

#include "eposp/canopen/cob_id.hpp"

#include <algorithm>

namespace eposp::canopen {

using namespace sdo;

namespace {

// Upfront reservation for an upload with a size indicator; a larger value grows as it arrives.
constexpr std::size_t kMaxReservation = 64 * 1024;

bool valid_block_size(std::uint8_t block_size) {
    return block_size != 0 && block_size <= kMaxBlockSize;
}

} // namespace

SdoClientTransfer::SdoClientTransfer(core::EventLoop& loop, can::Port& port,
                                     SdoTransmitQueue& queue, const SdoClientConfig& config,
                                     Done done)
    : queue_(queue), config_(config), done_(std::move(done)),
      watchdog_(loop, [this] { abort(AbortCode::SdoTimeout); }),
      block_sender_(loop, port, config.retry_delay) {}

void SdoClientTransfer::begin(std::uint32_t request_cob_id, Multiplexer mux,
                              const SdoRequestOptions& options, State state) {
    request_cob_id_ = request_cob_id;
    mux_ = mux;
    options_ = options;
    state_ = state;
    toggle_ = false;
    indicated_size_.reset();
    offset_ = 0;
    watchdog_.start(options.timeout.value_or(config_.timeout));
}

void SdoClientTransfer::start_upload(std::uint32_t request_cob_id, Multiplexer mux,
                                     const SdoRequestOptions& options) {
    data_.clear();
    if (options.protocol == SdoProtocol::Block) {
        begin(request_cob_id, mux, options, State::BlockUploadInitiate);
        const auto block_size = std::clamp<std::uint8_t>(config_.block_size, 1, kMaxBlockSize);
        const auto sizes = static_cast<std::uint32_t>(block_size) |
                           static_cast<std::uint32_t>(options.protocol_switch_threshold) << 8;
        return send(message(block_initiate_command(ccs::kBlockUpload, true), mux, sizes));
    }
    begin(request_cob_id, mux, options, State::InitiateUpload);
    send(message(static_cast<std::uint8_t>(ccs::kInitiateUpload << 5), mux));
}

void SdoClientTransfer::start_download(std::uint32_t request_cob_id, Multiplexer mux, Bytes value,
                                       const SdoRequestOptions& options) {
    data_ = std::move(value);
    const auto size = static_cast<std::uint32_t>(data_.size());
    expedited_ = !data_.empty() && data_.size() <= kExpeditedSize;
    if (expedited_) {
        begin(request_cob_id, mux, options, State::InitiateDownload);
        const bool sized = options.size_indicated || size != kExpeditedSize;
        Message request = message(
            initiate_command(ccs::kInitiateDownload, kExpeditedSize - size, true, sized), mux);
        std::copy(data_.begin(), data_.end(), request.begin() + 4);
        return send(request);
    }
    if (options.protocol == SdoProtocol::Block) {
        begin(request_cob_id, mux, options, State::BlockDownloadInitiate);
        return send(message(block_initiate_command(ccs::kBlockDownload, true, true), mux, size));
    }
    begin(request_cob_id, mux, options, State::InitiateDownload);
    send(message(initiate_command(ccs::kInitiateDownload, 0, false, true), mux, size));
}

void SdoClientTransfer::on_message(MessageBytes bytes) {
    if (state_ == State::Idle) {
        return;
    }
    // CiA 301 7.2.4.3.17: the server aborted; not answered. A code of 0 would read as success.
    const bool in_sub_block = state_ == State::BlockUploadSubBlock;
    if (in_sub_block ? bytes[0] == kAbortCommand : command_specifier(bytes[0]) == kAbort) {
        const auto code = static_cast<AbortCode>(value_of(bytes));
        if (code == AbortCode::CommandSpecifier && initiating_block_transfer()) {
            return retry_segmented();
        }
        return end(code == AbortCode::None ? AbortCode::GeneralError : code);
    }
    if (const AbortCode code = handle(bytes); code != AbortCode::None) {
        abort(code);
    }
}

bool SdoClientTransfer::initiating_block_transfer() const {
    return state_ == State::BlockDownloadInitiate || state_ == State::BlockUploadInitiate;
}

// CiA 301 7.2.4.3.9 / 7.2.4.3.13: a server without block transfer refuses its initiate with
// 0x05040001; the value then travels by the segmented protocol every server supports.
void SdoClientTransfer::retry_segmented() {
    options_.protocol = SdoProtocol::Segmented;
    const SdoRequestOptions options = options_;
    if (state_ == State::BlockUploadInitiate) {
        start_upload(request_cob_id_, mux_, options);
    } else {
        start_download(request_cob_id_, mux_, std::move(data_), options);
    }
}

AbortCode SdoClientTransfer::handle(MessageBytes bytes) {
    switch (state_) {
    case State::InitiateDownload:
        return initiate_download_response(bytes);
    case State::DownloadSegment:
        return download_segment_response(bytes);
    case State::InitiateUpload:
        return initiate_upload_response(bytes);
    case State::UploadSegment:
        return upload_segment(bytes);
    case State::BlockDownloadInitiate:
        return block_download_initiate_response(bytes);
    case State::BlockDownloadSubBlock:
        return block_download_acknowledge(bytes);
    case State::BlockDownloadEnd:
        if (command_specifier(bytes[0]) != scs::kBlockDownload ||
            block_subcommand(bytes[0]) != block::kEnd) {
            return AbortCode::CommandSpecifier;
        }
        end(AbortCode::None);
        return AbortCode::None;
    case State::BlockUploadInitiate:
        return block_upload_initiate_response(bytes);
    case State::BlockUploadSubBlock:
        return block_upload_segment(bytes);
    case State::BlockUploadEnd:
        return block_upload_end(bytes);
    case State::Idle:
        break;
    }
    return AbortCode::None;
}

// CiA 301 7.2.4.3.2 ff.: download, expedited or segmented.

AbortCode SdoClientTransfer::initiate_download_response(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kInitiateDownload) {
        return AbortCode::CommandSpecifier;
    }
    if (const AbortCode code = check_multiplexer(bytes); code != AbortCode::None) {
        return code;
    }
    if (expedited_) {
        end(AbortCode::None);
    } else {
        send_download_segment();
    }
    return AbortCode::None;
}

void SdoClientTransfer::send_download_segment() {
    const std::size_t size = std::min(kSegmentSize, data_.size() - offset_);
    const auto chunk = std::span<const std::uint8_t>(data_).subspan(offset_, size);
    offset_ += size;
    state_ = State::DownloadSegment;
    watchdog_.kick();
    send(segment_message(segment_command(ccs::kDownloadSegment, toggle_, kSegmentSize - size,
                                         offset_ == data_.size()),
                         chunk));
}

AbortCode SdoClientTransfer::download_segment_response(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kDownloadSegment) {
        return AbortCode::CommandSpecifier;
    }
    if (toggle_of(bytes[0]) != toggle_) {
        return AbortCode::ToggleBit;
    }
    if (offset_ == data_.size()) {
        end(AbortCode::None);
        return AbortCode::None;
    }
    toggle_ = !toggle_;
    send_download_segment();
    return AbortCode::None;
}

// CiA 301 7.2.4.3.5 ff.: upload, expedited or segmented.

AbortCode SdoClientTransfer::initiate_upload_response(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kInitiateUpload) {
        return AbortCode::CommandSpecifier;
    }
    if (const AbortCode code = check_multiplexer(bytes); code != AbortCode::None) {
        return code;
    }
    const bool size_indicated = (bytes[0] & 0x01) != 0;
    if ((bytes[0] & 0x02) != 0) { // expedited; without a size, all 4 bytes
        const std::size_t unused = size_indicated ? (bytes[0] >> 2) & 0x03 : 0;
        data_.assign(bytes.begin() + 4, bytes.end() - static_cast<std::ptrdiff_t>(unused));
        end(AbortCode::None);
        return AbortCode::None;
    }
    if (size_indicated) {
        indicated_size_ = value_of(bytes);
        if (*indicated_size_ > config_.max_upload_size) {
            return AbortCode::OutOfMemory;
        }
        data_.reserve(std::min<std::size_t>(*indicated_size_, kMaxReservation));
    }
    state_ = State::UploadSegment;
    watchdog_.kick();
    send(message(segment_command(ccs::kUploadSegment, toggle_), {}));
    return AbortCode::None;
}

AbortCode SdoClientTransfer::upload_segment(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kUploadSegment) {
        return AbortCode::CommandSpecifier;
    }
    if (toggle_of(bytes[0]) != toggle_) {
        return AbortCode::ToggleBit;
    }
    const std::size_t unused = (bytes[0] >> 1) & 0x07;
    const bool last = (bytes[0] & 0x01) != 0;
    data_.insert(data_.end(), bytes.begin() + 1, bytes.end() - static_cast<std::ptrdiff_t>(unused));
    if (const AbortCode code = check_size(last); code != AbortCode::None) {
        return code;
    }
    if (data_.size() > config_.max_upload_size) {
        return AbortCode::OutOfMemory;
    }
    if (last) {
        end(AbortCode::None);
        return AbortCode::None;
    }
    toggle_ = !toggle_;
    watchdog_.kick();
    send(message(segment_command(ccs::kUploadSegment, toggle_), {}));
    return AbortCode::None;
}

// CiA 301 7.2.4.3.8 ff.: block download.

AbortCode SdoClientTransfer::block_download_initiate_response(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kBlockDownload ||
        block_subcommand(bytes[0]) != block::kInitiate) {
        return AbortCode::CommandSpecifier;
    }
    if (const AbortCode code = check_multiplexer(bytes); code != AbortCode::None) {
        return code;
    }
    const std::uint8_t block_size = bytes[4];
    if (!valid_block_size(block_size)) {
        return AbortCode::InvalidBlockSize;
    }
    server_crc_ = (bytes[0] & 0x04) != 0;
    state_ = State::BlockDownloadSubBlock;
    watchdog_.kick();
    block_sender_.begin(request_cob_id_, data_);
    block_sender_.send_block(block_size);
    return AbortCode::None;
}

AbortCode SdoClientTransfer::block_download_acknowledge(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kBlockDownload ||
        block_subcommand(bytes[0]) != block::kAcknowledge) {
        return AbortCode::CommandSpecifier;
    }
    if (!block_sender_.acknowledge(bytes[1])) {
        return AbortCode::InvalidSequenceNumber;
    }
    if (!valid_block_size(bytes[2])) {
        return AbortCode::InvalidBlockSize;
    }
    watchdog_.kick();
    if (!block_sender_.complete()) {
        block_sender_.send_block(bytes[2]);
        return AbortCode::None;
    }
    state_ = State::BlockDownloadEnd;
    const std::uint16_t crc = server_crc_ ? block_crc(data_) : 0;
    const std::uint8_t crc_bytes[] = {static_cast<std::uint8_t>(crc),
                                      static_cast<std::uint8_t>(crc >> 8)};
    send(segment_message(
        block_end_command(ccs::kBlockDownload, block_sender_.unused_in_last_segment()), crc_bytes));
    return AbortCode::None;
}

// CiA 301 7.2.4.3.12 ff.: block upload.

AbortCode SdoClientTransfer::block_upload_initiate_response(MessageBytes bytes) {
    // The protocol switch: a value up to the threshold comes as a plain upload.
    if (command_specifier(bytes[0]) == scs::kInitiateUpload &&
        options_.protocol_switch_threshold != 0) {
        return initiate_upload_response(bytes);
    }
    if (command_specifier(bytes[0]) != scs::kBlockUpload ||
        block_subcommand(bytes[0]) != block::kInitiate) {
        return AbortCode::CommandSpecifier;
    }
    if (const AbortCode code = check_multiplexer(bytes); code != AbortCode::None) {
        return code;
    }
    if ((bytes[0] & 0x02) != 0) {
        indicated_size_ = value_of(bytes);
        if (*indicated_size_ > config_.max_upload_size) {
            return AbortCode::OutOfMemory;
        }
        data_.reserve(std::min<std::size_t>(*indicated_size_, kMaxReservation));
    }
    server_crc_ = (bytes[0] & 0x04) != 0;
    block_receiver_.begin(data_);
    block_receiver_.start_block(config_.block_size);
    state_ = State::BlockUploadSubBlock;
    watchdog_.kick();
    send(message(block_command(ccs::kBlockUpload, block::kStartUpload), {}));
    return AbortCode::None;
}

AbortCode SdoClientTransfer::block_upload_segment(MessageBytes bytes) {
    const auto outcome = block_receiver_.on_segment(bytes);
    if (outcome == SdoBlockReceiver::Outcome::InvalidSequence) {
        return AbortCode::InvalidSequenceNumber;
    }
    if (data_.size() > config_.max_upload_size) {
        return AbortCode::OutOfMemory;
    }
    watchdog_.kick();
    if (outcome == SdoBlockReceiver::Outcome::BlockEnd) {
        const std::uint8_t acknowledged[] = {block_receiver_.ackseq(),
                                             block_receiver_.block_size()};
        send(segment_message(block_command(ccs::kBlockUpload, block::kAcknowledge), acknowledged));
        if (block_receiver_.last_received()) {
            state_ = State::BlockUploadEnd;
        } else {
            block_receiver_.start_block(block_receiver_.block_size());
        }
    }
    return AbortCode::None;
}

AbortCode SdoClientTransfer::block_upload_end(MessageBytes bytes) {
    if (command_specifier(bytes[0]) != scs::kBlockUpload ||
        block_subcommand(bytes[0]) != block::kEnd) {
        return AbortCode::CommandSpecifier;
    }
    const std::size_t unused = (bytes[0] >> 2) & 0x07;
    data_.resize(data_.size() - std::min(unused, data_.size()));
    const auto crc = static_cast<std::uint16_t>(bytes[1] | bytes[2] << 8);
    if (server_crc_ && crc != block_crc(data_)) {
        return AbortCode::CrcError;
    }
    if (const AbortCode code = check_size(true); code != AbortCode::None) {
        return code;
    }
    send(message(block_command(ccs::kBlockUpload, block::kEnd), {}));
    end(AbortCode::None);
    return AbortCode::None;
}

// Shared steps.

AbortCode SdoClientTransfer::check_multiplexer(MessageBytes bytes) const {
    // CiA 301 names no code for a response about another object; like lely-core, the client
    // reports a general error.
    return multiplexer_of(bytes) == mux_ ? AbortCode::None : AbortCode::GeneralError;
}

AbortCode SdoClientTransfer::check_size(bool finished) const {
    if (!indicated_size_) {
        return AbortCode::None;
    }
    if (data_.size() > *indicated_size_) {
        return AbortCode::LengthTooHigh;
    }
    return finished && data_.size() < *indicated_size_ ? AbortCode::LengthTooLow : AbortCode::None;
}

void SdoClientTransfer::send(const Message& message) {
    queue_.send(make_frame(request_cob_id_, message));
}

void SdoClientTransfer::abort(AbortCode code) {
    if (state_ == State::Idle) {
        return;
    }
    send(abort_message(mux_, code));
    end(code);
}

void SdoClientTransfer::end(AbortCode code) {
    state_ = State::Idle;
    watchdog_.stop();
    block_sender_.stop();
    done_(code);
}

} // namespace eposp::canopen
