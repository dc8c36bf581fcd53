#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"
#include "eposp/service/link_option.hpp"
#include "eposp/service/paced_link.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace eposp::service {

struct ServingLinkSettings {
    LinkPacing pacing = LinkPacing::rs232();
    /// `--serial-link`: a symlink to the pseudo-terminal's slave; refused for other kinds.
    std::filesystem::path symlink{};
    /// The rate a device PATH is set to.
    std::uint32_t baud = 115200;
    std::size_t max_unsent_bytes = kDefaultMaxUnsentBytes;
};

struct ServingLink {
    std::unique_ptr<PacedLink> link;
    /// Where hosts find it, for `eposp serve` to print: "/dev/pts/4", "127.0.0.1:4001" (the port
    /// picked for 0), "/dev/ttyUSB0".
    std::string where;
};

/// The device side (`eposp serve`): `pty` opens a PtyLink, a PATH a DevicePathLink, `tcp:ADDR`
/// a TcpServerLink; each paced as `settings` say.
core::Result<ServingLink> open_serving_link(core::EventLoop& loop, const LinkOption& option,
                                            const ServingLinkSettings& settings = {});

/// The client side (`eposp download` / `od` / `watch --port`): a PATH opens a DevicePathLink at
/// `baud`, `tcp:ADDR` a TcpClientLink; `pty` is refused, a client needs something to reach.
core::Result<std::unique_ptr<Link>>
open_client_link(core::EventLoop& loop, const LinkOption& option, std::uint32_t baud = 115200);

} // namespace eposp::service
