#include "eposp/service/device_path_link.hpp"

#include "byte_stream.hpp"

#include <algorithm>
#include <array>
#include <boost/asio/error.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <cerrno>
#include <fcntl.h>
#include <fmt/format.h>
#include <optional>
#include <sys/stat.h>
#include <system_error>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace eposp::service {
namespace {

constexpr std::array<std::pair<std::uint32_t, speed_t>, 30> kBaudRates{{
    {50, B50},           {75, B75},           {110, B110},         {134, B134},
    {150, B150},         {200, B200},         {300, B300},         {600, B600},
    {1200, B1200},       {1800, B1800},       {2400, B2400},       {4800, B4800},
    {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
    {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
    {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
    {3500000, B3500000}, {4000000, B4000000},
}};

std::optional<speed_t> speed_of(std::uint32_t baud) {
    const auto found =
        std::ranges::find(kBaudRates, baud, &std::pair<std::uint32_t, speed_t>::first);
    return found == kBaudRates.end() ? std::nullopt : std::optional(found->second);
}

std::string errno_message(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// Raw 8N1 without flow control at `speed`; CLOCAL so that a port without modem lines (a
/// pseudo-terminal, a three-wire cable) is not waited on.
bool set_raw_8n1(int fd, speed_t speed) {
    termios settings{};
    if (::tcgetattr(fd, &settings) != 0) {
        return false;
    }
    ::cfmakeraw(&settings);
    settings.c_cflag &= ~static_cast<tcflag_t>(PARENB | CSTOPB | CSIZE | CRTSCTS);
    settings.c_cflag |= CS8 | CLOCAL | CREAD;
    settings.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
    settings.c_cc[VMIN] = 1;
    settings.c_cc[VTIME] = 0;
    return ::cfsetispeed(&settings, speed) == 0 && ::cfsetospeed(&settings, speed) == 0 &&
           ::tcsetattr(fd, TCSANOW, &settings) == 0;
}

} // namespace

bool termios_supports_baud(std::uint32_t baud) {
    return speed_of(baud).has_value();
}

class DevicePathLink::Impl {
public:
    Impl(Descriptor descriptor, std::size_t max_unsent_bytes)
        : stream_(
              std::make_shared<ByteStream<Descriptor>>(std::move(descriptor), max_unsent_bytes)) {}
    ~Impl() { stream_->close(); }

    void start(DevicePathLink& link) {
        link_ = &link;
        stream_->start([this](std::span<const std::uint8_t> bytes) { link_->deliver(bytes); },
                       [this](boost::system::error_code error) { on_end(error); });
    }

    void send(std::span<const std::uint8_t> bytes) {
        if (link_->closed()) {
            link_->statistics_.bytes_dropped_no_host += bytes.size();
            return;
        }
        link_->statistics_.bytes_dropped_full += stream_->send(bytes);
    }

    void add_bytes_sent(LinkStatistics& statistics) const {
        statistics.bytes_sent = stream_->bytes_written();
    }

private:
    void on_end(boost::system::error_code error) {
        link_->statistics_.bytes_dropped_no_host += stream_->stop();
        const bool gone =
            error == boost::asio::error::eof || error == boost::system::errc::io_error;
        link_->report({LinkEvent::Kind::Closed,
                       gone
                           ? fmt::format("{} hung up (the device is gone)", link_->name())
                           : fmt::format("reading {} failed: {}", link_->name(), error.message())});
    }

    std::shared_ptr<ByteStream<Descriptor>> stream_;
    DevicePathLink* link_ = nullptr;
};

core::Result<std::unique_ptr<DevicePathLink>>
DevicePathLink::open(core::EventLoop& loop, const std::filesystem::path& path,
                     DevicePathLinkOptions options) {
    const auto speed = speed_of(options.baud);
    if (!speed) {
        return core::Error{fmt::format(
            "{} baud is not a rate a serial port can be set to (termios has 50 ... 115200, "
            "230400, 460800, 500000, 576000, 921600, 1000000 ... 4000000)",
            options.baud)};
    }
    const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int error = errno;
        return core::Error{
            error == EISDIR
                ? fmt::format("{} is a directory, not a serial device", path.string())
                : fmt::format("cannot open {}: {}", path.string(), errno_message(error))};
    }
    if (::isatty(fd) != 1) {
        ::close(fd);
        return core::Error{
            fmt::format("{} is not a serial device (not a terminal)", path.string())};
    }
    if (!set_raw_8n1(fd, *speed)) {
        const int error = errno;
        ::close(fd);
        return core::Error{fmt::format("cannot set {} to {} baud 8N1: {}", path.string(),
                                       options.baud, errno_message(error))};
    }
    auto descriptor = watch_descriptor(loop.io(), fd, path.string());
    if (!descriptor) {
        return core::Error{descriptor.error()};
    }
    auto impl = std::make_unique<Impl>(std::move(*descriptor), options.max_unsent_bytes);
    std::unique_ptr<DevicePathLink> link(new DevicePathLink(path.string(), std::move(impl)));
    link->impl_->start(*link);
    return link;
}

DevicePathLink::DevicePathLink(std::string name, std::unique_ptr<Impl> impl)
    : name_(std::move(name)), impl_(std::move(impl)) {}

DevicePathLink::~DevicePathLink() = default;

void DevicePathLink::send(std::span<const std::uint8_t> bytes) {
    impl_->send(bytes);
}

LinkStatistics DevicePathLink::statistics() const {
    LinkStatistics statistics = statistics_;
    impl_->add_bytes_sent(statistics);
    return statistics;
}

} // namespace eposp::service
