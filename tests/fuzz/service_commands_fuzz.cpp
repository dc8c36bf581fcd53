// What a host may send the service interface of the EPOS P and of an ESCON2 (each input goes to
// both), once the link delivered whole frames: a
// sequence of requests of any opcode and parameters, with time passing between them. The
// commands (device/src/service/service_commands.hpp) never crash, answer every request exactly
// once with an answer frame (opcode 0x00, an error code and whole words), keep the segmented
// transfer's state consistent (a refused segment ends it), and leave the device serving: a
// ReadObject of 0x1000 afterwards is answered with its value.
//
// Input: frames as [opcode] [word count] [2 x count bytes]; a last frame cut short is dropped.
// The high bit of the word count lets 50 ms pass after the request (gateway timeouts, LSS waits).

#include "../../device/src/service/service_commands.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace {

namespace service = eposp::service;
using eposp::fuzz::require;
using namespace std::chrono_literals;

void check_answer(const service::Frame& answer) {
    require(answer.opcode == service::kAnswerOpCode, "an answer has opcode 0x00");
    require(answer.data.size() >= 4 && answer.data.size() % 2 == 0,
            "an answer starts with the error code and is whole words");
    require(answer.words() <= 255, "an answer fits a v2 frame");
}

void serve(std::span<const std::uint8_t> input, eposp::core::EventLoop& loop,
           eposp::device::ServiceCommands& commands) {
    std::size_t answers = 0;
    std::size_t requests = 0;
    for (std::size_t at = 0; at + 2 <= input.size();) {
        const std::uint8_t opcode = input[at];
        const std::size_t words = input[at + 1] & 0x7F;
        const bool wait = (input[at + 1] & 0x80) != 0;
        at += 2;
        if (at + 2 * words > input.size()) {
            break;
        }
        service::Frame request{opcode,
                               {input.begin() + static_cast<std::ptrdiff_t>(at),
                                input.begin() + static_cast<std::ptrdiff_t>(at + 2 * words)}};
        at += 2 * words;
        ++requests;
        commands.execute(request, [&answers](service::Frame answer) {
            check_answer(answer);
            ++answers;
        });
        loop.run_for(wait ? 50ms : 1ms);
    }
    loop.run_for(2s); // every gateway request and wait ends
    require(answers == requests, "every request is answered exactly once");

    std::optional<service::Frame> last;
    commands.execute(service::encode_request(service::ReadObject{{std::nullopt, 0, 0x1000, 0}}),
                     [&last](service::Frame answer) { last = std::move(answer); });
    loop.run_for(1ms);
    require(last && service::decode_answer(*last)->error == 0, "the device still serves");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> input(data, size);
    {
        eposp::device::EposP device;
        eposp::device::ServiceCommands commands(device.loop(),
                                                eposp::device::service_parts(device));
        serve(input, device.loop(), commands);
    }
    eposp::core::EventLoop loop;
    eposp::drives::escon2::Escon2Drive escon2(loop, {});
    escon2.start();
    eposp::device::ServiceCommands commands(loop, eposp::device::service_parts(escon2));
    serve(input, loop, commands);
    return 0;
}
