#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "eposp/service/commands.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "eposp/test/test_directory.hpp"
#include "memory_link_pair.hpp"

#include <gtest/gtest.h>

// The USB port of a simulated ESCON2 (ESCON2 FW spec 5.1, 7.2) on an in-memory link: the object
// commands of maxon's serial protocol v2 served by the object server the EPOS P's ports use,
// answered with the abort codes of table 111; the commands of a CAN gateway are unknown to it.

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using service::Answer;
using service::ObjectAddress;
using service::test::MemoryLink;

constexpr std::uint32_t kCommandUnknown = 0x0504'0001;
constexpr std::uint32_t kToggleError = 0x0503'0000;
constexpr std::uint32_t kCrcError = 0x0504'0004;
constexpr std::uint32_t kReadOnly = 0x0601'0002;
constexpr std::uint32_t kObjectDoesNotExist = 0x0602'0000;
constexpr std::uint32_t kTooHigh = 0x0607'0012;
constexpr std::uint32_t kValueRange = 0x0609'0030;
constexpr std::uint32_t kSegmentedTransferExpected = 0x0F00'FFC1;

ObjectAddress object(std::uint16_t index, std::uint8_t sub_index = 0, std::uint8_t node = 0) {
    return ObjectAddress{std::nullopt, node, index, sub_index};
}

drives::escon2::Escon2DriveConfig drive_config() {
    drives::escon2::Escon2DriveConfig config;
    config.dictionary.parameter_file = test::test_file("escon2-parameters.bin");
    return config;
}

class Escon2ServicePort : public testing::Test {
protected:
    Escon2ServicePort() {
        drive.start();
        auto [host, device_side] = MemoryLink::pair(loop);
        host_link = std::move(host);
        host_link->on_receive(
            [this](std::span<const std::uint8_t> bytes) { decoder.receive(bytes); });
        port = std::make_unique<ServicePort>(loop, drive, std::move(device_side));
    }

    /// Sends `bytes` as a host does and runs the loop until the answer is in (or 100 ms).
    std::optional<Answer> exchange_bytes(const std::vector<std::uint8_t>& bytes) {
        answers.clear();
        host_link->send(bytes);
        for (int i = 0; i < 100 && answers.empty(); ++i) {
            loop.run_for(1ms);
        }
        if (answers.empty()) {
            return std::nullopt;
        }
        return service::decode_answer(answers.front());
    }
    Answer exchange(const service::Frame& request) {
        const auto answer = exchange_bytes(service::encode_v2(request));
        EXPECT_TRUE(answer) << "no answer to opcode " << int{request.opcode};
        return answer.value_or(Answer{0xFFFF'FFFF, {}});
    }
    Answer run(const service::Request& request) {
        return exchange(service::encode_request(request));
    }
    Answer read(ObjectAddress address) { return run(service::ReadObject{address}); }
    template <typename T>
    Answer write(ObjectAddress address, T value) {
        service::WriteObject request{address, {}};
        const auto bytes = canopen::encode(value);
        std::copy(bytes.begin(), bytes.end(), request.value.begin());
        return run(request);
    }
    template <typename T>
    static T value_of(const Answer& answer) {
        return canopen::decode<T>(std::span(answer.data).first(sizeof(T)));
    }

    core::EventLoop loop;
    drives::escon2::Escon2Drive drive{loop, drive_config()};
    std::unique_ptr<MemoryLink> host_link;
    std::vector<service::Frame> answers;
    service::V2Decoder decoder{[this](const service::Frame& frame) {
        answers.push_back(frame);
    }};
    std::unique_ptr<ServicePort> port;
};

// 6.2.1, 6.2.60, table 111: the objects read and written as the dictionary has them, the
// dictionary's refusals answered with their abort codes.
TEST_F(Escon2ServicePort, ReadsAndWritesObjectsWithTheAbortCodesOfTable111) {
    const Answer device_type = read(object(0x1000));
    ASSERT_EQ(device_type.error, 0u);
    EXPECT_EQ(value_of<std::uint32_t>(device_type), 0x0002'0192u);
    EXPECT_EQ(write(object(0x210C, 2), std::uint32_t{0xCAFE'F00D}).error, 0u);
    EXPECT_EQ(drive.objects().get_as<std::uint32_t>(0x210C, 2), 0xCAFE'F00Du);
    EXPECT_EQ(value_of<std::uint32_t>(read(object(0x210C, 2))), 0xCAFE'F00Du);
    // The mode is an INTEGER8: the object takes one of the 4 bytes.
    EXPECT_EQ(write(object(0x6060), std::int32_t{-120}).error, 0u);
    EXPECT_EQ(value_of<std::int8_t>(read(object(0x6060))), -120);

    EXPECT_EQ(write(object(0x1000), std::uint32_t{0}).error, kReadOnly);
    EXPECT_EQ(read(object(0x5555)).error, kObjectDoesNotExist);
    EXPECT_EQ(read(object(0x1F50, 1)).error, kObjectDoesNotExist) << "no program to download";
    EXPECT_EQ(read(object(0x1000, 0, 3)).error, kValueRange) << "no node but itself";
    EXPECT_EQ(read(object(0x2100, 1)).error, kSegmentedTransferExpected) << "UNSIGNED64";
}

TEST_F(Escon2ServicePort, LongValuesMoveBySegmentedTransfers) {
    ASSERT_EQ(run(service::InitiateSegmentedRead{object(0x1008)}).error, 0u);
    std::string name;
    for (bool toggle = false, more = true; more; toggle = !toggle) {
        const Answer segment = run(service::SegmentRead{std::nullopt, toggle});
        ASSERT_EQ(segment.error, 0u);
        const auto control = service::SegmentControl::decode(segment.data.at(0));
        EXPECT_EQ(control.toggle, toggle);
        name.append(segment.data.begin() + 1, segment.data.begin() + 1 + control.length);
        more = control.more;
    }
    canopen::Bytes stored;
    ASSERT_EQ(drive.objects().read(0x1008, 0, stored), canopen::AbortCode::None);
    EXPECT_EQ(name, std::string(stored.begin(), stored.end()));
    EXPECT_NE(name.find("ESCON2"), std::string::npos) << name;

    // A segment without a transfer, a toggle that does not alternate.
    EXPECT_EQ(run(service::SegmentRead{std::nullopt, false}).error, kCommandUnknown);
    ASSERT_EQ(run(service::InitiateSegmentedRead{object(0x2100, 1)}).error, 0u);
    EXPECT_EQ(run(service::SegmentRead{std::nullopt, true}).error, kToggleError);

    // Writes: the object's size and access decide at the initiate.
    EXPECT_EQ(run(service::InitiateSegmentedWrite{object(0x210C, 1), 6}).error, kTooHigh);
    EXPECT_EQ(run(service::InitiateSegmentedWrite{object(0x2100, 1), 8}).error, kReadOnly);
    ASSERT_EQ(run(service::InitiateSegmentedWrite{object(0x210C, 1), 4}).error, 0u);
    service::SegmentWrite segment;
    segment.control = {4, false, false};
    segment.data = {0x78, 0x56, 0x34, 0x12};
    ASSERT_EQ(run(segment).error, 0u);
    EXPECT_EQ(drive.objects().get_as<std::uint32_t>(0x210C, 1), 0x1234'5678u);
}

// What the ESCON2 has no use for (it has no CAN, no NMT, no LSS, no program): "command unknown".
TEST_F(Escon2ServicePort, TheCommandsOfACanGatewayAreUnknown) {
    const std::vector<service::Request> gateway_commands = {
        service::SendNmtService{std::nullopt, 0, 1},
        service::SendCanFrame{std::nullopt, 0x601, 8, {}},
        service::RequestCanFrame{std::nullopt, 0x701, 1},
        service::SendLssFrame{std::nullopt, {0x04, 0x01}},
        service::ReadLssFrame{std::nullopt, 10},
        service::ReadObject{{service::Network::Controller, 0, 0x1000, 0}},
    };
    for (const service::Request& request : gateway_commands) {
        const service::Frame frame = service::encode_request(request);
        EXPECT_EQ(exchange(frame).error, kCommandUnknown) << "opcode " << int{frame.opcode};
    }
    EXPECT_EQ(exchange(service::Frame{0x7F, {}}).error, kCommandUnknown);
    EXPECT_EQ(port->counters().answers, gateway_commands.size() + 1);
}

// Table 111: a frame whose CRC failed is answered 0x05040004, and the port serves the next.
TEST_F(Escon2ServicePort, AFrameWithAWrongCrcIsAnsweredWithTheCrcError) {
    auto bytes = service::encode_v2(service::encode_request(service::ReadObject{object(0x1000)}));
    bytes.at(4) ^= 0x01; // the index' low byte, 0x00: 0x1001 does not match the CRC
    const auto answer = exchange_bytes(bytes);
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->error, kCrcError);
    EXPECT_EQ(port->counters().frame_errors, 1u);
    EXPECT_EQ(read(object(0x1000)).error, 0u);
}

// 2.2, 3.3: a host configures and runs the ESCON2 over USB as ESCON Studio would: controlword,
// velocity set value, and reads the velocity back.
TEST_F(Escon2ServicePort, AHostEnablesTheDriveAndSetsItsVelocityOverUsb) {
    ASSERT_EQ(write(object(0x6040), std::uint16_t{0x0006}).error, 0u); // Shutdown
    ASSERT_EQ(write(object(0x6040), std::uint16_t{0x000F}).error, 0u); // Enable operation
    ASSERT_EQ(write(object(0x60FF), std::int32_t{1000}).error, 0u);
    loop.run_for(1s);
    EXPECT_EQ(value_of<std::uint16_t>(read(object(0x6041))) & 0x006F, 0x0027)
        << "Operation enabled";
    EXPECT_NEAR(value_of<std::int32_t>(read(object(0x30D3, 1))), 1000, 15)
        << "averaged actual velocity";
}

// 6.2.5: "save" over USB keeps a parameter in the device's memory across a power-up.
TEST_F(Escon2ServicePort, ParametersSavedOverUsbSurviveAPowerCycle) {
    ASSERT_EQ(write(object(0x210C, 4), std::uint32_t{4242}).error, 0u);
    ASSERT_EQ(write(object(0x1010, 1), std::uint32_t{0x6576'6173}).error, 0u); // "save"
    port.reset();
    core::EventLoop other_loop;
    drives::escon2::Escon2Drive powered_up(other_loop, drive_config());
    powered_up.start();
    EXPECT_EQ(powered_up.objects().get_as<std::uint32_t>(0x210C, 4), 4242u);
}

} // namespace
} // namespace eposp::device
