#include "object_transfer.hpp"

#include "../network_port.hpp"

#include <algorithm>
#include <utility>

namespace eposp::device {
namespace {

using service::Answer;
using service::SegmentControl;

constexpr std::size_t kObjectValueSize = 4; // ReadObject / WriteObject carry 4 bytes

std::uint32_t code(canopen::AbortCode abort) {
    return static_cast<std::uint32_t>(abort);
}

Answer error_answer(std::uint32_t error) {
    return Answer{error, {}};
}
Answer error_answer(canopen::AbortCode abort) {
    return Answer{code(abort), {}};
}

// How many of a WriteObject's 4 bytes the controller's object takes: its type's size, or all 4
// for a string or DOMAIN (the SDO server does the same with an expedited write without size).
std::size_t expedited_size(const canopen::ObjectDictionary& od, std::uint16_t index,
                           std::uint8_t sub_index) {
    const canopen::SubObject* entry = od.find(index, sub_index);
    const auto fixed = entry ? canopen::fixed_size(entry->type) : std::nullopt;
    return fixed && *fixed <= kObjectValueSize ? *fixed : kObjectValueSize;
}

} // namespace

struct ObjectTransfer::Segmented {
    enum class Direction { Read, Write };
    Direction direction = Direction::Read;
    ServiceTarget target;
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    canopen::Bytes data;
    std::size_t position = 0;           ///< reads: the next byte to send
    std::uint32_t announced_length = 0; ///< writes: the length the initiate named
    bool toggle = false;                ///< the toggle the next segment must carry
};

ObjectTransfer::ObjectTransfer(const ServiceParts& parts) : parts_(parts) {}

ObjectTransfer::~ObjectTransfer() {
    *alive_ = false;
    cancel_gateway_request();
}

void ObjectTransfer::abandon() {
    end_segmented(canopen::AbortCode::GeneralError);
    cancel_gateway_request();
}

void ObjectTransfer::end_segmented(canopen::AbortCode reason) {
    const auto ended = std::move(segmented_);
    // A write to the controller's own object ends unfinished: the object is told (a download
    // to 0x1F50 reports the interruption); a node's value was only ever in this buffer.
    if (ended && ended->direction == Segmented::Direction::Write && !ended->target.port) {
        parts_.objects.write_aborted(ended->index, ended->sub_index, reason);
    }
}

void ObjectTransfer::cancel_gateway_request() {
    if (gateway_port_ && gateway_request_) {
        const auto request = std::exchange(gateway_request_, {});
        // Its callback runs and is told to do nothing more.
        const auto alive = std::exchange(alive_, std::make_shared<bool>(true));
        *alive = false;
        gateway_port_->sdo().cancel(request);
    }
    gateway_port_ = nullptr;
}

void ObjectTransfer::upload(const ServiceTarget& target, std::uint16_t index,
                            std::uint8_t sub_index, Uploaded done) {
    if (!target.port) {
        canopen::Bytes value;
        const canopen::AbortCode abort = parts_.objects.read(index, sub_index, value);
        return done(code(abort), std::move(value));
    }
    gateway_port_ = target.port;
    gateway_request_ =
        target.port->sdo().upload(target.node, index, sub_index,
                                  [this, alive = alive_, done = std::move(done)](
                                      canopen::AbortCode abort, canopen::Bytes value) {
                                      if (*alive) {
                                          gateway_request_ = {};
                                          done(code(abort), std::move(value));
                                      }
                                  });
}

void ObjectTransfer::download(const ServiceTarget& target, std::uint16_t index,
                              std::uint8_t sub_index, canopen::Bytes value, bool sized,
                              Downloaded done) {
    if (!target.port) {
        return done(code(parts_.objects.write(index, sub_index, value)));
    }
    gateway_port_ = target.port;
    gateway_request_ = target.port->sdo().download(
        target.node, index, sub_index, std::move(value),
        [this, alive = alive_, done = std::move(done)](canopen::AbortCode abort) {
            if (*alive) {
                gateway_request_ = {};
                done(code(abort));
            }
        },
        {.size_indicated = sized});
}

void ObjectTransfer::read(const service::ReadObject& request, Done done) {
    const auto resolved = resolve_object_target(parts_, request.object);
    if (!resolved.target) {
        return done(error_answer(resolved.error));
    }
    upload(*resolved.target, request.object.index, request.object.sub_index,
           [done = std::move(done)](std::uint32_t error, canopen::Bytes value) {
               if (error != service::error::kNone) {
                   return done(error_answer(error));
               }
               // A longer value needs a segmented read.
               if (value.size() > kObjectValueSize) {
                   return done(error_answer(canopen::AbortCode::LengthTooHigh));
               }
               value.resize(kObjectValueSize, 0);
               done(Answer{service::error::kNone, std::move(value)});
           });
}

void ObjectTransfer::write(const service::WriteObject& request, Done done) {
    const auto resolved = resolve_object_target(parts_, request.object);
    if (!resolved.target) {
        return done(error_answer(resolved.error));
    }
    const auto& object = request.object;
    const std::size_t size = resolved.target->port
                                 ? kObjectValueSize
                                 : expedited_size(parts_.objects, object.index, object.sub_index);
    canopen::Bytes value(request.value.begin(), request.value.begin() + size);
    // Through the gateway the 4 bytes go without a size: the node's object decides how many it
    // takes, as it would from the device itself.
    download(*resolved.target, object.index, object.sub_index, std::move(value), false,
             [done = std::move(done)](std::uint32_t error) { done(error_answer(error)); });
}

void ObjectTransfer::initiate_read(const service::InitiateSegmentedRead& request, Done done) {
    end_segmented(canopen::AbortCode::CommandSpecifier); // a new transfer ends the one before
    const auto resolved = resolve_object_target(parts_, request.object);
    if (!resolved.target) {
        return done(error_answer(resolved.error));
    }
    auto transfer = std::make_unique<Segmented>();
    transfer->target = *resolved.target;
    transfer->index = request.object.index;
    transfer->sub_index = request.object.sub_index;
    upload(*resolved.target, request.object.index, request.object.sub_index,
           [this, transfer = std::shared_ptr<Segmented>(std::move(transfer)),
            done = std::move(done)](std::uint32_t error, canopen::Bytes value) {
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

void ObjectTransfer::read_segment(const service::SegmentRead& request, Done done) {
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

void ObjectTransfer::initiate_write(const service::InitiateSegmentedWrite& request, Done done) {
    end_segmented(canopen::AbortCode::CommandSpecifier);
    const auto resolved = resolve_object_target(parts_, request.object);
    if (!resolved.target) {
        return done(error_answer(resolved.error));
    }
    const auto& object = request.object;
    // The controller refuses what its object cannot take at once, as its SDO server does at an
    // initiate; a node's answer comes with the last segment.
    const canopen::AbortCode refused =
        resolved.target->port
            ? (request.length > kMaxGatewayValue ? canopen::AbortCode::OutOfMemory
                                                 : canopen::AbortCode::None)
            : parts_.objects.check_write_size(object.index, object.sub_index, request.length);
    if (refused != canopen::AbortCode::None) {
        return done(error_answer(refused));
    }
    segmented_ = std::make_unique<Segmented>();
    segmented_->direction = Segmented::Direction::Write;
    segmented_->target = *resolved.target;
    segmented_->index = object.index;
    segmented_->sub_index = object.sub_index;
    segmented_->announced_length = request.length;
    done(error_answer(service::error::kNone));
}

void ObjectTransfer::write_segment(const service::SegmentWrite& request, Done done) {
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
    download(finished->target, finished->index, finished->sub_index, std::move(finished->data),
             true, [done = std::move(done), confirmation](std::uint32_t error) {
                 done(error == service::error::kNone ? confirmation : error_answer(error));
             });
}

} // namespace eposp::device
