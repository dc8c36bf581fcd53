// The EPOS2 dictionary as a master sees it: a canopen::Node runs on it on a virtual bus, an SDO
// client reads and writes it, PDOs carry its default mappings. Abort codes as EPOS2 FW spec
// table 4-12 lists them.
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/test/test_directory.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::Bytes;
using canopen::encode;

constexpr canopen::NodeId kNode = 3;

struct Upload {
    AbortCode code = AbortCode::None;
    Bytes value;
};

class Epos2DictionaryOnBus : public ::testing::Test {
protected:
    Epos2DictionaryOnBus() {
        master->on_receive([this](const can::Frame& frame) {
            received.push_back(frame);
            client.on_frame(frame);
        });
        node.start();
        loop.run_for(10ms);
    }

    static Epos2DictionaryConfig config(const std::filesystem::path& file) {
        Epos2DictionaryConfig config;
        config.node_id = kNode;
        config.serial_number = 0x0A0B'0C0D;
        config.parameter_file = file;
        return config;
    }

    Upload read(std::uint16_t index, std::uint8_t sub) {
        std::optional<Upload> result;
        client.upload(kNode, index, sub, [&result](AbortCode code, Bytes value) {
            result = {code, std::move(value)};
        });
        loop.run_for(50ms);
        EXPECT_TRUE(result.has_value()) << "no answer";
        return result.value_or(Upload{AbortCode::SdoTimeout, {}});
    }
    AbortCode write(std::uint16_t index, std::uint8_t sub, Bytes value) {
        std::optional<AbortCode> result;
        client.download(kNode, index, sub, std::move(value),
                        [&result](AbortCode code) { result = code; });
        loop.run_for(50ms);
        EXPECT_TRUE(result.has_value()) << "no answer";
        return result.value_or(AbortCode::SdoTimeout);
    }
    void nmt(canopen::NmtCommand command) {
        master->send(can::Frame::data_frame(
            canopen::kNmtCanId,
            std::vector<std::uint8_t>{static_cast<std::uint8_t>(command), kNode}));
        loop.run_for(50ms);
    }
    void reset_node() { nmt(canopen::NmtCommand::ResetNode); }

    const std::filesystem::path parameter_file = test::test_file("parameters.bin");
    core::EventLoop loop;
    can::VirtualBus bus{loop};
    std::unique_ptr<can::VirtualPort> device = bus.connect("epos2");
    std::unique_ptr<can::VirtualPort> master = bus.connect("master");
    Epos2Dictionary dictionary{config(parameter_file)};
    const std::size_t objects_before_node = dictionary.objects().objects().size();
    canopen::Node node{loop, *device, dictionary.objects(), dictionary.node_config()};
    canopen::SdoClient client{loop, *master};
    std::vector<can::Frame> received;
};

TEST(Epos2BitRates, HaveTheCodesOfTable8_81) {
    const std::vector<std::pair<std::uint32_t, std::uint16_t>> table = {
        {1'000'000, 0}, {800'000, 1}, {500'000, 2}, {250'000, 3},
        {125'000, 4},   {50'000, 6},  {20'000, 7}};
    for (const auto& [bit_rate, code] : table) {
        EXPECT_EQ(bit_rate_code(bit_rate), code) << bit_rate;
    }
    for (const std::uint32_t unsupported : {0U, 10'000U, 100'000U, 1'000'001U}) {
        EXPECT_EQ(bit_rate_code(unsupported), std::nullopt) << unsupported;
    }
}

TEST_F(Epos2DictionaryOnBus, NodeFindsEveryCommunicationObjectItNeeds) {
    EXPECT_EQ(dictionary.objects().objects().size(), objects_before_node);
    EXPECT_EQ(node.nmt_state(), canopen::NmtState::PreOperational);
}

// 8.2.1, 8.2.5, 8.2.15
TEST_F(Epos2DictionaryOnBus, ReadsDeviceTypeNameAndIdentity) {
    EXPECT_EQ(read(0x1000, 0).value, encode(std::uint32_t{0x0002'0192}));
    EXPECT_EQ(read(0x1008, 0).value, canopen::encode_string("EPOS2"));
    EXPECT_EQ(read(0x1018, 1).value, encode(std::uint32_t{0x0000'00FB}));
    EXPECT_EQ(read(0x1018, 2).value, encode(std::uint32_t{0x6220'0000}));
    EXPECT_EQ(read(0x1018, 3).value, encode(std::uint32_t{0x2126'0000}));
    EXPECT_EQ(read(0x1018, 4).value, encode(std::uint32_t{0x0A0B'0C0D}));
}

struct DefaultCase {
    std::uint16_t index;
    std::uint8_t sub;
    Bytes value;
};

TEST_F(Epos2DictionaryOnBus, ReadsTheSpecifiedDefaults) {
    const std::vector<DefaultCase> cases = {
        {0x1005, 0, encode(std::uint32_t{0x80})},                // 8.2.4
        {0x1014, 0, encode(std::uint32_t{0x80 + kNode})},        // 8.2.12
        {0x1200, 1, encode(std::uint32_t{0x600 + kNode})},       // 8.2.17
        {0x1400, 1, encode(std::uint32_t{0x200 + kNode})},       // 8.2.18
        {0x1801, 1, encode(std::uint32_t{0xC000'0280 + kNode})}, // 8.2.27
        {0x1A02, 2, encode(std::uint32_t{0x6064'0020})},         // 8.2.32
        {0x2000, 0, encode(std::uint8_t{kNode})},                // 8.2.34
        {0x2001, 0, encode(std::uint16_t{9})},                   // 8.2.35
        {0x2071, 2, encode(std::uint16_t{0xE007})},              // 8.2.57
        {0x6065, 0, encode(std::uint32_t{2000})},                // 8.2.94
        {0x607D, 1, encode(std::int32_t{INT32_MIN})},            // 8.2.105
        {0x6098, 0, encode(std::int8_t{7})},                     // 8.2.118
        {0x60C0, 0, encode(std::int16_t{-1})},                   // 8.2.121
        {0x6502, 0, encode(std::uint32_t{0x003F'0065})},         // 8.2.131
    };
    for (const DefaultCase& c : cases) {
        const Upload got = read(c.index, c.sub);
        EXPECT_EQ(got.code, AbortCode::None) << fmt::format("0x{:04X} sub {}", c.index, c.sub);
        EXPECT_EQ(got.value, c.value) << fmt::format("0x{:04X} sub {}", c.index, c.sub);
    }
}

struct RefusedWrite {
    const char* what;
    std::uint16_t index;
    std::uint8_t sub;
    Bytes value;
    std::uint32_t abort_code; ///< as table 4-12 prints it
};

TEST_F(Epos2DictionaryOnBus, RefusedWritesAbortWithTheSpecifiedCodes) {
    const std::vector<RefusedWrite> cases = {
        {"read-only statusword", 0x6041, 0, encode(std::uint16_t{0}), 0x0601'0002},
        {"constant supported drive modes", 0x6502, 0, encode(std::uint32_t{0}), 0x0601'0002},
        {"constant device name", 0x1008, 0, canopen::encode_string("EPOS3"), 0x0601'0002},
        {"abort connection option code below 1", 0x6007, 0, encode(std::int16_t{0}), 0x0609'0032},
        {"abort connection option code above 3", 0x6007, 0, encode(std::int16_t{4}), 0x0609'0031},
        {"node-ID 0", 0x2000, 0, encode(std::uint8_t{0}), 0x0609'0032},
        {"reserved CAN bit rate code 5", 0x2001, 0, encode(std::uint16_t{5}), 0x0609'0030},
        {"mode of operation 2", 0x6060, 0, encode(std::int8_t{2}), 0x0609'0030},
        {"motor type 65535 on a 24/5", 0x6402, 0, encode(std::uint16_t{0xFFFF}), 0x0609'0030},
        {"position window between the range and the disable value", 0x6067, 0,
         encode(std::uint32_t{0x8000'0000}), 0x0609'0031},
        {"16 bits to a 32-bit object", 0x6065, 0, encode(std::uint16_t{1}), 0x0607'0013},
        {"sub-index 3 of the sensor configuration", 0x2210, 3, encode(std::uint16_t{1}),
         0x0609'0011},
        {"an object the EPOS2 lacks", 0x1015, 0, encode(std::uint16_t{1}), 0x0602'0000},
        {"store without the signature \"save\"", 0x1010, 1, encode(std::uint32_t{1}), 0x0800'0020},
    };
    for (const RefusedWrite& c : cases) {
        EXPECT_EQ(static_cast<std::uint32_t>(write(c.index, c.sub, c.value)), c.abort_code)
            << c.what;
    }
}

TEST_F(Epos2DictionaryOnBus, ReadOfTheWriteOnlyInterpolationRecordIsRefused) {
    EXPECT_EQ(static_cast<std::uint32_t>(read(0x20C1, 0).code), 0x0601'0001u);
}

// 8.2.8 / 8.2.9: "save" keeps values over a reset, "load" brings the defaults back at the next.
TEST_F(Epos2DictionaryOnBus, SavedValuesSurviveAResetAndRestoredDefaultsReturnAfterOne) {
    ASSERT_EQ(write(0x6065, 0, encode(std::uint32_t{1234})), AbortCode::None);
    ASSERT_EQ(write(0x1010, 1, encode(canopen::kSaveSignature)), AbortCode::None);
    ASSERT_EQ(write(0x6067, 0, encode(std::uint32_t{10})), AbortCode::None); // not saved
    reset_node();
    EXPECT_EQ(read(0x6065, 0).value, encode(std::uint32_t{1234}));
    EXPECT_EQ(read(0x6067, 0).value, encode(std::uint32_t{0xFFFF'FFFF}));

    ASSERT_EQ(write(0x1011, 1, encode(canopen::kLoadSignature)), AbortCode::None);
    reset_node();
    EXPECT_EQ(read(0x6065, 0).value, encode(std::uint32_t{2000}));
}

// 8.2.18 / 8.2.22 / 8.2.26 / 8.2.30: RPDO1 (0x200 + node-ID) carries the controlword, TPDO1
// (0x180 + node-ID, event-driven) the statusword; both valid from power-up.
TEST_F(Epos2DictionaryOnBus, DefaultPdo1CarriesControlwordInAndStatuswordOut) {
    nmt(canopen::NmtCommand::Start);
    master->send(can::Frame::data_frame(0x200 + kNode, std::vector<std::uint8_t>{0x0F, 0x00}));
    loop.run_for(10ms);
    EXPECT_EQ(dictionary.objects().get_as<std::uint16_t>(0x6040, 0), 0x000F);

    received.clear();
    dictionary.objects().set_as(0x6041, 0, std::uint16_t{0x0237});
    loop.run_for(10ms);
    ASSERT_EQ(received.size(), 1u);
    EXPECT_EQ(received[0].id, 0x180u + kNode);
    EXPECT_EQ(Bytes(received[0].payload().begin(), received[0].payload().end()),
              (Bytes{0x37, 0x02}));
}

} // namespace
} // namespace eposp::drives::epos2
