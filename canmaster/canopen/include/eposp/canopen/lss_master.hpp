#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/core/event_loop.hpp"

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eposp::canopen {

/// Why an LSS request did not succeed.
enum class LssErrorKind : std::uint8_t {
    NoAnswer, ///< no slave answered within the master's timeout
    NotSent,  ///< the port refused the request (bus-off, transmit queue full)
    Refused,  ///< the slave answered with a non-zero error code
};

struct LssError {
    LssErrorKind kind = LssErrorKind::NoAnswer;
    LssCommand service = LssCommand::SwitchStateGlobal; ///< the request's command specifier
    std::uint8_t code = 0;     ///< Refused: the error code of the answer (EPOS2 FW spec 7.4.2)
    std::uint8_t specific = 0; ///< Refused with code 255: the manufacturer-specific error
    friend bool operator==(const LssError&, const LssError&) = default;
};
/// "LSS slave refused configure node-ID: node-ID out of range (error code 1)".
std::string describe(const LssError& error);

/// The value of an LSS request, or why there is none: a missing answer is a value too.
template <typename T>
class LssResult {
public:
    LssResult(T value) : value_(std::move(value)) {}
    LssResult(LssError error) : error_(error) {}

    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }
    /// Asking a failed result for its value is a programming error (bad_optional_access).
    const T& value() const { return value_.value(); }
    const T& operator*() const { return value(); }
    const LssError& error() const { return error_; }

private:
    std::optional<T> value_;
    LssError error_;
};

/// The result of a service that answers only success or an error.
template <>
class LssResult<void> {
public:
    LssResult() = default;
    LssResult(LssError error) : error_(error) {}

    bool ok() const { return !error_; }
    explicit operator bool() const { return ok(); }
    const LssError& error() const { return *error_; }

private:
    std::optional<LssError> error_;
};

/// Identify remote slave's address range (EPOS2 FW spec 7.4.2.12): one vendor-ID and product
/// code, revision and serial number between low and high, inclusive.
struct LssAddressRange {
    std::uint32_t vendor_id = 0;
    std::uint32_t product_code = 0;
    std::uint32_t revision_low = 0;
    std::uint32_t revision_high = 0xFFFF'FFFF;
    std::uint32_t serial_low = 0;
    std::uint32_t serial_high = 0xFFFF'FFFF;
};

struct LssMasterConfig {
    /// How long a request waits for its answer, counted from handing it to the port. The
    /// identification services wait this long in any case, to collect every slave's answer.
    core::Duration timeout = std::chrono::milliseconds(100);
};

/// The LSS master (CiA 305, EPOS2 FW spec 7.4): every service as an asynchronous request on the
/// event loop. LSS is one conversation on one pair of identifiers, so requests run one at a
/// time in the order they were made; each completes by its callback (which may be empty), from a
/// loop event and never inside the call that made it, with the answer or an LssError.
class LssMaster {
public:
    template <typename T>
    using Callback = std::function<void(const LssResult<T>&)>;

    LssMaster(core::EventLoop& loop, can::Port& port, LssMasterConfig config = {});
    LssMaster(const LssMaster&) = delete;
    LssMaster& operator=(const LssMaster&) = delete;

    void on_frame(const can::Frame& frame);

    // Unconfirmed services: `done` runs when the request has been handed to the port.

    /// 7.4.2.1: every slave to waiting or to configuration.
    void switch_state_global(LssState state, Callback<void> done = {});
    /// 7.4.2.5: the slaves in configuration switch to their configured bit rate. The master
    /// sends nothing for two switch delays; `switch_now` runs after the first one, when the
    /// master's own controller must change its bit rate, and `done` after the second.
    void activate_bit_timing(std::uint16_t switch_delay_ms, std::function<void()> switch_now,
                             Callback<void> done = {});

    // Confirmed services: the answer of the slave in configuration.

    /// 7.4.2.2: the slave with this address switches to configuration and confirms.
    void switch_state_selective(const LssAddress& address, Callback<void> done);
    /// 7.4.2.3: the slave's pending node-ID (1..127, or 0xFF for none).
    void configure_node_id(NodeId id, Callback<void> done);
    /// 7.4.2.4: table selector 0 and an index of kLssBitTimingTable (lss_bit_timing_index()).
    void configure_bit_timing(std::uint8_t table_selector, std::uint8_t table_index,
                              Callback<void> done);
    /// 7.4.2.6
    void store_configuration(Callback<void> done);
    /// 7.4.2.7-7.4.2.10: one number of the slave's LSS address.
    void inquire_identity(LssPart part, Callback<std::uint32_t> done);
    /// 7.4.2.11: the slave's active node-ID.
    void inquire_node_id(Callback<NodeId> done);

    // Identification: any number of slaves may answer, so these wait the whole timeout and
    // report whether at least one did (several equal answers are one frame on a real bus).

    /// 7.4.2.12
    void identify_remote_slaves(const LssAddressRange& range, Callback<bool> done);
    /// 7.4.2.13
    void identify_non_configured_slaves(Callback<bool> done);
    /// One fastscan request (CiA 305); LssFastscan runs the whole procedure.
    void fastscan(const FastscanRequest& request, Callback<bool> done);

    /// No request running or waiting.
    bool idle() const { return !active_ && queue_.empty(); }
    const LssMasterConfig& config() const { return config_; }

private:
    /// What became of a request: whether the port took its frames, and the answer if any.
    struct Outcome {
        bool sent = true;
        std::optional<can::Frame> answer;
    };
    struct Request {
        std::vector<can::Frame> frames;
        /// The answer's command specifier; none for an unconfirmed service.
        std::optional<LssCommand> answer;
        /// Wait the whole timeout, keeping the first answer, instead of ending at it.
        bool collect = false;
        /// Unconfirmed: how long the master stays silent after sending.
        core::Duration hold{};
        std::function<void(const Outcome&)> complete;
    };

    void submit(Request request);
    /// A request answered by one slave: `done` gets NotSent, NoAnswer or what `convert` makes
    /// of the answer.
    template <typename T, typename Convert>
    void ask(LssCommand service, std::vector<can::Frame> frames, LssCommand answer,
             Callback<T> done, Convert convert);
    void configure(LssCommand cs, std::initializer_list<std::uint8_t> bytes, Callback<void> done);
    void unconfirmed(std::vector<can::Frame> frames, core::Duration hold, Callback<void> done);
    void identification(std::vector<can::Frame> frames, LssCommand answer, Callback<bool> done);
    void start_next();
    void finish(Outcome outcome);

    core::EventLoop& loop_;
    can::Port& port_;
    LssMasterConfig config_;
    std::deque<Request> queue_;
    std::optional<Request> active_;
    std::optional<can::Frame> collected_;
    core::ScopedTimer timer_;
    core::ScopedTimer start_;
};

} // namespace eposp::canopen
