// What may arrive on the RS-232 link (v1), as arbitrary bytes in arbitrary pieces, with the
// frame timeout striking between pieces, at both ends:
// - the device side (v1_device_link.hpp) takes the bytes as the host's; its owner answers each
//   request (or skips the answer where v1 sends none). It writes only handshakes, the answer
//   opcode and the answers it was given, and every request it delivers re-reads to itself;
// - the host side (v1_host_link.hpp) takes the bytes as the device's, sending the next request
//   whenever one completes. Each request completes once, an answer only with Answered, and
//   the host writes only the requests' bytes and handshakes.
// After a timeout neither is mid-frame; neither crashes, hangs or trips a sanitizer.
//
// Input: [control] [bytes...]; control bits 0..3: piece size - 1; bit 4: a timeout after every
// piece; bit 5: the device's owner leaves requests unanswered until the next piece.

#include "eposp/service/commands.hpp"
#include "eposp/service/frame_limits.hpp"
#include "eposp/service/v1_device_link.hpp"
#include "eposp/service/v1_frame.hpp"
#include "eposp/service/v1_host_link.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace {

namespace service = eposp::service;
using eposp::fuzz::require;

struct Control {
    std::size_t piece = 1;
    bool timeouts = false;
    bool late_answers = false;
};

bool is_handshake(std::span<const std::uint8_t> out) {
    return out.size() == 1 && (out[0] == service::kReady || out[0] == service::kNotReady);
}

void check_rereads(const service::Frame& frame) {
    require(frame.words() >= 1 && frame.words() <= service::kV1MaxWords &&
                frame.data.size() % 2 == 0,
            "a v1 frame holds 1 to 256 whole words");
    const std::vector<std::uint8_t> rest = service::v1_frame_rest(frame);
    service::V1FrameReader reader(frame.opcode);
    for (std::size_t i = 0; i + 1 < rest.size(); ++i) {
        require(reader.push(rest[i]) == service::V1FrameReader::Status::Incomplete,
                "a frame re-reads byte by byte");
    }
    require(reader.push(rest.back()) == service::V1FrameReader::Status::Complete &&
                std::move(reader).take() == frame,
            "a delivered frame re-reads to itself");
}

void fuzz_device(std::span<const std::uint8_t> stream, const Control& control) {
    // The answer: the request's data, as an answer frame (any size v1 carries).
    std::vector<std::uint8_t> answer_rest;
    bool pending = false;
    service::V1DeviceLink* self = nullptr;
    const auto answer = [&](const service::Frame& request) {
        if (!service::answered_on_v1(request.opcode)) {
            self->skip_answer();
            return;
        }
        const service::Frame reply{service::kAnswerOpCode, request.data};
        answer_rest = service::v1_frame_rest(reply);
        self->send_answer(reply);
    };
    std::vector<service::Frame> waiting;
    service::V1DeviceLink device(
        [&](std::span<const std::uint8_t> out) {
            const bool answer_opcode = out.size() == 1 && out[0] == service::kAnswerOpCode;
            const bool answer_bytes =
                std::equal(out.begin(), out.end(), answer_rest.begin(), answer_rest.end());
            require(is_handshake(out) || answer_opcode || answer_bytes,
                    "the device writes handshakes, the answer opcode and its answers only");
        },
        [&](const service::Frame& request) {
            check_rereads(request);
            require(!pending, "no request is delivered while one awaits its answer");
            if (control.late_answers) {
                pending = true;
                waiting.push_back(request);
            } else {
                answer(request);
            }
        });
    self = &device;
    for (std::size_t at = 0; at < stream.size(); at += control.piece) {
        device.receive(stream.subspan(at, std::min(control.piece, stream.size() - at)));
        if (pending) {
            pending = false;
            answer(waiting.back());
        }
        if (control.timeouts) {
            device.on_timeout();
            require(!device.mid_frame(), "the device is not mid-frame after a timeout");
        }
    }
}

void fuzz_host(std::span<const std::uint8_t> stream, const Control& control) {
    // Requests of every size class: one word, two, the largest.
    const std::vector<service::Frame> requests{
        {0x10, {0x41, 0x60, 0x00, 0x00}},
        {0x0E, {0x00, 0x00, 0x01, 0x00}},
        {0x15, std::vector<std::uint8_t>(2 * service::kV1MaxWords, 0x90)},
    };
    std::size_t next = 0;
    std::vector<std::uint8_t> request_rest;
    std::size_t started = 0;
    std::size_t completed = 0;
    service::V1HostLink* self = nullptr;
    const auto send_next = [&] {
        const service::Frame& request = requests[next++ % requests.size()];
        request_rest = service::v1_frame_rest(request);
        ++started;
        self->request(request, service::answered_on_v1(request.opcode));
    };
    service::V1HostLink host(
        [&](std::span<const std::uint8_t> out) {
            const bool opcode =
                out.size() == 1 && out[0] == requests[(next - 1) % requests.size()].opcode;
            const bool rest =
                std::equal(out.begin(), out.end(), request_rest.begin(), request_rest.end());
            require(is_handshake(out) || opcode || rest,
                    "the host writes its requests and handshakes only");
        },
        [&](const service::V1Completion& done) {
            ++completed;
            require(completed == started, "each request completes once");
            require(done.answer.has_value() == (done.outcome == service::V1Outcome::Answered),
                    "an answer comes with Answered only");
            if (done.answer) {
                require(done.answer->opcode == service::kAnswerOpCode, "an answer has opcode 0");
                check_rereads(*done.answer);
            }
            send_next();
        });
    self = &host;
    send_next();
    for (std::size_t at = 0; at < stream.size(); at += control.piece) {
        host.receive(stream.subspan(at, std::min(control.piece, stream.size() - at)));
        if (control.timeouts) {
            host.on_timeout(); // completes the request, which sends the next one
            require(host.busy() && completed + 1 == started, "a timeout completes the request");
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const Control control{(data[0] & 0x0Fu) + 1u, (data[0] & 0x10u) != 0, (data[0] & 0x20u) != 0};
    const std::span<const std::uint8_t> stream(data + 1, size - 1);
    fuzz_device(stream, control);
    fuzz_host(stream, control);
    return 0;
}
