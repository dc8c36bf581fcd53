#pragma once

// Internal: one Asio stream of a link (a pseudo-terminal master, a serial device, a TCP socket):
// a read loop that hands bytes on as they come, and a bounded queue of bytes to write.

#include "eposp/core/result.hpp"

#include <array>
#include <boost/asio/buffer.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/write.hpp>
#include <boost/system/error_code.hpp>
#include <cstddef>
#include <cstdint>
#include <fmt/format.h>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unistd.h>
#include <utility>

namespace eposp::service {

using Descriptor = boost::asio::posix::stream_descriptor;

/// Hands an open file descriptor to the loop's reactor, or closes it and says why the reactor
/// cannot watch it.
inline core::Result<Descriptor> watch_descriptor(boost::asio::io_context& io, int fd,
                                                 const std::string& name) {
    Descriptor descriptor(io);
    boost::system::error_code error;
    if (descriptor.assign(fd, error)) {
        ::close(fd);
        return core::Error{fmt::format("cannot wait on {}: {}", name, error.message())};
    }
    return descriptor;
}

/// Shared with its pending read and write, so that a completion arriving after the link is gone
/// finds a detached stream rather than a destroyed one.
template <typename Stream>
class ByteStream : public std::enable_shared_from_this<ByteStream<Stream>> {
public:
    using BytesHandler = std::function<void(std::span<const std::uint8_t>)>;
    /// The read ended: end of file or an error. Nothing is read after it until start().
    using EndHandler = std::function<void(boost::system::error_code)>;

    ByteStream(Stream stream, std::size_t capacity)
        : stream_(std::move(stream)), capacity_(capacity) {}

    Stream& stream() { return stream_; }

    /// Starts reading and writing what is queued; after an end, starts again.
    void start(BytesHandler on_bytes, EndHandler on_end) {
        on_bytes_ = std::move(on_bytes);
        on_end_ = std::move(on_end);
        running_ = true;
        read();
        write_next();
    }

    /// Queues `bytes` (written once started); returns how many did not fit within the capacity
    /// and were dropped, the newest ones, so that what is queued stays in order and whole.
    std::size_t send(std::span<const std::uint8_t> bytes) {
        const std::size_t room = capacity_ - std::min(capacity_, unsent());
        const std::size_t taken = std::min(room, bytes.size());
        pending_.append(reinterpret_cast<const char*>(bytes.data()), taken);
        write_next();
        return bytes.size() - taken;
    }

    /// Bytes queued or being written.
    std::size_t unsent() const { return pending_.size() + in_flight_; }
    std::uint64_t bytes_written() const { return bytes_written_; }

    /// Stops handing anything on and forgets what is queued (the write in flight finishes
    /// unheard); returns the bytes forgotten. start() resumes.
    std::size_t stop() {
        const std::size_t forgotten = unsent();
        running_ = false;
        ++generation_;
        pending_.clear();
        in_flight_ = 0;
        return forgotten;
    }

    /// stop(), handlers forgotten, and the stream closed: pending operations end unheard.
    void close() {
        stop();
        on_bytes_ = nullptr;
        on_end_ = nullptr;
        boost::system::error_code ignored; // a stream that is gone has nothing more to say
        stream_.close(ignored);
    }

private:
    void read() {
        if (read_pending_ || !running_) {
            return;
        }
        read_pending_ = true;
        stream_.async_read_some(boost::asio::buffer(buffer_),
                                [self = this->shared_from_this(), generation = generation_](
                                    boost::system::error_code error, std::size_t size) {
                                    self->read_pending_ = false;
                                    if (generation != self->generation_ || !self->running_) {
                                        return;
                                    }
                                    // Copies: a handler may close the stream, which forgets the
                                    // handlers.
                                    if (error) {
                                        self->running_ = false;
                                        if (const EndHandler on_end = self->on_end_) {
                                            on_end(error);
                                        }
                                        return;
                                    }
                                    if (const BytesHandler on_bytes = self->on_bytes_) {
                                        on_bytes(std::span(self->buffer_.data(), size));
                                    }
                                    self->read();
                                });
    }

    void write_next() {
        if (!running_ || writing_ || pending_.empty()) {
            return;
        }
        auto chunk = std::make_shared<std::string>(std::exchange(pending_, {}));
        in_flight_ = chunk->size();
        writing_ = true;
        boost::asio::async_write(stream_, boost::asio::buffer(*chunk),
                                 [self = this->shared_from_this(), chunk, generation = generation_](
                                     boost::system::error_code error, std::size_t written) {
                                     self->writing_ = false;
                                     if (generation != self->generation_) {
                                         self->write_next(); // queued after a restart
                                         return;
                                     }
                                     self->in_flight_ = 0;
                                     self->bytes_written_ += written;
                                     // A failed write is not reported here: the read ends with the
                                     // same cause.
                                     if (!error) {
                                         self->write_next();
                                     }
                                 });
    }

    Stream stream_;
    std::size_t capacity_;
    BytesHandler on_bytes_;
    EndHandler on_end_;
    std::array<std::uint8_t, 4096> buffer_{};
    std::string pending_;
    std::size_t in_flight_ = 0;
    std::uint64_t bytes_written_ = 0;
    std::uint64_t generation_ = 0;
    bool running_ = false;
    bool read_pending_ = false;
    bool writing_ = false;
};

} // namespace eposp::service
