#include "service_commands.hpp"

namespace eposp::device {

ServiceCommands::ServiceCommands(core::EventLoop& loop, ServiceParts parts)
    : parts_(std::move(parts)), objects_(parts_), gateway_(loop, parts_) {}

void ServiceCommands::abandon() {
    objects_.abandon();
    gateway_.abandon();
}

void ServiceCommands::execute(const service::Frame& request, Done done) {
    auto decoded = service::decode_request(request);
    if (!decoded.request) {
        return done(service::encode_answer({decoded.error, {}}));
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
                gateway_.send_nmt(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SendCanFrame>) {
                gateway_.send_frame(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::RequestCanFrame>) {
                gateway_.request_frame(command, std::move(answer));
            } else if constexpr (std::is_same_v<T, service::SendLssFrame>) {
                gateway_.send_lss(command, std::move(answer));
            } else {
                static_assert(std::is_same_v<T, service::ReadLssFrame>);
                gateway_.read_lss(command, std::move(answer));
            }
        },
        *decoded.request);
}

} // namespace eposp::device
