#pragma once

#include <boost/asio/buffer.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/system/error_code.hpp>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace eposp::can::io {

/// What one TCP connection still has to send, one write at a time: bytes appended while a write
/// is in flight wait and go out together with the next, so everything leaves in order.
class OutgoingBytes {
public:
    void append(std::string_view bytes) { pending_ += bytes; }
    /// Bytes waiting or in flight.
    std::size_t size() const { return pending_.size() + in_flight_.size(); }
    bool writing() const { return writing_; }
    void drop_pending() { pending_.clear(); }

    /// Starts the next write unless one is in flight or nothing waits; `done(error)` is called
    /// when it ends, and must call written() first.
    template <typename Done>
    void write_next(boost::asio::ip::tcp::socket& socket, Done done) {
        if (writing_ || pending_.empty()) {
            return;
        }
        in_flight_.swap(pending_);
        pending_.clear();
        writing_ = true;
        boost::asio::async_write(socket, boost::asio::buffer(in_flight_),
                                 [done = std::move(done)](boost::system::error_code error,
                                                          std::size_t) { done(error); });
    }
    /// The write in flight ended.
    void written() {
        writing_ = false;
        in_flight_.clear();
    }

private:
    std::string pending_;   ///< bytes waiting for the write in flight
    std::string in_flight_; ///< what the current write sends
    bool writing_ = false;
};

} // namespace eposp::can::io
