#include "../../../device/src/service/service_commands.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <optional>

// The commands of the service interface (docs/service-interface.md, "Commands") on an EPOS P
// with a simulated EPOS2 (node 2) on its CAN bus: the controller's own objects, the gateway to
// the nodes of both ports, NMT, CAN and LSS frames.

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using service::Answer;
using service::Network;
using service::ObjectAddress;

constexpr std::uint16_t kTestDomain = 0x3F00; // a DOMAIN the tests add to the dictionary

constexpr std::string_view kNetwork = R"(slaves:
  - {node: 2, kind: epos2, mandatory: false}
)";

class ServiceCommandsTest : public testing::Test {
protected:
    void SetUp() override {
        auto network = parse_network_file(kNetwork, "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        device.objects()
            .add_variable(kTestDomain, "Test domain", canopen::DataType::Domain,
                          canopen::Access::ReadWrite, {})
            .max_length = 200'000;
        device.boot_networks();
        device.loop().run_for(2s);
    }

    /// Runs `request` and the loop until it is answered.
    Answer run(const service::Request& request) {
        std::optional<service::Frame> answered;
        commands.execute(service::encode_request(request),
                         [&answered](service::Frame frame) { answered = std::move(frame); });
        for (int i = 0; i < 1000 && !answered; ++i) {
            device.loop().run_for(1ms);
        }
        EXPECT_TRUE(answered) << "no answer";
        if (!answered) {
            return Answer{0xFFFFFFFF, {}};
        }
        EXPECT_EQ(answered->opcode, service::kAnswerOpCode);
        return *service::decode_answer(*answered);
    }
    Answer run_frame(service::Frame frame) {
        std::optional<service::Frame> answered;
        commands.execute(frame, [&answered](service::Frame f) { answered = std::move(f); });
        EXPECT_TRUE(answered);
        return *service::decode_answer(*answered);
    }

    Answer read(ObjectAddress object) { return run(service::ReadObject{object}); }
    Answer write(ObjectAddress object, std::uint32_t value) {
        service::WriteObject request{object, {}};
        const auto bytes = canopen::encode(value);
        std::copy(bytes.begin(), bytes.end(), request.value.begin());
        return run(request);
    }
    static std::uint32_t value_of(const Answer& answer) {
        return canopen::decode<std::uint32_t>(answer.data);
    }

    /// Writes `value` to `object` by segments of up to 63 bytes; the error of the first refused
    /// step.
    std::uint32_t write_segmented(ObjectAddress object, const canopen::Bytes& value) {
        const Answer initiated =
            run(service::InitiateSegmentedWrite{object, static_cast<std::uint32_t>(value.size())});
        if (initiated.error != 0) {
            return initiated.error;
        }
        std::size_t sent = 0;
        bool toggle = false;
        do {
            const std::size_t length = std::min<std::size_t>(63, value.size() - sent);
            service::SegmentWrite segment;
            segment.control = {static_cast<std::uint8_t>(length), toggle,
                               sent + length < value.size()};
            segment.data.assign(value.begin() + static_cast<std::ptrdiff_t>(sent),
                                value.begin() + static_cast<std::ptrdiff_t>(sent + length));
            const Answer answer = run(segment);
            if (answer.error != 0) {
                return answer.error;
            }
            EXPECT_EQ(service::SegmentControl::decode(answer.data.at(0)),
                      (service::SegmentControl{static_cast<std::uint8_t>(length), toggle, false}));
            sent += length;
            toggle = !toggle;
        } while (sent < value.size());
        return 0;
    }

    /// Reads `object` by segments; the value, or the error of the first refused step.
    std::pair<std::uint32_t, canopen::Bytes> read_segmented(ObjectAddress object) {
        const Answer initiated = run(service::InitiateSegmentedRead{object});
        if (initiated.error != 0) {
            return {initiated.error, {}};
        }
        const auto length = canopen::decode<std::uint32_t>(initiated.data);
        canopen::Bytes value;
        bool toggle = false;
        for (;;) {
            const Answer segment = run(service::SegmentRead{std::nullopt, toggle});
            if (segment.error != 0) {
                return {segment.error, value};
            }
            const auto control = service::SegmentControl::decode(segment.data.at(0));
            EXPECT_EQ(control.toggle, toggle);
            value.insert(value.end(), segment.data.begin() + 1,
                         segment.data.begin() + 1 + control.length);
            toggle = !toggle;
            if (!control.more) {
                break;
            }
        }
        EXPECT_EQ(value.size(), length);
        return {0, value};
    }

    EposP device;
    ServiceCommands commands{device.loop(), service_parts(device)};
};

constexpr ObjectAddress own(std::uint16_t index, std::uint8_t sub_index = 0) {
    return {std::nullopt, 0, index, sub_index};
}

TEST_F(ServiceCommandsTest, ReadObjectOfNodeZeroReadsTheControllersDictionary) {
    const Answer answer = read(own(0x1000));
    EXPECT_EQ(answer.error, 0u);
    EXPECT_EQ(value_of(answer), device.objects().get_as<std::uint32_t>(0x1000, 0));
    EXPECT_EQ(answer.data.size(), 4u);
}

TEST_F(ServiceCommandsTest, WriteObjectStoresAsManyBytesAsTheObjectsType) {
    EXPECT_EQ(write(own(0x5005), 1234).error, 0u);
    EXPECT_EQ(device.objects().get_as<std::uint16_t>(0x5005, 0), 1234);
}

TEST_F(ServiceCommandsTest, RefusedAccessAnswersTheAbortCode) {
    EXPECT_EQ(read(own(0x1234)).error, 0x06020000u);
    EXPECT_EQ(read(own(0x1018, 9)).error, 0x06090011u);
    EXPECT_EQ(write(own(0x1000), 1).error, 0x06010002u);
}

TEST_F(ServiceCommandsTest, ReadObjectOfAValueLongerThanFourBytesAsksForASegmentedRead) {
    EXPECT_EQ(read(own(0x1008)).error, 0x06070012u); // the device name
}

TEST_F(ServiceCommandsTest, UnknownOpCodeIsAnIllegalCommand) {
    EXPECT_EQ(run_frame({0x7F, {0, 0}}).error, 0x0F00FFBFu);
}

TEST_F(ServiceCommandsTest, ParametersOfTheWrongLengthAreRefused) {
    EXPECT_EQ(run_frame({0x10, {0x00, 0x10}}).error, 0x06070010u);
    EXPECT_EQ(run_frame({0x10, {0x00, 0x10, 0, 0, 0, 0}}).error, 0x06070010u);
}

TEST_F(ServiceCommandsTest, NodeIdAbove127IsAWrongNodeId) {
    EXPECT_EQ(read({std::nullopt, 128, 0x1000, 0}).error, 0x0F00FFB9u);
    EXPECT_EQ(read({Network::ExternalPort, 0, 0x1000, 0}).error, 0x0F00FFB9u);
    EXPECT_EQ(read({static_cast<Network>(3), 1, 0x1000, 0}).error, 0x0F00FFB9u);
}

TEST_F(ServiceCommandsTest, SegmentedWriteAndReadOfA100KilobyteDomain) {
    canopen::Bytes value(100'000);
    for (std::size_t i = 0; i < value.size(); ++i) {
        value[i] = static_cast<std::uint8_t>(i * 7 + i / 251);
    }
    ASSERT_EQ(write_segmented(own(kTestDomain), value), 0u);
    EXPECT_EQ(device.objects().get(kTestDomain, 0), value);
    const auto [error, read_back] = read_segmented(own(kTestDomain));
    EXPECT_EQ(error, 0u);
    EXPECT_EQ(read_back, value);
}

TEST_F(ServiceCommandsTest, SegmentedReadOfAShortValueIsOneLastSegment) {
    const auto [error, name] = read_segmented(own(0x1008));
    EXPECT_EQ(error, 0u);
    EXPECT_EQ(std::string(name.begin(), name.end()), "EPOS P");
}

TEST_F(ServiceCommandsTest, SegmentWithoutInitiateIsRefused) {
    EXPECT_EQ(run(service::SegmentRead{std::nullopt, false}).error, 0x05040001u);
    EXPECT_EQ(run(service::SegmentWrite{std::nullopt, {1, false, false}, {0}}).error, 0x05040001u);
}

TEST_F(ServiceCommandsTest, ToggleNotAlternatedEndsTheTransfer) {
    ASSERT_EQ(run(service::InitiateSegmentedRead{own(0x1008)}).error, 0u);
    EXPECT_EQ(run(service::SegmentRead{std::nullopt, true}).error, 0x05030000u);
    EXPECT_EQ(run(service::SegmentRead{std::nullopt, false}).error, 0x05040001u);
}

TEST_F(ServiceCommandsTest, SegmentedWriteLongerOrShorterThanAnnouncedIsRefused) {
    ASSERT_EQ(run(service::InitiateSegmentedWrite{own(kTestDomain), 2}).error, 0u);
    EXPECT_EQ(run(service::SegmentWrite{std::nullopt, {3, false, false}, {1, 2, 3}}).error,
              0x06070012u);
    ASSERT_EQ(run(service::InitiateSegmentedWrite{own(kTestDomain), 4}).error, 0u);
    EXPECT_EQ(run(service::SegmentWrite{std::nullopt, {3, false, false}, {1, 2, 3}}).error,
              0x06070013u);
}

TEST_F(ServiceCommandsTest, InitiateSegmentedWriteBeyondTheObjectsLimitIsRefusedAtOnce) {
    EXPECT_EQ(run(service::InitiateSegmentedWrite{own(kTestDomain), 300'000}).error, 0x06070012u);
}

TEST_F(ServiceCommandsTest, GatewayReadsAndWritesANodeOnTheCanBus) {
    const Answer type = read({std::nullopt, 2, 0x1000, 0});
    EXPECT_EQ(type.error, 0u);
    EXPECT_EQ(value_of(type), 0x00020192u);
    // 0x6060 is INTEGER8: the 4 bytes go without a size and the drive takes one.
    EXPECT_EQ(write({std::nullopt, 2, 0x6060, 0}, 1).error, 0u);
    EXPECT_EQ(device.simulated_slaves()[0]->node().dictionary().get_as<std::int8_t>(0x6060, 0), 1);
    EXPECT_EQ(read({std::nullopt, 2, 0x1234, 0}).error, 0x06020000u);
}

TEST_F(ServiceCommandsTest, GatewayToAMissingNodeTimesOut) {
    EXPECT_EQ(read({std::nullopt, 9, 0x1000, 0}).error, 0x05040000u);
}

TEST_F(ServiceCommandsTest, NetworkAddressedOpcodesReachTheInternalEpos2AndTheController) {
    const Answer internal = read({Network::InternalPort, 1, 0x1000, 0});
    EXPECT_EQ(internal.error, 0u);
    EXPECT_EQ(value_of(internal), 0x00020192u);
    const Answer controller = read({Network::Controller, 0, 0x1000, 0});
    EXPECT_EQ(value_of(controller), device.objects().get_as<std::uint32_t>(0x1000, 0));
    EXPECT_EQ(write({Network::ExternalPort, 2, 0x6060, 0}, 3).error, 0u);
    EXPECT_EQ(device.simulated_slaves()[0]->node().dictionary().get_as<std::int8_t>(0x6060, 0), 3);
}

TEST_F(ServiceCommandsTest, GatewaySegmentedReadOfANodesString) {
    const auto [error, name] = read_segmented({std::nullopt, 2, 0x1008, 0});
    EXPECT_EQ(error, 0u);
    const canopen::Bytes expected = device.simulated_slaves()[0]->node().dictionary().get(0x1008, 0);
    EXPECT_EQ(name, expected);
    EXPECT_GT(name.size(), 4u);
}

TEST_F(ServiceCommandsTest, NmtServiceStartsAndStopsANode) {
    auto& slave = *device.simulated_slaves()[0];
    EXPECT_EQ(run(service::SendNmtService{std::nullopt, 2, 0x02}).error, 0u);
    device.loop().run_for(10ms);
    EXPECT_EQ(slave.node().nmt_state(), canopen::NmtState::Stopped);
    EXPECT_EQ(run(service::SendNmtService{std::nullopt, 2, 0x80}).error, 0u);
    device.loop().run_for(10ms);
    EXPECT_EQ(slave.node().nmt_state(), canopen::NmtState::PreOperational);
    EXPECT_EQ(run(service::SendNmtService{std::nullopt, 2, 0x55}).error, 0x06090030u);
    EXPECT_EQ(run(service::SendNmtService{std::nullopt, 200, 0x01}).error, 0x0F00FFB9u);
}

class ServiceGatewayFrames : public ServiceCommandsTest {
protected:
    void SetUp() override {
        ServiceCommandsTest::SetUp();
        probe->on_receive([this](const can::Frame& frame) { received.push_back(frame); });
    }
    std::unique_ptr<can::VirtualPort> probe = device.external_bus().connect("probe");
    std::vector<can::Frame> received;
};

TEST_F(ServiceGatewayFrames, SendCanFrameSendsItOnTheCanBus) {
    EXPECT_EQ(run(service::SendCanFrame{std::nullopt, 0x321, 3, {1, 2, 3, 4, 5, 6, 7, 8}}).error,
              0u);
    device.loop().run_for(1ms);
    EXPECT_THAT(received, testing::Contains(can::Frame::data_frame(0x321, {1, 2, 3})));
    EXPECT_EQ(run(service::SendCanFrame{std::nullopt, 0x800, 0, {}}).error, 0x06090030u);
}

TEST_F(ServiceGatewayFrames, RequestCanFrameAnswersWithTheDataOfTheAnsweringFrame) {
    probe->on_receive([this](const can::Frame& frame) {
        if (frame.remote && frame.id == 0x2AA) {
            probe->send(can::Frame::data_frame(0x2AA, {9, 8, 7}));
        }
    });
    const Answer answer = run(service::RequestCanFrame{std::nullopt, 0x2AA, 3});
    EXPECT_EQ(answer.error, 0u);
    EXPECT_EQ(answer.data, (canopen::Bytes{9, 8, 7, 0, 0, 0, 0, 0}));
    EXPECT_EQ(run(service::RequestCanFrame{std::nullopt, 0x2AB, 3}).error, 0x05040000u);
}

TEST_F(ServiceGatewayFrames, LssResponseThatCameBeforeTheReadIsKept) {
    probe->on_receive([this](const can::Frame& frame) {
        if (frame.id == 0x7E5) {
            probe->send(can::Frame::data_frame(0x7E4, {0x44, 0, 0, 0, 0, 0, 0, 0}));
        }
    });
    EXPECT_EQ(run(service::SendLssFrame{std::nullopt, {0x04, 0x01}}).error, 0u);
    device.loop().run_for(5ms);
    const Answer response = run(service::ReadLssFrame{std::nullopt, 100});
    EXPECT_EQ(response.error, 0u);
    EXPECT_EQ(response.data.at(0), 0x44);
    EXPECT_EQ(run(service::ReadLssFrame{std::nullopt, 50}).error, 0x05040000u);
}

TEST_F(ServiceCommandsTest, AbandonedGatewayRequestIsNeverAnswered) {
    bool answered = false;
    commands.execute(service::encode_request(service::ReadObject{{std::nullopt, 9, 0x1000, 0}}),
                     [&answered](service::Frame) { answered = true; });
    commands.abandon();
    device.loop().run_for(3s);
    EXPECT_FALSE(answered);
    EXPECT_EQ(read({std::nullopt, 2, 0x1000, 0}).error, 0u);
}

} // namespace
} // namespace eposp::device
