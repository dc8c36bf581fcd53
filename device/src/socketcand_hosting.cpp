#include "eposp/device/socketcand_hosting.hpp"

#include <cstdio>
#include <fmt/format.h>

namespace eposp::device {

core::Result<std::unique_ptr<can::io::SocketcandServer>>
serve_socketcand(can::VirtualBus& bus, const std::string& address, core::Duration epoch_offset) {
    auto server =
        can::io::SocketcandServer::open(bus, {.listen = address, .epoch_offset = epoch_offset});
    if (!server) {
        return server;
    }
    (*server)->on_client_event([](const can::io::SocketcandClientEvent& event) {
        if (event.kind == can::io::SocketcandClientEvent::Kind::Connected) {
            fmt::print("socketcand: {} joined from {}\n", event.client, event.remote);
        } else {
            fmt::print("socketcand: {} left ({})\n", event.client, event.reason);
        }
        std::fflush(stdout);
    });
    fmt::print("socketcand: listening on {} (bus {})\n", (*server)->address(), bus.config().name);
    return server;
}

} // namespace eposp::device
