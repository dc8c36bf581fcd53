#include "eposp/device/socketcand_hosting.hpp"

#include <cstdio>
#include <fmt/format.h>

namespace eposp::device {

core::Result<std::unique_ptr<can::io::SocketcandServer>>
serve_socketcand(can::VirtualBus& bus, const std::string& address, core::Duration epoch_offset,
                 const can::io::SocketcandLimits& limits) {
    auto server = can::io::SocketcandServer::open(
        bus, {.listen = address, .epoch_offset = epoch_offset, .limits = limits});
    if (!server) {
        return server;
    }
    (*server)->on_client_event([](const can::io::SocketcandClientEvent& event) {
        using Kind = can::io::SocketcandClientEvent::Kind;
        switch (event.kind) {
        case Kind::Joined:
            fmt::print("socketcand: {} joined from {}\n", event.client, event.remote);
            break;
        case Kind::Left:
            fmt::print("socketcand: {} left ({})\n", event.client, event.reason);
            break;
        case Kind::Dropped:
            fmt::print("socketcand: connection from {} dropped ({})\n", event.remote, event.reason);
            break;
        }
        std::fflush(stdout);
    });
    fmt::print("socketcand: listening on {} (bus {})\n", (*server)->address(), bus.config().name);
    return server;
}

} // namespace eposp::device
