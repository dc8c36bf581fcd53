#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/service/commands.hpp"
#include "eposp/service/v1_frame.hpp"
#include "eposp/service/v1_host_link.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "memory_link_pair.hpp"

#include <gtest/gtest.h>
#include <random>

// A service port of the EPOS P on an in-memory link (docs/service-interface.md): what a host
// sees of the frame timeout 0x5005, of hang-ups, of a second host racing the first and of
// garbage, on both protocols. The commands themselves are tested in service_commands_test.cpp.

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using service::test::MemoryLink;

service::Frame read_device_type() {
    return service::encode_request(service::ReadObject{{std::nullopt, 0, 0x1000, 0}});
}

class ServicePortTest : public testing::TestWithParam<ServiceProtocol> {
protected:
    ServicePortTest() {
        auto [host, device_side] = MemoryLink::pair(device.loop());
        host_link = std::move(host);
        host_link->on_receive([this](std::span<const std::uint8_t> bytes) {
            received.insert(received.end(), bytes.begin(), bytes.end());
        });
        device_end = device_side.get();
        port = std::make_unique<ServicePort>(device, std::move(device_side), GetParam());
    }

    void send(std::span<const std::uint8_t> bytes) {
        host_link->send(bytes);
        device.loop().run_for(1ms);
    }
    void send(std::initializer_list<std::uint8_t> bytes) {
        send(std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
    }

    /// A whole exchange as a well-behaved host does it; the answer, or nullopt.
    std::optional<service::Answer> exchange(const service::Frame& request) {
        received.clear();
        if (GetParam() == ServiceProtocol::Usb) {
            send(service::encode_v2(request));
            std::optional<service::Frame> answer;
            service::V2Decoder decoder([&answer](const service::Frame& f) { answer = f; });
            decoder.receive(received);
            return answer ? service::decode_answer(*answer) : std::nullopt;
        }
        std::optional<service::V1Completion> completion;
        service::V1HostLink host([this](std::span<const std::uint8_t> b) { host_link->send(b); },
                                 [&completion](const service::V1Completion& c) { completion = c; });
        host_link->on_receive(
            [&host](std::span<const std::uint8_t> bytes) { host.receive(bytes); });
        host.request(request);
        device.loop().run_for(10ms);
        host_link->on_receive([this](std::span<const std::uint8_t> bytes) {
            received.insert(received.end(), bytes.begin(), bytes.end());
        });
        if (!completion || completion->outcome != service::V1Outcome::Answered) {
            return std::nullopt;
        }
        return service::decode_answer(*completion->answer);
    }

    EposP device;
    std::unique_ptr<MemoryLink> host_link;
    MemoryLink* device_end = nullptr; ///< owned by the port
    std::vector<std::uint8_t> received;
    std::unique_ptr<ServicePort> port;
};

TEST_P(ServicePortTest, AnswersAWellFormedRequest) {
    const auto answer = exchange(read_device_type());
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->error, 0u);
    EXPECT_EQ(port->counters().requests, 1u);
    EXPECT_EQ(port->counters().answers, 1u);
}

TEST_P(ServicePortTest, AFrameThatStallsIsDroppedAfterTheFrameTimeout) {
    device.objects().set_as<std::uint16_t>(0x5005, 0, 200);
    const service::Frame request = read_device_type();
    if (GetParam() == ServiceProtocol::Usb) {
        auto bytes = service::encode_v2(request);
        send(std::span(bytes).first(5)); // stalls mid-frame
    } else {
        send({request.opcode, 0x01}); // the opcode, then Len-1 and nothing more
    }
    device.loop().run_for(150ms);
    EXPECT_EQ(port->counters().frame_errors, 0u) << "still within 0x5005";
    device.loop().run_for(100ms);
    EXPECT_EQ(port->counters().frame_errors, 1u);
    EXPECT_EQ(port->counters().requests, 0u);
    const auto answer = exchange(request);
    ASSERT_TRUE(answer) << "the port serves the next frame";
    EXPECT_EQ(answer->error, 0u);
}

TEST_P(ServicePortTest, EachByteRestartsTheFrameTimeout) {
    device.objects().set_as<std::uint16_t>(0x5005, 0, 100);
    const service::Frame request = read_device_type();
    std::vector<std::uint8_t> bytes = GetParam() == ServiceProtocol::Usb
                                          ? service::encode_v2(request)
                                          : std::vector<std::uint8_t>{request.opcode};
    if (GetParam() == ServiceProtocol::Rs232) {
        const auto rest = service::v1_frame_rest(request);
        bytes.insert(bytes.end(), rest.begin(), rest.end());
    }
    received.clear();
    for (const std::uint8_t byte : bytes) { // a slow host: 80 ms between bytes
        send({byte});
        device.loop().run_for(79ms);
    }
    device.loop().run_for(10ms);
    EXPECT_EQ(port->counters().frame_errors, 0u);
    EXPECT_EQ(port->counters().requests, 1u);
}

TEST_P(ServicePortTest, AHostThatHangsUpDuringAGatewayRequestGetsNoAnswerAndTheNextIsServed) {
    // Node 9 does not exist: the gateway's SDO waits 1 s for it.
    const service::Frame to_missing_node =
        service::encode_request(service::ReadObject{{std::nullopt, 9, 0x1000, 0}});
    if (GetParam() == ServiceProtocol::Usb) {
        send(service::encode_v2(to_missing_node));
    } else {
        send({to_missing_node.opcode});
        send(service::v1_frame_rest(to_missing_node));
    }
    device_end->close_from_peer(); // the host hangs up
    EXPECT_EQ(port->counters().hang_ups, 1u);
    received.clear();
    device.loop().run_for(2s);
    EXPECT_TRUE(received.empty()) << "the gateway's timeout is not answered to the next host";
    const auto answer = exchange(read_device_type());
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->error, 0u);
}

TEST_P(ServicePortTest, GarbageNeverStopsTheService) {
    device.objects().set_as<std::uint16_t>(0x5005, 0, 50);
    std::mt19937 random(14);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int burst = 0; burst < 50; ++burst) {
        std::vector<std::uint8_t> garbage(static_cast<std::size_t>(byte(random)));
        for (auto& b : garbage) {
            b = static_cast<std::uint8_t>(byte(random));
        }
        send(garbage);
    }
    device.loop().run_for(2s); // every frame the garbage began timed out, every answer went
    const auto answer = exchange(read_device_type());
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->error, 0u);
}

INSTANTIATE_TEST_SUITE_P(Protocols, ServicePortTest,
                         testing::Values(ServiceProtocol::Rs232, ServiceProtocol::Usb),
                         [](const testing::TestParamInfo<ServiceProtocol>& param) {
                             return param.param == ServiceProtocol::Rs232 ? "Rs232" : "Usb";
                         });

class ServicePortRs232 : public ServicePortTest {};

TEST_P(ServicePortRs232, ASecondHostsOpcodeWhileARequestRunsIsRefusedNotReady) {
    const service::Frame to_missing_node =
        service::encode_request(service::ReadObject{{std::nullopt, 9, 0x1000, 0}});
    send({to_missing_node.opcode});
    send(service::v1_frame_rest(to_missing_node));
    received.clear();
    send({0x10}); // another host's ReadObject while the gateway waits
    EXPECT_EQ(received, (std::vector<std::uint8_t>{service::kNotReady}));
    EXPECT_EQ(port->counters().refused_busy, 1u);
}

INSTANTIATE_TEST_SUITE_P(Protocols, ServicePortRs232, testing::Values(ServiceProtocol::Rs232),
                         [](const auto&) { return "Rs232"; });

TEST(ServicePortUsb, RequestsSentBackToBackAreAnsweredInOrder) {
    EposP device;
    auto [host, device_side] = MemoryLink::pair(device.loop());
    ServicePort port(device, std::move(device_side), ServiceProtocol::Usb);
    std::vector<service::Frame> answers;
    service::V2Decoder decoder([&answers](const service::Frame& f) { answers.push_back(f); });
    host->on_receive([&decoder](std::span<const std::uint8_t> bytes) { decoder.receive(bytes); });
    std::vector<std::uint8_t> burst;
    for (const std::uint16_t index : {std::uint16_t{0x1000}, std::uint16_t{0x1001},
                                      std::uint16_t{0x5005}, std::uint16_t{0x1234}}) {
        const auto bytes = service::encode_v2(
            service::encode_request(service::ReadObject{{std::nullopt, 0, index, 0}}));
        burst.insert(burst.end(), bytes.begin(), bytes.end());
    }
    host->send(burst);
    device.loop().run_for(10ms);
    ASSERT_EQ(answers.size(), 4u);
    EXPECT_EQ(service::decode_answer(answers[2])->data,
              (std::vector<std::uint8_t>{0xF4, 0x01, 0, 0})); // 0x5005 = 500
    EXPECT_EQ(service::decode_answer(answers[3])->error, 0x06020000u);
}

// An EPOS P with a simulated EPOS2 (node 3) on its CAN bus, booted, and a service port on a
// memory link.
class ServicePortGateway : public testing::Test {
protected:
    void SetUp() override {
        auto network = parse_network_file("slaves:\n  - {node: 3, kind: epos2}\n", "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        device.boot_networks();
        device.loop().run_for(2s);
        auto [host_end, device_end] = MemoryLink::pair(device.loop());
        host = std::move(host_end);
        device_side = std::move(device_end);
    }
    canopen::NmtState slave_state() const {
        return device.simulated_slaves()[0]->node().nmt_state();
    }

    EposP device;
    std::unique_ptr<MemoryLink> host;
    std::unique_ptr<MemoryLink> device_side; ///< for the port a test opens
};

TEST_F(ServicePortGateway, ReadsAnExternalEpos2AndSendsItNmtThroughTheLink) {
    ServicePort port(device, std::move(device_side), ServiceProtocol::Usb);
    std::vector<service::Frame> answers;
    service::V2Decoder decoder([&answers](const service::Frame& f) { answers.push_back(f); });
    host->on_receive([&decoder](std::span<const std::uint8_t> bytes) { decoder.receive(bytes); });

    host->send(service::encode_v2(
        service::encode_request(service::ReadObject{{std::nullopt, 3, 0x1018, 1}})));
    host->send(service::encode_v2(
        service::encode_request(service::SendNmtService{std::nullopt, 3, 0x02})));
    device.loop().run_for(20ms);
    ASSERT_EQ(answers.size(), 2u);
    const auto vendor = service::decode_answer(answers[0]);
    EXPECT_EQ(vendor->error, 0u);
    EXPECT_EQ(canopen::decode<std::uint32_t>(vendor->data), 0xFBu); // maxon's vendor-ID
    EXPECT_EQ(service::decode_answer(answers[1])->error, 0u);
    EXPECT_EQ(slave_state(), canopen::NmtState::Stopped);
}

// v1 sends no answer to SendNMTService: the exchange ends with the device's second 'O', and
// the command still reaches the node.
TEST_F(ServicePortGateway, AnNmtCommandOverRs232IsTakenWithoutAnAnswer) {
    ServicePort port(device, std::move(device_side), ServiceProtocol::Rs232);
    std::optional<service::V1Completion> completion;
    service::V1HostLink v1([this](std::span<const std::uint8_t> b) { host->send(b); },
                           [&completion](const service::V1Completion& c) { completion = c; });
    host->on_receive([&v1](std::span<const std::uint8_t> bytes) { v1.receive(bytes); });
    v1.request(service::encode_request(service::SendNmtService{std::nullopt, 3, 0x02}),
               /*expect_answer=*/false);
    device.loop().run_for(20ms);
    ASSERT_TRUE(completion);
    EXPECT_EQ(completion->outcome, service::V1Outcome::Sent);
    EXPECT_EQ(slave_state(), canopen::NmtState::Stopped);
    EXPECT_EQ(port.counters().answers, 0u);
    // The link is free for the next request.
    completion.reset();
    v1.request(service::encode_request(service::ReadObject{{std::nullopt, 0, 0x1000, 0}}));
    device.loop().run_for(20ms);
    ASSERT_TRUE(completion);
    EXPECT_EQ(completion->outcome, service::V1Outcome::Answered);
}

} // namespace
} // namespace eposp::device
