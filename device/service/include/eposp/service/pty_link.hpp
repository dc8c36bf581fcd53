#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace eposp::service {

struct PtyLinkOptions {
    /// Where to put a symlink to the slave, e.g. "./ttyEPOSP" (`--serial-link`); empty for
    /// none. Only a missing path, or a symlink that an earlier run left to a /dev/pts/N that is
    /// gone, is (re)placed; anything else is refused. Removed at close if it still points to
    /// our slave.
    std::filesystem::path symlink{};
    std::size_t max_unsent_bytes = kDefaultMaxUnsentBytes;
};

/// The device side of an emulated serial port: a new pseudo-terminal in raw mode whose slave
/// (`/dev/pts/N`) any program opens as it would a serial device.
///
/// A host closing the slave is a hang-up (HungUp), not an error: output still queued for it is
/// dropped, and the link waits for the next host to open the slave, checking every
/// kHostCheckPeriod; output sent meanwhile is dropped too, and what the last host left unread
/// is flushed before the next one is served. Closing the link closes the master: a host then
/// reads end of file or EIO, as when a serial device is unplugged.
///
/// Before the first host opens the slave nothing can tell that none is there: what is sent
/// then waits in the kernel for the first host. While waiting for a host after a hang-up, the
/// check is a periodic loop timer, so a virtual loop's run() does not return meanwhile (use
/// run_for / run_until).
class PtyLink final : public Link {
public:
    static constexpr core::Duration kHostCheckPeriod = std::chrono::milliseconds(10);

    /// Opens the pseudo-terminal (and the symlink), or says why it cannot.
    static core::Result<std::unique_ptr<PtyLink>> open(core::EventLoop& loop,
                                                       PtyLinkOptions options = {});
    ~PtyLink() override;
    PtyLink(const PtyLink&) = delete;
    PtyLink& operator=(const PtyLink&) = delete;

    void send(std::span<const std::uint8_t> bytes) override;
    std::string_view name() const override { return name_; }
    LinkStatistics statistics() const override;

    /// "/dev/pts/N", for `eposp serve` to print.
    const std::string& slave_path() const;
    /// The symlink made, empty when none was asked for.
    const std::filesystem::path& symlink_path() const;
    /// False between a hang-up and the next host opening the slave.
    bool host_present() const;

private:
    class Impl;
    explicit PtyLink(std::unique_ptr<Impl> impl);

    std::unique_ptr<Impl> impl_;
    std::string name_;
};

} // namespace eposp::service
