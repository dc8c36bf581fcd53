#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/service/commands.hpp"
#include "eposp/service/link.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::service {

/// Which of maxon's serial protocols a client speaks (docs/service-interface.md).
enum class Protocol {
    V1, ///< RS-232: handshakes, Len-1
    V2, ///< USB: 0x90 0x02 frames with byte stuffing
};
std::string_view to_string(Protocol protocol);

struct ClientSettings {
    Protocol protocol = Protocol::V1;
    /// The line rate, for the time a frame takes on the line (added to the answer timeout).
    std::uint32_t bits_per_second = 115200;
    /// How long the device may take to answer, beyond the line time of the frames.
    core::Duration answer_timeout = std::chrono::seconds(1);
    /// v1: how often a request the device refused with 'F' (not ready, or a CRC error it saw)
    /// is sent again, after `retry_delay`.
    int retries = 3;
    core::Duration retry_delay = std::chrono::milliseconds(10);
};

/// Why a request failed.
struct ClientError {
    enum class Kind {
        Refused,  ///< the device answered with an error code (`code`)
        NoAnswer, ///< nothing (or nothing whole) came back within the timeout
        Link,     ///< the link failed: closed, a wrong CRC, 'F' after every retry, a bad answer
    };
    Kind kind = Kind::Refused;
    std::uint32_t code = 0; ///< Refused: the CANopen abort code or maxon error code
    std::string message;    ///< for the user: "0x06020000 Object does not exist Error"
};

/// A value, or the ClientError that explains its absence.
template <typename T>
class ClientResult {
public:
    ClientResult(T value) : value_(std::move(value)) {}
    ClientResult(ClientError error) : error_(std::move(error)) {}

    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }
    const T& value() const { return value_.value(); }
    const T& operator*() const { return value(); }
    const T* operator->() const { return &value(); }
    /// Meaningful when !ok().
    const ClientError& error() const { return error_; }

private:
    std::optional<T> value_;
    ClientError error_;
};

/// A request that completes without a value.
struct Done {};

/// The text of an error code an answer carries: "0x06020000 Object does not exist Error".
std::string describe_error_code(std::uint32_t code);

/// The host side of the service interface (`eposp download`, `od`, `watch`): requests to an
/// EPOS P (or, by node / network, to a node behind its gateway) over a Link, framed as v1 or
/// v2, on the link's event loop. One operation at a time: starting one while busy() is a
/// programming error (std::logic_error). Each completes exactly once through its callback,
/// called from the loop; the callback may start the next operation.
///
/// Every frame has a timeout (answer_timeout plus its line time, restarted at each byte that
/// arrives); on v1 a request the device refuses with 'F' is sent again up to `retries` times.
/// Segmented transfers move segments of up to 63 bytes with the toggle bit (maxon EPOS2
/// communication guide, "InitiateSegmentedWrite", "SegmentWrite").
class Client {
public:
    using Progress = std::function<void(std::size_t transferred, std::size_t total)>;
    template <typename T>
    using Callback = std::function<void(const ClientResult<T>&)>;

    /// `link` must outlive the client; the client takes its handlers over.
    Client(core::EventLoop& loop, Link& link, ClientSettings settings = {});
    ~Client();
    Client(const Client&) = delete;
    Client& operator=(const Client&) = delete;

    bool busy() const;
    const ClientSettings& settings() const;

    /// ReadObject: the 4 data bytes of the answer (an object of fewer bytes is padded).
    void read_object(const ObjectAddress& object, Callback<std::array<std::uint8_t, 4>> done);
    /// WriteObject: the device takes as many of the 4 bytes as its object has.
    void write_object(const ObjectAddress& object, std::array<std::uint8_t, 4> value,
                      Callback<Done> done);
    /// InitiateSegmentedRead, then SegmentRead until the last segment; the segments may bring
    /// no more than the length the initiate's answer announced (1 MiB when it announced none;
    /// `progress` then gets a total of 0).
    void read_segmented(const ObjectAddress& object, Callback<std::vector<std::uint8_t>> done,
                        Progress progress = {});
    /// InitiateSegmentedWrite with the length, then SegmentWrite in segments of 63 bytes.
    void write_segmented(const ObjectAddress& object, std::vector<std::uint8_t> value,
                         Callback<Done> done, Progress progress = {});
    /// Any request, answered with its data (an error code is a Refused error). On v1 the
    /// requests that get no answer complete with empty data once the device took them.
    void request(const Request& request, Callback<std::vector<std::uint8_t>> done);

private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace eposp::service
