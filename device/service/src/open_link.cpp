#include "eposp/service/open_link.hpp"

#include "eposp/service/device_path_link.hpp"
#include "eposp/service/pty_link.hpp"
#include "eposp/service/tcp_client_link.hpp"
#include "eposp/service/tcp_server_link.hpp"

#include <fmt/format.h>

namespace eposp::service {
namespace {

core::Result<ServingLink> paced(core::EventLoop& loop, std::unique_ptr<Link> line,
                                std::string where, const LinkPacing& pacing) {
    auto link = PacedLink::wrap(loop, std::move(line), pacing);
    if (!link) {
        return core::Error{link.error()};
    }
    return ServingLink{std::move(*link), std::move(where)};
}

} // namespace

core::Result<ServingLink> open_serving_link(core::EventLoop& loop, const LinkOption& option,
                                            const ServingLinkSettings& settings) {
    if (!settings.symlink.empty() && option.kind != LinkOption::Kind::Pty) {
        return core::Error{fmt::format("a symlink ({}) can only name a pseudo-terminal (pty)",
                                       settings.symlink.string())};
    }
    switch (option.kind) {
    case LinkOption::Kind::Pty: {
        auto pty = PtyLink::open(loop, {settings.symlink, settings.max_unsent_bytes});
        if (!pty) {
            return core::Error{pty.error()};
        }
        std::string where = (*pty)->slave_path();
        return paced(loop, std::move(*pty), std::move(where), settings.pacing);
    }
    case LinkOption::Kind::DevicePath: {
        auto device =
            DevicePathLink::open(loop, option.target, {settings.baud, settings.max_unsent_bytes});
        if (!device) {
            return core::Error{device.error()};
        }
        return paced(loop, std::move(*device), option.target, settings.pacing);
    }
    case LinkOption::Kind::Tcp: {
        auto server = TcpServerLink::open(loop, option.target, {settings.max_unsent_bytes});
        if (!server) {
            return core::Error{server.error()};
        }
        std::string where = (*server)->address();
        return paced(loop, std::move(*server), std::move(where), settings.pacing);
    }
    }
    return core::Error{"unknown kind of link"};
}

core::Result<std::unique_ptr<Link>> open_client_link(core::EventLoop& loop,
                                                     const LinkOption& option, std::uint32_t baud) {
    switch (option.kind) {
    case LinkOption::Kind::Pty:
        return core::Error{"a client cannot open a new pseudo-terminal: give the path that "
                           "`eposp serve` printed (or its symlink), a serial device or tcp:ADDR"};
    case LinkOption::Kind::DevicePath: {
        auto device = DevicePathLink::open(loop, option.target, {.baud = baud});
        if (!device) {
            return core::Error{device.error()};
        }
        return std::unique_ptr<Link>(std::move(*device));
    }
    case LinkOption::Kind::Tcp: {
        auto client = TcpClientLink::open(loop, option.target);
        if (!client) {
            return core::Error{client.error()};
        }
        return std::unique_ptr<Link>(std::move(*client));
    }
    }
    return core::Error{"unknown kind of link"};
}

} // namespace eposp::service
