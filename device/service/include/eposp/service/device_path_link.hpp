#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace eposp::service {

struct DevicePathLinkOptions {
    /// 8N1 at this rate; only the rates termios has a constant for (B50 ... B4000000).
    std::uint32_t baud = 115200;
    std::size_t max_unsent_bytes = kDefaultMaxUnsentBytes;
};

/// A serial device that exists already: a USB adapter (/dev/ttyUSB0), a real port, or the slave
/// of the pseudo-terminal that `eposp serve` prints, which is how the client commands reach it.
/// Opened raw, 8 data bits, no parity, one stop bit, no flow control, modem lines ignored.
///
/// The device going away (unplugged; the pseudo-terminal's master closed: EIO or end of file)
/// closes the link for good (Closed).
class DevicePathLink final : public Link {
public:
    static core::Result<std::unique_ptr<DevicePathLink>> open(core::EventLoop& loop,
                                                              const std::filesystem::path& path,
                                                              DevicePathLinkOptions options = {});
    ~DevicePathLink() override;
    DevicePathLink(const DevicePathLink&) = delete;
    DevicePathLink& operator=(const DevicePathLink&) = delete;

    void send(std::span<const std::uint8_t> bytes) override;
    std::string_view name() const override { return name_; }
    LinkStatistics statistics() const override;

private:
    class Impl;
    DevicePathLink(std::string name, std::unique_ptr<Impl> impl);

    std::string name_;
    std::unique_ptr<Impl> impl_;
};

/// Whether termios can set `baud` (a B constant exists for it).
bool termios_supports_baud(std::uint32_t baud);

} // namespace eposp::service
