#include "service_commands.hpp"

#include "service_target.hpp"

namespace eposp::device {
namespace {

// The object commands of the plain opcodes, which every device serves.
bool is_plain_object_command(std::uint8_t opcode) {
    return opcode >= static_cast<std::uint8_t>(service::OpCode::ReadObject) &&
           opcode <= static_cast<std::uint8_t>(service::OpCode::SegmentWrite);
}

} // namespace

ServiceCommands::ServiceCommands(core::EventLoop& loop, ServiceParts parts)
    : parts_(std::move(parts)), objects_(
                                    [this](const service::ObjectAddress& address) {
                                        return resolve_object_target(parts_, address);
                                    },
                                    parts_.dialect.segmented_expected) {
    if (parts_.network_port) {
        gateway_.emplace(loop, parts_);
    }
}

void ServiceCommands::abandon() {
    objects_.abandon();
    if (gateway_) {
        gateway_->abandon();
    }
}

void ServiceCommands::execute(const service::Frame& request, Done done) {
    const auto refuse = [&done](std::uint32_t error) {
        done(service::encode_answer({error, {}}));
    };
    if (!gateway_ && !is_plain_object_command(request.opcode)) {
        return refuse(parts_.dialect.unknown_command);
    }
    auto decoded = service::decode_request(request);
    if (!decoded.request) {
        return refuse(decoded.error == service::error::kIllegalCommand
                          ? parts_.dialect.unknown_command
                          : decoded.error);
    }
    auto answer = [done = std::move(done)](service::Answer result) {
        done(service::encode_answer(result));
    };
    std::visit(
        [this, &answer](const auto& command) {
            using T = std::decay_t<decltype(command)>;
            if constexpr (std::is_same_v<T, service::ReadObject>) {
                objects_.read(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::WriteObject>) {
                objects_.write(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::InitiateSegmentedRead>) {
                objects_.initiate_read(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::InitiateSegmentedWrite>) {
                objects_.initiate_write(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SegmentRead>) {
                objects_.read_segment(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SegmentWrite>) {
                objects_.write_segment(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SendNmtService>) {
                gateway_->send_nmt(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SendCanFrame>) {
                gateway_->send_frame(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::RequestCanFrame>) {
                gateway_->request_frame(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SendLssFrame>) {
                gateway_->send_lss(command, std::move(answer));
            } else {
                static_assert(std::is_same_v<T, service::ReadLssFrame>);
                gateway_->read_lss(command, std::move(answer));
            }
        },
        *decoded.request);
}

} // namespace eposp::device
