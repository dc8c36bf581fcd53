#include "service_connection.hpp"

#include "eposp/service/link_option.hpp"
#include "eposp/service/open_link.hpp"
#include "eposp/service/paced_link.hpp"
#include "options.hpp"

#include <boost/asio/signal_set.hpp>
#include <csignal>
#include <fmt/format.h>

namespace eposp::device::cli {

void add_service_client_options(CLI::App& command, ServiceClientOptions& options) {
    command
        .add_option("--port", options.port,
                    "The device's service port: a serial device PATH (e.g. the pty `eposp "
                    "serve` printed) or tcp:ADDR")
        ->required();
    command
        .add_option_function<std::string>(
            "--protocol",
            [&options](const std::string& name) {
                options.protocol = name == "v2" ? service::Protocol::V2 : service::Protocol::V1;
            },
            "maxon serial v1 (RS-232, the default) or v2 (USB)")
        ->check(CLI::IsMember({"v1", "v2"}));
    command.add_option("--baud", options.baud, "The line rate of a serial device, bit/s")
        ->capture_default_str()
        ->check(CLI::Range(1200U, 4'000'000U));
}

void add_object_target_options(CLI::App& command, ObjectTargetOptions& options) {
    command
        .add_option("--node", options.node,
                    "The node: 0 the EPOS P itself, others a node on its CAN port (gateway)")
        ->capture_default_str()
        ->check(whole_number_in(0, 127));
    command
        .add_option("--network", options.network,
                    "Use the network-addressed commands (v2): 0 the EPOS P, 1 its internal port, "
                    "2 its external CAN port")
        ->check(whole_number_in(0, 2));
}

service::ObjectAddress object_address(const ObjectTargetOptions& target, std::uint16_t index,
                                      std::uint8_t sub_index) {
    service::ObjectAddress address;
    address.node = static_cast<std::uint8_t>(target.node);
    address.index = index;
    address.sub_index = sub_index;
    if (target.network) {
        address.network = static_cast<service::Network>(*target.network);
    }
    return address;
}

struct ServiceConnection::SignalWatch {
    explicit SignalWatch(ServiceConnection& connection)
        : signals(connection.loop_.io(), SIGINT, SIGTERM) {
        signals.async_wait([&connection](const boost::system::error_code& error, int) {
            if (!error) {
                connection.interrupted_ = true;
                connection.loop_.stop();
            }
        });
    }
    boost::asio::signal_set signals;
};

core::Result<std::unique_ptr<ServiceConnection>>
ServiceConnection::open(const ServiceClientOptions& options) {
    auto option = service::parse_link_option(options.port);
    if (!option) {
        return core::Error{fmt::format("--port: {}", option.error())};
    }
    auto connection = std::unique_ptr<ServiceConnection>(new ServiceConnection());
    auto link = service::open_client_link(connection->loop_, *option, options.baud);
    if (!link) {
        return core::Error{fmt::format("--port: {}", link.error())};
    }
    connection->link_ = std::move(*link);
    // The line time the timeouts allow for: the USB port is a bridge at 1 Mbit/s whatever the
    // host asks (LinkPacing::usb()). The client sends at once; the line is paced where it is:
    // by the UART of a real port, by `eposp serve`'s PacedLink (both ways) on an emulated one.
    service::ClientSettings settings;
    settings.protocol = options.protocol;
    settings.bits_per_second = options.protocol == service::Protocol::V2
                                   ? service::LinkPacing::usb().bits_per_second
                                   : options.baud;
    connection->client_.emplace(connection->loop_, *connection->link_, settings);
    connection->signals_ = std::make_unique<SignalWatch>(*connection);
    return connection;
}

ServiceConnection::~ServiceConnection() {
    client_.reset(); // before the link it listens to
    if (signals_) {
        signals_->signals.cancel();
        loop_.io().poll(); // completes the cancelled wait while the signal set still exists
    }
}

template <typename T>
service::ClientResult<T>
ServiceConnection::wait(const std::function<void(service::Client::Callback<T>)>& start) {
    std::optional<service::ClientResult<T>> result;
    if (!interrupted_) {
        start([this, &result](const service::ClientResult<T>& done) {
            result.emplace(done);
            loop_.stop();
        });
    }
    while (!result && !interrupted_) {
        loop_.run();
    }
    if (!result) {
        // The client stays busy with the request; nothing more is sent on this connection.
        return service::ClientError{service::ClientError::Kind::Link, 0, "interrupted"};
    }
    return *result;
}

service::ClientResult<std::array<std::uint8_t, 4>>
ServiceConnection::read_object(const service::ObjectAddress& object) {
    return wait<std::array<std::uint8_t, 4>>(
        [&](auto done) { client_->read_object(object, std::move(done)); });
}

service::ClientResult<service::Done>
ServiceConnection::write_object(const service::ObjectAddress& object,
                                std::array<std::uint8_t, 4> value) {
    return wait<service::Done>(
        [&](auto done) { client_->write_object(object, value, std::move(done)); });
}

service::ClientResult<ServiceConnection::Bytes>
ServiceConnection::read_segmented(const service::ObjectAddress& object) {
    return wait<Bytes>([&](auto done) { client_->read_segmented(object, std::move(done)); });
}

service::ClientResult<service::Done>
ServiceConnection::write_segmented(const service::ObjectAddress& object, Bytes value,
                                   service::Client::Progress progress) {
    return wait<service::Done>([&](auto done) {
        client_->write_segmented(object, std::move(value), std::move(done), std::move(progress));
    });
}

bool ServiceConnection::pause(core::Duration delay) {
    if (!interrupted_) {
        loop_.run_for(delay);
    }
    return !interrupted_;
}

} // namespace eposp::device::cli
