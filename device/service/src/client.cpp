#include "eposp/service/client.hpp"

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/service/v1_host_link.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"

#include <algorithm>
#include <deque>
#include <fmt/format.h>
#include <stdexcept>
#include <type_traits>

namespace eposp::service {
namespace {

using Bytes = std::vector<std::uint8_t>;
using AnswerCallback = Client::Callback<Bytes>;

// The longest answer a request may bring: the error code, a segment's control byte and 63
// bytes, framed (v2 with every byte stuffed at worst).
constexpr std::size_t kLongestAnswerBytes = 2 * (2 + 4 + 1 + SegmentControl::kMaxLength + 2);

// A segmented read whose length the device did not announce takes at most the longest DOMAIN a
// dictionary holds.
constexpr std::size_t kLongestUnannouncedValue = canopen::SubObject::kDefaultMaxLength;

// Segments of a write in flight at once on v2: half of what the EPOS P queues (ServicePort).
constexpr std::size_t kWriteWindow = 8;

ClientError link_error(std::string message) {
    return ClientError{ClientError::Kind::Link, 0, std::move(message)};
}

} // namespace

std::string_view to_string(Protocol protocol) {
    return protocol == Protocol::V1 ? "v1 (RS-232)" : "v2 (USB)";
}

std::string describe_error_code(std::uint32_t code) {
    return fmt::format("0x{:08X} {}", code,
                       canopen::describe(static_cast<canopen::AbortCode>(code)));
}

class Client::Impl {
public:
    Impl(core::EventLoop& loop, Link& link, ClientSettings settings)
        : loop_(loop), link_(link), settings_(settings) {
        link_.on_receive([this](std::span<const std::uint8_t> bytes) { receive(bytes); });
        link_.on_event([this](const LinkEvent& event) {
            fail_in_flight(link_error(fmt::format("{}: {}", link_.name(), event.text)));
        });
        if (settings_.protocol == Protocol::V1) {
            v1_.emplace([this](std::span<const std::uint8_t> bytes) { link_.send(bytes); },
                        [this](const V1Completion& completion) { completed(completion); });
        } else {
            v2_.emplace([this](const Frame& frame) { answered(frame); },
                        [this](V2Error error) {
                            // A whole answer with a wrong CRC ends the request at once; a frame
                            // cut short may be followed by the whole one, the timeout decides.
                            if (!in_flight_.empty() && error == V2Error::CrcError) {
                                finish(link_error("the answer arrived with a wrong CRC"));
                            }
                        });
        }
    }

    ~Impl() {
        link_.on_receive({});
        link_.on_event({});
    }

    bool busy() const { return !in_flight_.empty() || segmented_busy_; }
    void require_idle() const {
        if (busy()) {
            throw std::logic_error("service::Client: an operation is already under way");
        }
    }
    const ClientSettings& settings() const { return settings_; }

    // One frame and its answer: the answer's data when its error code is 0. On v2 several may
    // be in flight (a segmented write's window): the device answers them in order.
    void transact(const Request& request, AnswerCallback done) {
        if (!in_flight_.empty() && settings_.protocol == Protocol::V1) {
            throw std::logic_error("service::Client: a request is already outstanding");
        }
        Frame frame = encode_request(request);
        const bool expect_answer =
            settings_.protocol == Protocol::V2 || answered_on_v1(frame.opcode);
        in_flight_.push_back(Pending{std::move(frame), expect_answer, 0, std::move(done)});
        send(in_flight_.back());
    }

    void read_object(const ObjectAddress& object, Callback<std::array<std::uint8_t, 4>> done) {
        transact(ReadObject{object}, [done = std::move(done)](const ClientResult<Bytes>& answer) {
            if (!answer) {
                return done(answer.error());
            }
            if (answer->size() < 4) {
                return done(link_error("the ReadObject answer holds no value"));
            }
            std::array<std::uint8_t, 4> value{};
            std::copy_n(answer->begin(), 4, value.begin());
            done(value);
        });
    }

    void write_object(const ObjectAddress& object, std::array<std::uint8_t, 4> value,
                      Callback<Done> done) {
        transact(WriteObject{object, value},
                 [done = std::move(done)](const ClientResult<Bytes>& answer) {
                     answer ? done(Done{}) : done(answer.error());
                 });
    }

    void read_segmented(const ObjectAddress& object, Callback<Bytes> done, Progress progress) {
        auto transfer = std::make_shared<Transfer>(object, Bytes{}, std::move(progress));
        begin_segmented();
        transact(InitiateSegmentedRead{object},
                 [this, transfer, done = std::move(done)](const ClientResult<Bytes>& answer) {
                     if (!answer) {
                         return end_segmented(done, answer.error());
                     }
                     // The object's length, as the SDO initiate upload announces it (the
                     // EPOS P does; a device that answers with the error code alone is bounded
                     // by the longest DOMAIN): no segment may bring more.
                     if (answer->size() >= 4) {
                         transfer->total = static_cast<std::size_t>(
                             (*answer)[0] | (*answer)[1] << 8 | (*answer)[2] << 16 |
                             static_cast<std::uint32_t>((*answer)[3]) << 24);
                         transfer->announced = true;
                     } else {
                         transfer->total = kLongestUnannouncedValue;
                     }
                     read_next_segment(transfer, done);
                 });
    }

    void write_segmented(const ObjectAddress& object, Bytes value, Callback<Done> done,
                         Progress progress) {
        const auto length = static_cast<std::uint32_t>(value.size());
        auto transfer = std::make_shared<Transfer>(object, std::move(value), std::move(progress));
        transfer->total = transfer->data.size();
        begin_segmented();
        transact(InitiateSegmentedWrite{object, length},
                 [this, transfer, done = std::move(done)](const ClientResult<Bytes>& answer) {
                     if (!answer) {
                         return end_segmented(done, answer.error());
                     }
                     write_next_segment(transfer, done);
                 });
    }

private:
    struct Pending {
        Frame frame;
        bool expect_answer = true;
        int retries = 0;
        AnswerCallback done;
    };

    struct Transfer {
        Transfer(const ObjectAddress& address, Bytes bytes, Progress on_progress)
            : object(address), data(std::move(bytes)), progress(std::move(on_progress)) {}
        ObjectAddress object;
        Bytes data;
        Progress progress;
        std::size_t total = 0;
        bool announced = false;             ///< a read: whether the device told `total`
        std::size_t position = 0;           ///< bytes written (answered)
        std::size_t sent = 0;               ///< a write: bytes sent
        std::size_t outstanding = 0;        ///< a write: segments sent and not answered yet
        std::optional<ClientError> failure; ///< a write: the first refusal
        bool toggle = false;                ///< the toggle of the next segment; the first carries 0
    };

    void begin_segmented() { segmented_busy_ = true; }

    template <typename T>
    void end_segmented(const Callback<T>& done, std::type_identity_t<ClientResult<T>> result) {
        segmented_busy_ = false;
        done(result);
    }

    void read_next_segment(const std::shared_ptr<Transfer>& transfer, const Callback<Bytes>& done) {
        transact(
            SegmentRead{transfer->object.network, transfer->toggle},
            [this, transfer, done](const ClientResult<Bytes>& answer) {
                if (!answer) {
                    return end_segmented(done, answer.error());
                }
                if (answer->empty()) {
                    return end_segmented<Bytes>(done, link_error("a SegmentRead answer is empty"));
                }
                const SegmentControl control = SegmentControl::decode(answer->front());
                if (control.toggle != transfer->toggle || control.length + 1U > answer->size()) {
                    return end_segmented<Bytes>(
                        done, link_error("a SegmentRead answer has a wrong toggle or length"));
                }
                if (transfer->data.size() + control.length > transfer->total) {
                    return end_segmented<Bytes>(
                        done, link_error(fmt::format(
                                  "the segments bring more than the {} bytes {}", transfer->total,
                                  transfer->announced ? "announced" : "a value may have")));
                }
                transfer->data.insert(transfer->data.end(), answer->begin() + 1,
                                      answer->begin() + 1 + control.length);
                transfer->toggle = !transfer->toggle;
                if (transfer->progress) {
                    transfer->progress(transfer->data.size(),
                                       transfer->announced ? transfer->total : 0);
                }
                if (!control.more) {
                    return end_segmented<Bytes>(done, std::move(transfer->data));
                }
                read_next_segment(transfer, done);
            });
    }

    // Sends segments while the window has room: one at a time on v1 (its handshakes allow no
    // more), kWriteWindow on v2, so that the line carries segments while the device answers the
    // ones before (the device queues 16). The first refusal stops the sending; the transfer
    // ends once every segment in flight is answered, so no answer is left for the next request.
    void write_next_segment(const std::shared_ptr<Transfer>& transfer, const Callback<Done>& done) {
        const std::size_t window = settings_.protocol == Protocol::V2 ? kWriteWindow : 1;
        while (!transfer->failure && transfer->outstanding < window &&
               transfer->sent < transfer->data.size()) {
            send_segment(transfer, done);
        }
    }

    void send_segment(const std::shared_ptr<Transfer>& transfer, const Callback<Done>& done) {
        const std::size_t length =
            std::min(SegmentControl::kMaxLength, transfer->data.size() - transfer->sent);
        const auto first = transfer->data.begin() + static_cast<std::ptrdiff_t>(transfer->sent);
        const bool more = transfer->sent + length < transfer->data.size();
        const bool toggle = transfer->toggle;
        SegmentWrite segment{transfer->object.network,
                             SegmentControl{static_cast<std::uint8_t>(length), toggle, more},
                             Bytes(first, first + static_cast<std::ptrdiff_t>(length))};
        transfer->sent += length;
        transfer->toggle = !transfer->toggle;
        ++transfer->outstanding;
        transact(
            segment, [this, transfer, done, length, toggle](const ClientResult<Bytes>& answer) {
                --transfer->outstanding;
                if (!transfer->failure) {
                    if (!answer) {
                        transfer->failure = answer.error();
                    } else if (answer->empty() ||
                               SegmentControl::decode(answer->front()).toggle != toggle) {
                        transfer->failure = link_error("a SegmentWrite answer has a wrong toggle");
                    } else {
                        transfer->position += length;
                        if (transfer->progress) {
                            transfer->progress(transfer->position, transfer->total);
                        }
                    }
                }
                if (transfer->failure) {
                    if (transfer->outstanding == 0) {
                        end_segmented<Done>(done, *transfer->failure);
                    }
                    return;
                }
                if (transfer->position == transfer->data.size()) {
                    return end_segmented<Done>(done, Done{});
                }
                write_next_segment(transfer, done);
            });
    }

    void send(const Pending& request) {
        if (settings_.protocol == Protocol::V1) {
            v1_->request(request.frame, request.expect_answer);
        } else {
            link_.send(encode_v2(request.frame));
        }
        if (&request == &in_flight_.front()) {
            arm_timeout();
        }
    }

    // The device has answer_timeout to answer, plus the time the request and the longest
    // answer take on the line; each byte that arrives restarts it (a long answer on a slow line).
    void arm_timeout() {
        // The oldest request's answer comes first, after the requests in flight crossed the line.
        std::size_t bytes = kLongestAnswerBytes;
        for (const Pending& request : in_flight_) {
            bytes += 8 + 2 * request.frame.data.size();
        }
        const auto line_time = std::chrono::microseconds(
            bytes * 10 * 1'000'000 / std::max<std::uint32_t>(settings_.bits_per_second, 1));
        timeout_ = core::ScopedTimer(
            loop_, loop_.after(settings_.answer_timeout + line_time, [this] { timed_out(); }));
    }

    void receive(std::span<const std::uint8_t> bytes) {
        if (v1_) {
            v1_->receive(bytes);
        } else {
            v2_->receive(bytes);
        }
        if (!in_flight_.empty() && !retry_timer_.pending()) {
            arm_timeout();
        }
    }

    void timed_out() {
        if (in_flight_.empty()) {
            return;
        }
        if (v1_) {
            v1_->on_timeout(); // completes the request with V1Outcome::Timeout
            return;
        }
        if (v2_->mid_frame()) {
            v2_->on_timeout();
        }
        // Without the oldest answer the later ones cannot be told apart: all are lost.
        fail_in_flight(no_answer());
    }

    void fail_in_flight(const ClientError& error) {
        while (!in_flight_.empty()) {
            finish(error);
        }
    }

    ClientError no_answer() const {
        return ClientError{ClientError::Kind::NoAnswer, 0,
                           fmt::format("no answer from {} (is a device there, speaking {}?)",
                                       link_.name(), to_string(settings_.protocol))};
    }

    void completed(const V1Completion& completion) {
        if (in_flight_.empty()) {
            return;
        }
        Pending& pending = in_flight_.front();
        switch (completion.outcome) {
        case V1Outcome::Answered:
            return answered(*completion.answer);
        case V1Outcome::Sent:
            return finish(Bytes{});
        case V1Outcome::DeviceNotReady:
        case V1Outcome::DeviceCrcError:
            // The device did not take the request: send it again a little later.
            if (pending.retries < settings_.retries) {
                ++pending.retries;
                timeout_.cancel();
                retry_timer_ = core::ScopedTimer(loop_, loop_.after(settings_.retry_delay, [this] {
                    send(in_flight_.front());
                }));
                return;
            }
            return finish(link_error(fmt::format(
                "the device refused the request with 'F' {} times ({})", settings_.retries + 1,
                completion.outcome == V1Outcome::DeviceNotReady ? "not ready" : "CRC error")));
        case V1Outcome::AnswerCrcError:
            return finish(link_error("the answer arrived with a wrong CRC"));
        case V1Outcome::UnexpectedByte:
            return finish(link_error("the device sent a byte that has no place in the exchange "
                                     "(is it speaking v1?)"));
        case V1Outcome::Timeout:
            return finish(no_answer());
        }
    }

    void answered(const Frame& frame) {
        if (in_flight_.empty() || frame.opcode != kAnswerOpCode) {
            return; // a late answer to a request that timed out, or a stray frame
        }
        const auto answer = decode_answer(frame);
        if (!answer) {
            return finish(link_error("an answer shorter than its error code"));
        }
        if (answer->error != error::kNone) {
            return finish(ClientError{ClientError::Kind::Refused, answer->error,
                                      describe_error_code(answer->error)});
        }
        finish(answer->data);
    }

    // Ends the oldest request in flight, before its callback, which may send the next one.
    void finish(ClientResult<Bytes> result) {
        timeout_.cancel();
        retry_timer_.cancel();
        AnswerCallback done = std::move(in_flight_.front().done);
        in_flight_.pop_front();
        if (!in_flight_.empty()) {
            arm_timeout();
        }
        done(result);
    }

    core::EventLoop& loop_;
    Link& link_;
    ClientSettings settings_;
    std::optional<V1HostLink> v1_;
    std::optional<V2Decoder> v2_;
    std::deque<Pending> in_flight_; ///< oldest first: the order the device answers in
    bool segmented_busy_ = false;
    core::ScopedTimer timeout_;
    core::ScopedTimer retry_timer_;
};

Client::Client(core::EventLoop& loop, Link& link, ClientSettings settings)
    : impl_(std::make_unique<Impl>(loop, link, settings)) {}
Client::~Client() = default;

bool Client::busy() const {
    return impl_->busy();
}
const ClientSettings& Client::settings() const {
    return impl_->settings();
}
void Client::read_object(const ObjectAddress& object, Callback<std::array<std::uint8_t, 4>> done) {
    impl_->require_idle();
    impl_->read_object(object, std::move(done));
}
void Client::write_object(const ObjectAddress& object, std::array<std::uint8_t, 4> value,
                          Callback<Done> done) {
    impl_->require_idle();
    impl_->write_object(object, value, std::move(done));
}
void Client::read_segmented(const ObjectAddress& object, Callback<std::vector<std::uint8_t>> done,
                            Progress progress) {
    impl_->require_idle();
    impl_->read_segmented(object, std::move(done), std::move(progress));
}
void Client::write_segmented(const ObjectAddress& object, std::vector<std::uint8_t> value,
                             Callback<Done> done, Progress progress) {
    impl_->require_idle();
    impl_->write_segmented(object, std::move(value), std::move(done), std::move(progress));
}
void Client::request(const Request& request, Callback<std::vector<std::uint8_t>> done) {
    impl_->require_idle();
    impl_->transact(request, std::move(done));
}

} // namespace eposp::service
