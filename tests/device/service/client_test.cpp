// The service client against an EPOS P in the same process, over a pair of links in memory, in
// virtual time: every operation on both protocols, refusals with their abort code, timeouts and
// v1's 'F' retries.
#include "../compile_program.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/service/client.hpp"
#include "eposp/service/crc.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "eposp/vm/image_format.hpp"
#include "memory_link_pair.hpp"

#include <gtest/gtest.h>
#include <optional>

namespace eposp::service {
namespace {

using namespace std::chrono_literals;
using test::MemoryLink;
using Bytes = std::vector<std::uint8_t>;

constexpr const char* kCounter = R"(
    PROGRAM Main
    VAR counter : DINT; END_VAR
    counter := counter + 1;
    END_PROGRAM)";

ObjectAddress at(std::uint16_t index, std::uint8_t sub_index) {
    ObjectAddress address;
    address.index = index;
    address.sub_index = sub_index;
    return address;
}

ClientSettings settings_for(Protocol protocol) {
    ClientSettings settings;
    settings.protocol = protocol;
    return settings;
}

// An EPOS P serving one end of a memory link pair, a client on the other.
class ClientTest : public ::testing::TestWithParam<Protocol> {
protected:
    ClientTest() {
        auto [host, device] = MemoryLink::pair(device_.loop());
        host_ = std::move(host);
        port_.emplace(device_, std::move(device),
                      GetParam() == Protocol::V1 ? device::ServiceProtocol::Rs232
                                                 : device::ServiceProtocol::Usb);
        client_.emplace(device_.loop(), *host_, settings_for(GetParam()));
    }
    ~ClientTest() override {
        client_.reset();
        port_.reset();
    }

    // Runs the loop until the operation `start` began has completed.
    template <typename T, typename Start>
    ClientResult<T> wait(Start start) {
        std::optional<ClientResult<T>> result;
        start([&](const ClientResult<T>& done) { result.emplace(done); });
        while (!result && device_.loop().now() < deadline()) {
            device_.loop().run_for(1ms);
        }
        return result ? *result
                      : ClientResult<T>(ClientError{ClientError::Kind::NoAnswer, 0, "test"});
    }
    core::TimePoint deadline() const { return started_ + 60s; }

    ClientResult<std::array<std::uint8_t, 4>> read(std::uint16_t index, std::uint8_t sub) {
        return wait<std::array<std::uint8_t, 4>>(
            [&](auto done) { client_->read_object(at(index, sub), done); });
    }
    ClientResult<Done> write(std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
        return wait<Done>([&](auto done) {
            client_->write_object(at(index, sub), canopen::encode_array(value), done);
        });
    }
    ClientResult<Done> write_segmented(std::uint16_t index, std::uint8_t sub, Bytes value,
                                       Client::Progress progress = {}) {
        return wait<Done>(
            [&](auto done) { client_->write_segmented(at(index, sub), value, done, progress); });
    }
    ClientResult<Bytes> read_segmented(std::uint16_t index, std::uint8_t sub) {
        return wait<Bytes>([&](auto done) { client_->read_segmented(at(index, sub), done); });
    }
    static std::uint32_t u32(const std::array<std::uint8_t, 4>& bytes) {
        return canopen::decode<std::uint32_t>(bytes);
    }
    static Bytes text(std::string_view value) { return Bytes(value.begin(), value.end()); }

    device::EposP device_;
    core::TimePoint started_ = device_.loop().now();
    std::unique_ptr<MemoryLink> host_;
    std::optional<device::ServicePort> port_;
    std::optional<Client> client_;
};

TEST_P(ClientTest, ReadsAnObjectOfTheDevice) {
    const auto value = read(0x1000, 0);
    ASSERT_TRUE(value) << value.error().message;
    EXPECT_EQ(u32(*value), device::kDeviceType);
}

TEST_P(ClientTest, WritesAnObjectAndReadsItBack) {
    const auto written = write(0x5005, 0, 750); // the frame timeout, UNSIGNED16
    ASSERT_TRUE(written) << written.error().message;
    const auto value = read(0x5005, 0);
    ASSERT_TRUE(value) << value.error().message;
    EXPECT_EQ(u32(*value), 750u);
}

TEST_P(ClientTest, ARefusalCarriesTheAbortCodeAndItsText) {
    const auto value = read(0x1234, 0);
    ASSERT_FALSE(value);
    EXPECT_EQ(value.error().kind, ClientError::Kind::Refused);
    EXPECT_EQ(value.error().code, 0x06020000u);
    EXPECT_EQ(value.error().message, "0x06020000 Object does not exist Error");
    EXPECT_FALSE(client_->busy());
}

TEST_P(ClientTest, DownloadsAProgramInSegmentsStartsItAndWatchesAVariable) {
    const Bytes image = vm::write_image(device::compile_program(kCounter));
    std::vector<std::size_t> progress;
    const auto downloaded =
        write_segmented(0x1F50, 1, image, [&](std::size_t done, std::size_t total) {
            EXPECT_EQ(total, image.size());
            progress.push_back(done);
        });
    ASSERT_TRUE(downloaded) << downloaded.error().message;
    EXPECT_EQ(progress.size(), (image.size() + 62) / 63); // segments of 63 bytes
    EXPECT_EQ(progress.back(), image.size());

    const auto stored = read_segmented(0x1F50, 1);
    ASSERT_TRUE(stored) << stored.error().message;
    EXPECT_EQ(*stored, image);

    ASSERT_TRUE(write(device::kProgramControlIndex, 0, 1)); // cold start
    device_.loop().run_for(100ms);
    ASSERT_TRUE(write_segmented(device::kVariableAccessIndex, 1, text("Main.counter")));
    const auto counter = read_segmented(device::kVariableAccessIndex, 2);
    ASSERT_TRUE(counter) << counter.error().message;
    EXPECT_GE(std::stoi(std::string(counter->begin(), counter->end())), 10);
}

TEST_P(ClientTest, ARefusedDownloadSaysWhy) {
    const auto downloaded = write_segmented(0x1F50, 1, text("not a program image"));
    ASSERT_FALSE(downloaded);
    EXPECT_EQ(downloaded.error().kind, ClientError::Kind::Refused);
    EXPECT_EQ(downloaded.error().code, 0x08000020u); // TransferOrStore
    EXPECT_FALSE(client_->busy());
    // The client goes on serving.
    EXPECT_TRUE(read(0x1000, 0));
}

INSTANTIATE_TEST_SUITE_P(BothProtocols, ClientTest, ::testing::Values(Protocol::V1, Protocol::V2),
                         [](const ::testing::TestParamInfo<Protocol>& param_info) {
                             return std::string(param_info.param == Protocol::V1 ? "V1" : "V2");
                         });

// A client whose link leads to `device`, a stand-in that answers as a test wants.
struct ClientWithoutDevice {
    explicit ClientWithoutDevice(Protocol protocol) {
        auto [h, d] = MemoryLink::pair(loop);
        host = std::move(h);
        device = std::move(d);
        client.emplace(loop, *host, settings_for(protocol));
    }
    ClientResult<std::array<std::uint8_t, 4>> read() {
        std::optional<ClientResult<std::array<std::uint8_t, 4>>> result;
        client->read_object(at(0x1000, 0), [&](const auto& done) { result.emplace(done); });
        loop.run_for(10s);
        return result.value();
    }

    core::EventLoop loop;
    std::unique_ptr<MemoryLink> host;
    std::unique_ptr<MemoryLink> device;
    std::optional<Client> client;
};

TEST(Client, NoDeviceIsATimeoutAfterTheAnswerTimeAndTheLineTime) {
    for (const Protocol protocol : {Protocol::V1, Protocol::V2}) {
        ClientWithoutDevice setup(protocol);
        std::optional<core::TimePoint> failed;
        setup.client->read_object(at(0x1000, 0), [&](const auto& done) {
            EXPECT_EQ(done.error().kind, ClientError::Kind::NoAnswer);
            EXPECT_NE(done.error().message.find("no answer from memory host"), std::string::npos);
            failed = setup.loop.now();
        });
        setup.loop.run_for(10s);
        ASSERT_TRUE(failed);
        EXPECT_GE(*failed - core::TimePoint{}, 1s);
        EXPECT_LT(*failed - core::TimePoint{}, 1100ms);
        EXPECT_FALSE(setup.client->busy());
    }
}

TEST(Client, V1RetriesARequestTheDeviceRefusesWithF) {
    ClientWithoutDevice setup(Protocol::V1);
    int opcodes = 0;
    setup.device->on_receive([&](std::span<const std::uint8_t> bytes) {
        for (const std::uint8_t byte : bytes) {
            EXPECT_EQ(byte, 0x10); // ReadObject, again and again
            ++opcodes;
            const std::uint8_t not_ready = 'F';
            setup.device->send(std::span(&not_ready, 1));
        }
    });
    const auto result = setup.read();
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().kind, ClientError::Kind::Link);
    EXPECT_EQ(opcodes, 4); // the request and 3 retries
    EXPECT_NE(result.error().message.find("'F' 4 times"), std::string::npos);
}

TEST(Client, V1AnswersAfterARetry) {
    ClientWithoutDevice setup(Protocol::V1);
    int opcodes = 0;
    std::vector<std::uint8_t> received;
    setup.device->on_receive([&](std::span<const std::uint8_t> bytes) {
        received.insert(received.end(), bytes.begin(), bytes.end());
        if (received.size() == 1) {
            ++opcodes;
            const std::uint8_t reply = opcodes == 1 ? 'F' : 'O';
            received.clear();
            setup.device->send(std::span(&reply, 1));
        }
    });
    const auto result = setup.read();
    // The second opcode was taken ('O'); the stand-in never answers the frame: a timeout.
    EXPECT_EQ(opcodes, 2);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().kind, ClientError::Kind::NoAnswer);
}

TEST(Client, AV2AnswerWithAWrongCrcEndsTheRequestAtOnce) {
    ClientWithoutDevice setup(Protocol::V2);
    setup.device->on_receive([&](std::span<const std::uint8_t>) {
        std::vector<std::uint8_t> answer = encode_v2(encode_answer(Answer{}));
        answer.back() ^= 0x01;
        setup.device->send(answer);
    });
    std::optional<ClientResult<std::array<std::uint8_t, 4>>> result;
    setup.client->read_object(at(0x1000, 0), [&](const auto& done) { result.emplace(done); });
    setup.loop.run_for(10ms);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->error().kind, ClientError::Kind::Link);
    EXPECT_EQ(result->error().message, "the answer arrived with a wrong CRC");
}

TEST(Client, AV1AnswerWithAWrongCrcIsRefusedWithF) {
    ClientWithoutDevice setup(Protocol::V1);
    const Frame answer = encode_answer(Answer{});
    int chunks = 0;
    std::vector<std::uint8_t> to_device;
    setup.device->on_receive([&](std::span<const std::uint8_t> bytes) {
        to_device.insert(to_device.end(), bytes.begin(), bytes.end());
        switch (chunks++) {
        case 0: // the opcode
            setup.device->send(std::vector<std::uint8_t>{'O'});
            break;
        case 1: // Len-1, data, CRC: taken; the answer begins
            setup.device->send(std::vector<std::uint8_t>{'O', kAnswerOpCode});
            break;
        case 2: { // the host's 'O': the rest of the answer, its CRC wrong
            std::vector<std::uint8_t> rest{static_cast<std::uint8_t>(answer.words() - 1)};
            rest.insert(rest.end(), answer.data.begin(), answer.data.end());
            const std::uint16_t crc = v1_crc(answer) ^ 0x0001;
            rest.push_back(static_cast<std::uint8_t>(crc));
            rest.push_back(static_cast<std::uint8_t>(crc >> 8));
            setup.device->send(rest);
            break;
        }
        default:
            break;
        }
    });
    std::optional<ClientResult<std::array<std::uint8_t, 4>>> result;
    setup.client->read_object(at(0x1000, 0), [&](const auto& done) { result.emplace(done); });
    setup.loop.run_for(10ms);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->error().kind, ClientError::Kind::Link);
    EXPECT_EQ(result->error().message, "the answer arrived with a wrong CRC");
    EXPECT_EQ(to_device.back(), 'F'); // the host said so
}

// A device whose segments never end: the length it announced bounds them, or without one the
// longest DOMAIN (1 MiB: 16644 segments of 63 bytes, the next one too many).
TEST(Client, ASegmentedReadTakesNoMoreThanTheAnnouncedLength) {
    for (const bool announced : {true, false}) {
        ClientWithoutDevice setup(Protocol::V2);
        int requests = 0;
        setup.device->on_receive([&](std::span<const std::uint8_t>) {
            Answer answer{error::kNone, {}};
            if (requests == 0 && announced) {
                answer.data = {100, 0, 0, 0}; // 100 bytes
            } else if (requests > 0) {
                const bool toggle = (requests - 1) % 2 == 1;
                answer.data.assign(1 + SegmentControl::kMaxLength, 0x55);
                answer.data[0] = SegmentControl{63, toggle, true}.encode();
            }
            ++requests;
            setup.device->send(encode_v2(encode_answer(answer)));
        });
        std::optional<ClientResult<std::vector<std::uint8_t>>> result;
        setup.client->read_segmented(at(0x1F50, 1),
                                     [&](const auto& done) { result.emplace(done); });
        setup.loop.run_for(100ms);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->error().kind, ClientError::Kind::Link);
        EXPECT_EQ(result->error().message,
                  announced ? "the segments bring more than the 100 bytes announced"
                            : "the segments bring more than the 1048576 bytes a value may have");
        EXPECT_EQ(requests, announced ? 3 : 1 + 16645); // the initiate and the segments
        EXPECT_FALSE(setup.client->busy());
    }
}

// On v2 a segmented write keeps 8 segments in flight (the device answers them in order).
// A device that stops answering after the initiate sees exactly the window, then the client
// times out.
TEST(Client, AV2SegmentedWriteKeepsEightSegmentsInFlight) {
    ClientWithoutDevice setup(Protocol::V2);
    std::vector<std::uint8_t> opcodes;
    V2Decoder decoder([&](const Frame& request) {
        opcodes.push_back(request.opcode);
        if (request.opcode == 0x13) { // only the initiate is answered
            setup.device->send(encode_v2(encode_answer(Answer{})));
        }
    });
    setup.device->on_receive([&](std::span<const std::uint8_t> bytes) { decoder.receive(bytes); });
    std::optional<ClientResult<Done>> result;
    setup.client->write_segmented(at(0x1F50, 1), std::vector<std::uint8_t>(2000, 0x90),
                                  [&](const auto& done) { result.emplace(done); });
    setup.loop.run_for(100ms);
    EXPECT_EQ(opcodes.size(), 1u + 8u);
    setup.loop.run_for(2s);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->error().kind, ClientError::Kind::NoAnswer);
    EXPECT_FALSE(setup.client->busy());
}

// A segment refused while later ones are in flight ends the write with that refusal once
// their answers are in, and sends nothing more: the next request gets its own answer.
TEST(Client, ARefusedSegmentEndsAPipelinedWriteAndTheNextAnswerIsTheNextRequests) {
    ClientWithoutDevice setup(Protocol::V2);
    std::size_t segments = 0;
    V2Decoder decoder([&](const Frame& request) {
        Answer answer;
        if (request.opcode == 0x15) {
            const bool toggle = segments++ % 2 == 1;
            answer.error = segments == 3 ? 0x08000020u : error::kNone;
            answer.data = {SegmentControl{63, toggle, false}.encode()};
        } else if (request.opcode == 0x10) {
            answer.data = {0x34, 0x12, 0, 0};
        }
        setup.device->send(encode_v2(encode_answer(answer)));
    });
    setup.device->on_receive([&](std::span<const std::uint8_t> bytes) { decoder.receive(bytes); });
    std::optional<ClientResult<Done>> result;
    setup.client->write_segmented(at(0x1F50, 1), std::vector<std::uint8_t>(63 * 20, 1),
                                  [&](const auto& done) { result.emplace(done); });
    setup.loop.run_for(100ms);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->error().code, 0x08000020u);
    EXPECT_LE(segments, 3u + 8u) << "nothing is sent after the refusal came";
    EXPECT_FALSE(setup.client->busy());
    const auto value = setup.read();
    ASSERT_TRUE(value) << value.error().message;
    EXPECT_EQ((*value)[0], 0x34);
}

TEST(Client, ALinkThatClosesEndsTheRequest) {
    ClientWithoutDevice setup(Protocol::V2);
    std::optional<ClientResult<std::array<std::uint8_t, 4>>> result;
    setup.client->read_object(at(0x1000, 0), [&](const auto& done) { result.emplace(done); });
    setup.host->close_from_peer();
    ASSERT_TRUE(result);
    EXPECT_EQ(result->error().kind, ClientError::Kind::Link);
    EXPECT_NE(result->error().message.find("the device went away"), std::string::npos);
}

TEST(Client, StartingASecondOperationWhileBusyIsAProgrammingError) {
    ClientWithoutDevice setup(Protocol::V2);
    setup.client->read_object(at(0x1000, 0), [](const auto&) {});
    EXPECT_THROW(setup.client->read_object(at(0x1000, 0), [](const auto&) {}), std::logic_error);
}

} // namespace
} // namespace eposp::service
