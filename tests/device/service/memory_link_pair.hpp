#pragma once

// For the tests of the service clients: two links joined back to back in memory, on the event
// loop (what one sends, the other receives at the next turn of the loop), so that a client and
// a ServicePort talk in virtual time without a pseudo-terminal.

#include "eposp/core/event_loop.hpp"
#include "eposp/service/link.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace eposp::service::test {

class MemoryLink final : public Link {
public:
    MemoryLink(core::EventLoop& loop, std::string name) : loop_(loop), name_(std::move(name)) {}
    ~MemoryLink() override {
        *alive_ = false; // bytes still on their way to it are dropped
        if (peer_) {
            peer_->peer_ = nullptr;
        }
    }
    MemoryLink(const MemoryLink&) = delete;
    MemoryLink& operator=(const MemoryLink&) = delete;

    static std::pair<std::unique_ptr<MemoryLink>, std::unique_ptr<MemoryLink>>
    pair(core::EventLoop& loop) {
        auto host = std::make_unique<MemoryLink>(loop, "memory host");
        auto device = std::make_unique<MemoryLink>(loop, "memory device");
        host->peer_ = device.get();
        device->peer_ = host.get();
        return {std::move(host), std::move(device)};
    }

    void send(std::span<const std::uint8_t> bytes) override {
        if (peer_ == nullptr) {
            statistics_.bytes_dropped_no_host += bytes.size();
            return;
        }
        statistics_.bytes_sent += bytes.size();
        // Delivered by the loop, as a file descriptor would, never from within send().
        loop_.post([alive = peer_->alive_, peer = peer_,
                    copy = std::vector<std::uint8_t>(bytes.begin(), bytes.end())] {
            if (*alive) {
                peer->deliver(copy);
            }
        });
    }
    std::string_view name() const override { return name_; }

    /// The other end goes away: this one reports Closed.
    void close_from_peer() { report(LinkEvent{LinkEvent::Kind::Closed, "the device went away"}); }

private:
    core::EventLoop& loop_;
    std::string name_;
    MemoryLink* peer_ = nullptr;
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace eposp::service::test
