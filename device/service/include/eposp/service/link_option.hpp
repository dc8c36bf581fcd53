#pragma once

#include "eposp/core/result.hpp"

#include <string>
#include <string_view>

namespace eposp::service {

/// What `--serial` / `--usb` / `--port` name: `pty`, a device PATH, or `tcp:ADDR`.
struct LinkOption {
    enum class Kind {
        Pty,        ///< a new pseudo-terminal (device side only)
        DevicePath, ///< a serial device that exists: /dev/ttyUSB0, a pty slave
        Tcp,        ///< TCP: the device listens on ADDR, a client connects to it
    };
    Kind kind = Kind::Pty;
    std::string target; ///< the path or ADDR; empty for Pty

    friend bool operator==(const LinkOption&, const LinkOption&) = default;
};

/// Parses the option text, or says what is wrong with it: empty, a malformed TCP address, a
/// path that does not exist, is a directory, or is not a character device.
core::Result<LinkOption> parse_link_option(std::string_view text);

} // namespace eposp::service
