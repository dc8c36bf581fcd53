#pragma once

#include "eposp/can/io/socketcand_server.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/result.hpp"
#include "eposp/core/time.hpp"

#include <memory>
#include <string>

namespace eposp::device {

/// Serves `bus` over socketcand on `address` the way every long-running command does: prints
/// "socketcand: listening on ADDRESS (bus NAME)" and each client joining (once it has opened
/// the bus), leaving or dropped on stdout (scripts wait for the first line). `epoch_offset` as
/// SocketcandServerConfig says.
core::Result<std::unique_ptr<can::io::SocketcandServer>>
serve_socketcand(can::VirtualBus& bus, const std::string& address, core::Duration epoch_offset,
                 const can::io::SocketcandLimits& limits = {});

} // namespace eposp::device
