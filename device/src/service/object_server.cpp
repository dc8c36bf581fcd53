#include "object_server.hpp"

#include <algorithm>
#include <utility>

namespace eposp::device {
namespace {

using service::Answer;
using service::SegmentControl;

constexpr std::size_t kObjectValueSize = 4; // ReadObject / WriteObject carry 4 bytes

Answer error_answer(std::uint32_t error) {
    return Answer{error, {}};
}
Answer error_answer(canopen::AbortCode abort) {
    return Answer{static_cast<std::uint32_t>(abort), {}};
}

} // namespace

struct ObjectServer::Segmented {
    enum class Direction { Read, Write };
    Direction direction = Direction::Read;
    std::shared_ptr<ObjectAccess> access;
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    canopen::Bytes data;
    std::size_t position = 0;           ///< reads: the next byte to send
    std::uint32_t announced_length = 0; ///< writes: the length the initiate named
    bool toggle = false;                ///< the toggle the next segment must carry
};

ObjectServer::ObjectServer(Resolve resolve, std::uint32_t segmented_expected)
    : resolve_(std::move(resolve)), segmented_expected_(segmented_expected) {}

ObjectServer::~ObjectServer() {
    if (in_flight_) {
        in_flight_->cancel();
    }
}

void ObjectServer::abandon() {
    end_segmented(canopen::AbortCode::GeneralError);
    if (in_flight_) {
        in_flight_->cancel();
    }
}

ObjectAccess* ObjectServer::start(const service::ObjectAddress& address, Done& done) {
    Resolved resolved = resolve_(address);
    if (!resolved.access) {
        done(error_answer(resolved.error));
        return nullptr;
    }
    in_flight_ = std::move(resolved.access);
    return in_flight_.get();
}

void ObjectServer::end_segmented(canopen::AbortCode reason) {
    const auto ended = std::move(segmented_);
    if (ended && ended->direction == Segmented::Direction::Write) {
        ended->access->write_aborted(ended->index, ended->sub_index, reason);
    }
}

void ObjectServer::read(const service::ReadObject& request, Done done) {
    ObjectAccess* access = start(request.object, done);
    if (!access) {
        return;
    }
    access->upload(request.object.index, request.object.sub_index,
                   [this, done = std::move(done)](std::uint32_t error, canopen::Bytes value) {
                       if (error != service::error::kNone) {
                           return done(error_answer(error));
                       }
                       if (value.size() > kObjectValueSize) {
                           return done(error_answer(segmented_expected_));
                       }
                       value.resize(kObjectValueSize, 0);
                       done(Answer{service::error::kNone, std::move(value)});
                   });
}

void ObjectServer::write(const service::WriteObject& request, Done done) {
    ObjectAccess* access = start(request.object, done);
    if (!access) {
        return;
    }
    access->download(request.object.index, request.object.sub_index,
                     canopen::Bytes(request.value.begin(), request.value.end()), false,
                     [done = std::move(done)](std::uint32_t error) { done(error_answer(error)); });
}

void ObjectServer::initiate_read(const service::InitiateSegmentedRead& request, Done done) {
    end_segmented(canopen::AbortCode::CommandSpecifier); // a new transfer ends the one before
    ObjectAccess* access = start(request.object, done);
    if (!access) {
        return;
    }
    auto transfer = std::make_shared<Segmented>();
    transfer->access = in_flight_;
    transfer->index = request.object.index;
    transfer->sub_index = request.object.sub_index;
    access->upload(
        request.object.index, request.object.sub_index,
        [this, transfer, done = std::move(done)](std::uint32_t error, canopen::Bytes value) {
            if (error != service::error::kNone) {
                return done(error_answer(error));
            }
            // The answer names the object's length, as the SDO initiate upload does.
            const auto length = static_cast<std::uint32_t>(value.size());
            transfer->data = std::move(value);
            segmented_ = std::make_unique<Segmented>(std::move(*transfer));
            done(Answer{service::error::kNone, canopen::encode(length)});
        });
}

void ObjectServer::read_segment(const service::SegmentRead& request, Done done) {
    if (!segmented_ || segmented_->direction != Segmented::Direction::Read) {
        return done(error_answer(canopen::AbortCode::CommandSpecifier));
    }
    Segmented& transfer = *segmented_;
    if (request.toggle != transfer.toggle) {
        segmented_.reset();
        return done(error_answer(canopen::AbortCode::ToggleBit));
    }
    const std::size_t length =
        std::min(SegmentControl::kMaxLength, transfer.data.size() - transfer.position);
    const auto first = transfer.data.begin() + static_cast<std::ptrdiff_t>(transfer.position);
    transfer.position += length;
    const bool more = transfer.position < transfer.data.size();
    const SegmentControl control{static_cast<std::uint8_t>(length), transfer.toggle, more};
    Answer answer{service::error::kNone, {control.encode()}};
    answer.data.insert(answer.data.end(), first, first + static_cast<std::ptrdiff_t>(length));
    transfer.toggle = !transfer.toggle;
    if (!more) {
        segmented_.reset();
    }
    done(std::move(answer));
}

void ObjectServer::initiate_write(const service::InitiateSegmentedWrite& request, Done done) {
    end_segmented(canopen::AbortCode::CommandSpecifier);
    ObjectAccess* access = start(request.object, done);
    if (!access) {
        return;
    }
    const auto& object = request.object;
    // What the object cannot take is refused at once, as an SDO server does at an initiate.
    const canopen::AbortCode refused =
        access->check_write_size(object.index, object.sub_index, request.length);
    if (refused != canopen::AbortCode::None) {
        return done(error_answer(refused));
    }
    segmented_ = std::make_unique<Segmented>();
    segmented_->direction = Segmented::Direction::Write;
    segmented_->access = in_flight_;
    segmented_->index = object.index;
    segmented_->sub_index = object.sub_index;
    segmented_->announced_length = request.length;
    done(error_answer(service::error::kNone));
}

void ObjectServer::write_segment(const service::SegmentWrite& request, Done done) {
    if (!segmented_ || segmented_->direction != Segmented::Direction::Write) {
        return done(error_answer(canopen::AbortCode::CommandSpecifier));
    }
    Segmented& transfer = *segmented_;
    if (request.control.toggle != transfer.toggle) {
        end_segmented(canopen::AbortCode::ToggleBit);
        return done(error_answer(canopen::AbortCode::ToggleBit));
    }
    if (transfer.data.size() + request.data.size() > transfer.announced_length) {
        end_segmented(canopen::AbortCode::LengthTooHigh);
        return done(error_answer(canopen::AbortCode::LengthTooHigh));
    }
    transfer.data.insert(transfer.data.end(), request.data.begin(), request.data.end());
    const SegmentControl written{request.control.length, transfer.toggle, false};
    const Answer confirmation{service::error::kNone, {written.encode()}};
    transfer.toggle = !transfer.toggle;
    if (request.control.more) {
        return done(confirmation);
    }
    if (transfer.data.size() < transfer.announced_length) {
        end_segmented(canopen::AbortCode::LengthTooLow);
        return done(error_answer(canopen::AbortCode::LengthTooLow));
    }
    const auto finished = std::move(segmented_);
    in_flight_ = finished->access;
    finished->access->download(finished->index, finished->sub_index, std::move(finished->data),
                               true, [done = std::move(done), confirmation](std::uint32_t error) {
                                   done(error == service::error::kNone ? confirmation
                                                                       : error_answer(error));
                               });
}

} // namespace eposp::device
