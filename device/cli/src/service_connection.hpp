#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/client.hpp"

#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device::cli {

/// The options every service client takes: `--port PATH|tcp:ADDR`, `--protocol v1|v2`,
/// `--baud N`.
struct ServiceClientOptions {
    std::string port;
    service::Protocol protocol = service::Protocol::V1;
    std::uint32_t baud = 115200;
};
void add_service_client_options(CLI::App& command, ServiceClientOptions& options);

/// `--node N` and `--network N`: which node a request addresses (docs/service-interface.md).
struct ObjectTargetOptions {
    unsigned node = 0;
    std::optional<unsigned> network;
};
void add_object_target_options(CLI::App& command, ObjectTargetOptions& options);
service::ObjectAddress object_address(const ObjectTargetOptions& target, std::uint16_t index,
                                      std::uint8_t sub_index);

/// A service client on its link, run in real time, one operation after the other: each call
/// runs the loop until the operation completed (the client's own timeouts bound it) or SIGINT /
/// SIGTERM arrived (interrupted() then, and the result is an error saying so; every later call
/// fails at once).
class ServiceConnection {
public:
    using Bytes = std::vector<std::uint8_t>;

    /// Opens the link `--port` names; the error says why not.
    static core::Result<std::unique_ptr<ServiceConnection>>
    open(const ServiceClientOptions& options);
    ~ServiceConnection();

    core::EventLoop& loop() { return loop_; }
    bool interrupted() const { return interrupted_; }

    service::ClientResult<std::array<std::uint8_t, 4>>
    read_object(const service::ObjectAddress& object);
    service::ClientResult<service::Done> write_object(const service::ObjectAddress& object,
                                                      std::array<std::uint8_t, 4> value);
    service::ClientResult<Bytes> read_segmented(const service::ObjectAddress& object);
    service::ClientResult<service::Done> write_segmented(const service::ObjectAddress& object,
                                                         Bytes value,
                                                         service::Client::Progress progress = {});
    /// Waits `delay`, or less when interrupted; false then.
    bool pause(core::Duration delay);

private:
    ServiceConnection() = default;

    template <typename T>
    service::ClientResult<T> wait(const std::function<void(service::Client::Callback<T>)>& start);

    struct SignalWatch;

    core::EventLoop loop_{core::Pace::RealTime};
    /// SIGINT / SIGTERM caught for the connection's whole life, so that none ends the process
    /// between two requests.
    std::unique_ptr<SignalWatch> signals_;
    std::unique_ptr<service::Link> link_;
    std::optional<service::Client> client_;
    bool interrupted_ = false;
};

} // namespace eposp::device::cli
