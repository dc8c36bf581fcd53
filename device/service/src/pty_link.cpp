#include "eposp/service/pty_link.hpp"

#include "byte_stream.hpp"
#include "pty_symlink.hpp"

#include <array>
#include <boost/asio/error.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <system_error>
#include <termios.h>
#include <unistd.h>

namespace eposp::service {
namespace {

std::string errno_message(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// Linux reports a pseudo-terminal whose slave no process has open (after one had) as POLLHUP
/// on the master; reading it fails with EIO until a host opens the slave again.
bool slave_hung_up(int master) {
    pollfd watched{master, POLLIN, 0};
    return ::poll(&watched, 1, 0) == 1 && (watched.revents & POLLHUP) != 0;
}

/// Drops what the device wrote that the last host left unread, so that the next host does not
/// read an answer meant for another. Nothing is written while no host is there, so everything
/// in the slave's input is stale.
void flush_slave_input(const std::string& slave) {
    const int fd = ::open(slave.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
        ::tcflush(fd, TCIFLUSH);
        ::close(fd);
    }
}

bool is_hang_up(boost::system::error_code error) {
    return error == boost::asio::error::eof || error == boost::system::errc::io_error;
}

} // namespace

class PtyLink::Impl {
public:
    Impl(core::EventLoop& loop, Descriptor master, std::string slave, std::filesystem::path symlink,
         std::size_t max_unsent_bytes)
        : loop_(loop),
          stream_(std::make_shared<ByteStream<Descriptor>>(std::move(master), max_unsent_bytes)),
          slave_(std::move(slave)), symlink_(std::move(symlink)) {}

    ~Impl() {
        stream_->close();
        if (!symlink_.empty()) {
            remove_pty_symlink(symlink_, slave_);
        }
    }

    void start(PtyLink& link) {
        link_ = &link;
        resume();
    }

    void send(std::span<const std::uint8_t> bytes) {
        if (!host_present_ || link_->closed()) {
            link_->statistics_.bytes_dropped_no_host += bytes.size();
            return;
        }
        link_->statistics_.bytes_dropped_full += stream_->send(bytes);
    }

    void add_bytes_sent(LinkStatistics& statistics) const {
        statistics.bytes_sent = stream_->bytes_written();
    }

    const std::string& slave() const { return slave_; }
    const std::filesystem::path& symlink() const { return symlink_; }
    bool host_present() const { return host_present_; }

private:
    void resume() {
        host_present_ = true;
        stream_->start([this](std::span<const std::uint8_t> bytes) { link_->deliver(bytes); },
                       [this](boost::system::error_code error) { on_end(error); });
    }

    void on_end(boost::system::error_code error) {
        if (!is_hang_up(error)) {
            link_->statistics_.bytes_dropped_no_host += stream_->stop();
            link_->report({LinkEvent::Kind::Closed,
                           fmt::format("reading {} failed: {}", link_->name(), error.message())});
            return;
        }
        host_present_ = false;
        link_->statistics_.bytes_dropped_no_host += stream_->stop();
        host_check_ =
            core::ScopedTimer(loop_, loop_.every(kHostCheckPeriod, [this] { check_for_host(); }));
        link_->report({LinkEvent::Kind::HungUp, fmt::format("the host closed {}", slave_)});
    }

    void check_for_host() {
        if (slave_hung_up(stream_->stream().native_handle())) {
            return;
        }
        host_check_.cancel();
        flush_slave_input(slave_);
        resume();
    }

    core::EventLoop& loop_;
    std::shared_ptr<ByteStream<Descriptor>> stream_;
    std::string slave_;
    std::filesystem::path symlink_;
    PtyLink* link_ = nullptr;
    core::ScopedTimer host_check_;
    bool host_present_ = true;
};

core::Result<std::unique_ptr<PtyLink>> PtyLink::open(core::EventLoop& loop,
                                                     PtyLinkOptions options) {
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (master < 0) {
        return core::Error{fmt::format("cannot open a pseudo-terminal: {}", errno_message(errno))};
    }
    const auto fail = [master](std::string_view step) {
        const int error = errno;
        ::close(master);
        return core::Error{fmt::format("cannot set up a pseudo-terminal: {} failed: {}", step,
                                       errno_message(error))};
    };
    if (::grantpt(master) != 0) {
        return fail("grantpt");
    }
    if (::unlockpt(master) != 0) {
        return fail("unlockpt");
    }
    std::array<char, 128> name{};
    if (::ptsname_r(master, name.data(), name.size()) != 0) {
        return fail("ptsname");
    }
    // Raw: bytes pass both ways unchanged (no echo, no line editing, no CR/LF translation, no
    // signals), as on a serial line; the master's settings are the slave's.
    termios settings{};
    if (::tcgetattr(master, &settings) != 0) {
        return fail("tcgetattr");
    }
    ::cfmakeraw(&settings);
    if (::tcsetattr(master, TCSANOW, &settings) != 0) {
        return fail("tcsetattr");
    }
    std::string slave = name.data();
    if (!options.symlink.empty()) {
        const auto made = make_pty_symlink(options.symlink, slave);
        if (!made) {
            ::close(master);
            return core::Error{made.error()};
        }
    }
    auto descriptor = watch_descriptor(loop.io(), master, "the pseudo-terminal " + slave);
    if (!descriptor) {
        if (!options.symlink.empty()) {
            remove_pty_symlink(options.symlink, slave);
        }
        return core::Error{descriptor.error()};
    }
    auto impl = std::make_unique<Impl>(loop, std::move(*descriptor), std::move(slave),
                                       std::move(options.symlink), options.max_unsent_bytes);
    std::unique_ptr<PtyLink> link(new PtyLink(std::move(impl)));
    link->impl_->start(*link);
    return link;
}

PtyLink::PtyLink(std::unique_ptr<Impl> impl)
    : impl_(std::move(impl)), name_(fmt::format("pty {}", impl_->slave())) {}

PtyLink::~PtyLink() = default;

void PtyLink::send(std::span<const std::uint8_t> bytes) {
    impl_->send(bytes);
}

LinkStatistics PtyLink::statistics() const {
    LinkStatistics statistics = statistics_;
    impl_->add_bytes_sent(statistics);
    return statistics;
}

const std::string& PtyLink::slave_path() const {
    return impl_->slave();
}

const std::filesystem::path& PtyLink::symlink_path() const {
    return impl_->symlink();
}

bool PtyLink::host_present() const {
    return impl_->host_present();
}

} // namespace eposp::service
