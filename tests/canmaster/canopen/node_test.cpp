#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/canopen/predefined_connection_set.hpp"
#include "eposp/test/test_directory.hpp"
#include "lss_test_support.hpp"
#include "service_bench.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::at_ms;
using testing::Sent;
using testing::ServiceBench;

constexpr NodeId kNode = 5;
constexpr std::uint16_t kTpdoVariable = 0x2000; // UNSIGNED32, mapped into TPDO1
constexpr std::uint16_t kRpdoVariable = 0x2001; // UNSIGNED16, mapped from RPDO1

/// The device's own objects: two mappable variables and a string (a segmented upload).
void add_device_objects(ObjectDictionary& od) {
    od.add_variable(kTpdoVariable, "Position", DataType::Unsigned32, Access::ReadWrite,
                    encode<std::uint32_t>(0))
        .pdo_mappable = true;
    od.add_variable(kRpdoVariable, "Command", DataType::Unsigned16, Access::ReadWrite,
                    encode<std::uint16_t>(7))
        .pdo_mappable = true;
    od.add_variable(0x2002, "Name", DataType::VisibleString, Access::ReadOnly,
                    encode_string("EPOS P test node"));
}

/// TPDO1 on 0x185, synchronous every SYNC (type 1), with 0x2000; RPDO1 on 0x205 with 0x2001.
PdoObjectsConfig test_pdos() {
    PdoObjectsConfig pdos = cia301_pdo_defaults(kNode, 1, 1);
    pdos.tpdos[0].cob_id = 0x4000'0185;
    pdos.tpdos[0].transmission_type = 1;
    pdos.tpdos[0].mapping = {0x2000'0020};
    pdos.rpdos[0].cob_id = 0x205;
    pdos.rpdos[0].mapping = {0x2001'0010};
    return pdos;
}

NodeConfig test_config() {
    NodeConfig config;
    config.node_id = kNode;
    config.device_type = 0x0002'0192;
    config.identity = {
        .vendor_id = 0xFB, .product_code = 0x1234, .revision_number = 2, .serial_number = 99};
    config.pdos = test_pdos();
    return config;
}

/// A node on the device port of a bench; the tester is the master. `sdo_*` run raw SDO
/// transfers and return the server's answers.
class NodeTest : public ::testing::Test {
protected:
    NodeTest() {
        bench.tester->on_receive([this](const can::Frame& frame) { received.push_back(frame); });
    }

    /// The answer of the server of `server` to one request frame, or nullopt when it stays
    /// silent.
    std::optional<can::Frame> sdo_request(std::vector<std::uint8_t> bytes, NodeId server = kNode) {
        received.clear();
        bench.tester->send(can::Frame::data_frame(0x600 + server, bytes));
        bench.run_for(5ms);
        for (const auto& frame : received) {
            if (frame.id == 0x580u + server) {
                return frame;
            }
        }
        return std::nullopt;
    }
    /// An SDO upload, expedited or segmented (CiA 301 7.2.4.3.3 - 7.2.4.3.6); nullopt when
    /// aborted or unanswered.
    std::optional<Bytes> sdo_upload(std::uint16_t index, std::uint8_t sub_index,
                                    NodeId server = kNode) {
        const auto lo = static_cast<std::uint8_t>(index & 0xFF);
        const auto hi = static_cast<std::uint8_t>(index >> 8);
        auto reply = sdo_request({0x40, lo, hi, sub_index, 0, 0, 0, 0}, server);
        if (!reply || (reply->data[0] & 0xE0) != 0x40) {
            return std::nullopt;
        }
        const std::uint8_t initiate = reply->data[0];
        if ((initiate & 0x02) != 0) { // expedited, size indicated or 4 bytes
            const std::size_t size = (initiate & 0x01) != 0 ? 4u - ((initiate >> 2) & 3u) : 4u;
            return Bytes(reply->data.begin() + 4, reply->data.begin() + 4 + size);
        }
        Bytes value;
        for (std::uint8_t toggle = 0;; toggle ^= 0x10) {
            reply = sdo_request({static_cast<std::uint8_t>(0x60 | toggle), 0, 0, 0, 0, 0, 0, 0},
                                server);
            if (!reply || (reply->data[0] & 0xF0) != toggle) {
                return std::nullopt;
            }
            const std::size_t size = 7u - ((reply->data[0] >> 1) & 7u);
            value.insert(value.end(), reply->data.begin() + 1, reply->data.begin() + 1 + size);
            if ((reply->data[0] & 0x01) != 0) {
                return value;
            }
        }
    }
    /// An expedited download of `value` (CiA 301 7.2.4.3.3); the server's answer.
    template <typename T>
    std::string sdo_write(std::uint16_t index, std::uint8_t sub_index, T value,
                          NodeId server = kNode) {
        const Bytes data = encode(value);
        const auto command = static_cast<std::uint8_t>(0x23 | (4 - data.size()) << 2);
        std::vector<std::uint8_t> request = {command, static_cast<std::uint8_t>(index & 0xFF),
                                             static_cast<std::uint8_t>(index >> 8), sub_index};
        request.insert(request.end(), data.begin(), data.end());
        request.resize(8);
        const auto reply = sdo_request(request, server);
        return reply ? testing::candump(*reply) : "no answer";
    }
    /// The device's frames with `id` from `from` on.
    std::vector<Sent> device_frames(std::uint32_t id, core::TimePoint from = {}) const {
        return device_frames_where([id](std::uint32_t frame_id) { return frame_id == id; }, from);
    }
    /// Every frame the device sent from `from` on, in candump form.
    std::vector<std::string> device_frames_since(core::TimePoint from) const {
        std::vector<std::string> out;
        for (const auto& sent : device_frames_where([](std::uint32_t) { return true; }, from)) {
            out.push_back(sent.frame);
        }
        return out;
    }
    template <typename Predicate>
    std::vector<Sent> device_frames_where(Predicate wanted, core::TimePoint from) const {
        std::vector<Sent> out;
        for (const auto& sent : bench.device_frames()) {
            if (sent.at >= from && wanted(can::parse_candump_frame(sent.frame)->id)) {
                out.push_back(sent);
            }
        }
        return out;
    }
    void start() {
        node.start();
        bench.run_for(1ms);
    }

    ServiceBench bench;
    ObjectDictionary od = [] {
        ObjectDictionary dictionary;
        add_device_objects(dictionary);
        return dictionary;
    }();
    Node node{bench.loop, *bench.device, od, test_config()};
    std::vector<can::Frame> received;
};

TEST_F(NodeTest, StartSendsTheBootUpMessageAndEntersPreOperational) {
    start();
    // CiA 301 7.2.8.3.2.3: boot-up on 0x700 + node-ID with one byte 0x00.
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"}}));
    EXPECT_EQ(node.nmt_state(), NmtState::PreOperational);
}

TEST_F(NodeTest, AddsTheCommunicationObjectsTheDictionaryLacks) {
    for (const int index :
         {0x1000, 0x1001, 0x1003, 0x1005, 0x1006, 0x1007, 0x100C, 0x100D, 0x1014, 0x1015, 0x1016,
          0x1017, 0x1018, 0x1019, 0x1200, 0x1400, 0x1600, 0x1800, 0x1A00}) {
        EXPECT_NE(od.find(static_cast<std::uint16_t>(index)), nullptr) << std::hex << index;
    }
    EXPECT_EQ(od.find(0x1401), nullptr); // the PDOs of the configuration only
}

TEST_F(NodeTest, AnswersExpeditedReadsOfDeviceTypeAndVendorId) {
    start();
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4300100092010200");
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0})),
              "585#43181001FB000000");
}

TEST_F(NodeTest, SegmentedReadOfADeviceString) {
    start();
    EXPECT_EQ(sdo_upload(0x2002, 0), encode_string("EPOS P test node"));
}

TEST_F(NodeTest, OperationalNodeSendsItsSynchronousTpdoOnSync) {
    start();
    od.set_as<std::uint32_t>(kTpdoVariable, 0, 0xA1B2'C3D4);
    bench.send("000#0105"); // NMT start node 5
    bench.run_for(1ms);
    ASSERT_EQ(node.nmt_state(), NmtState::Operational);
    const core::TimePoint sync_at = bench.loop.now();
    bench.send("080#");
    bench.run_for(1ms);
    const auto tpdos = device_frames(0x185, sync_at);
    ASSERT_EQ(tpdos.size(), 1u);
    EXPECT_EQ(tpdos[0].frame, "185#D4C3B2A1");
}

TEST_F(NodeTest, PreOperationalNodeSendsNoTpdoOnSync) {
    start();
    bench.send("080#");
    bench.run_for(1ms);
    EXPECT_TRUE(device_frames(0x185).empty());
}

TEST_F(NodeTest, OperationalNodeTakesRpdoIntoTheMappedVariable) {
    start();
    bench.send("000#0100"); // NMT start all nodes
    bench.run_for(1ms);
    bench.send("205#3412");
    bench.run_for(1ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 0x1234);
}

TEST_F(NodeTest, HeartbeatPeriodComesFromAnSdoWriteOf0x1017) {
    start();
    // CiA 301 7.5.2.29: 0x1017 = 100 ms.
    EXPECT_EQ(testing::candump(*sdo_request({0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0})),
              "585#6017100000000000");
    const core::TimePoint written = bench.loop.now();
    bench.run_for(350ms);
    const auto heartbeats = device_frames(0x705, written);
    ASSERT_EQ(heartbeats.size(), 3u);
    EXPECT_EQ(heartbeats[0].frame, "705#7F");
    EXPECT_EQ(heartbeats[1].at - heartbeats[0].at, 100ms);
    EXPECT_EQ(heartbeats[2].at - heartbeats[1].at, 100ms);
}

TEST_F(NodeTest, StoppedNodeIsSilentButForItsHeartbeat) {
    start();
    ASSERT_TRUE(sdo_request({0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0}));
    bench.send("000#0105");
    bench.run_for(1ms);
    bench.send("000#0205"); // NMT stop
    bench.run_for(1ms);
    ASSERT_EQ(node.nmt_state(), NmtState::Stopped);
    const core::TimePoint stopped = bench.loop.now();

    // CiA 301 7.3.2.2, table 83: in stopped only NMT and error control.
    EXPECT_FALSE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
    bench.send("080#");
    bench.run_for(1ms);
    bench.send("205#3412");
    bench.run_for(300ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 7);
    EXPECT_EQ(device_frames_since(stopped),
              (std::vector<std::string>{"705#04", "705#04", "705#04"}));
}

TEST_F(NodeTest, ResetCommunicationBootsAgainWithTheDefaultHeartbeatTime) {
    start();
    ASSERT_TRUE(sdo_request({0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0}));
    od.set_as<std::uint16_t>(kRpdoVariable, 0, 42);
    const core::TimePoint reset_at = bench.loop.now();
    bench.send("000#8205"); // NMT reset communication
    bench.run_for(1ms);
    EXPECT_EQ(device_frames(0x705, reset_at).front().frame, "705#00");
    EXPECT_EQ(node.nmt_state(), NmtState::PreOperational);
    // 0x1017 is back at its default 0: no heartbeat after the boot-up.
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x17, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4B17100000000000");
    bench.run_for(300ms);
    EXPECT_EQ(device_frames(0x705, reset_at).size(), 1u);
    // The application area keeps its values.
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 42);
}

TEST_F(NodeTest, ResetNodeAlsoResetsTheApplicationAreaAndTellsTheDevice) {
    int application_resets = 0;
    node.on_reset_application([&] { ++application_resets; });
    start();
    EXPECT_EQ(application_resets, 1);
    od.set_as<std::uint16_t>(kRpdoVariable, 0, 42);
    bench.send("000#8105"); // NMT reset node
    bench.run_for(1ms);
    EXPECT_EQ(application_resets, 2);
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 7);
    EXPECT_EQ(device_frames(0x705).back().frame, "705#00");
}

TEST_F(NodeTest, HeartbeatTimeoutRaisesACommunicationEmergency) {
    start();
    // 0x1016 sub 1: node 0x10 within 100 ms.
    ASSERT_TRUE(sdo_request({0x23, 0x16, 0x10, 0x01, 100, 0, 0x10, 0}));
    bench.send("710#7F");
    bench.run_for(150ms);
    // CiA 301 7.2.7.3.1: code 0x8130, error register 0x11 (communication, EPOS2 FW spec table
    // 4-11, and generic, CiA 301 7.5.2.2).
    const auto emcys = device_frames(0x085);
    ASSERT_EQ(emcys.size(), 1u);
    EXPECT_EQ(emcys[0].frame, "085#3081110000000000");
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x01, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4F01100011000000");
}

/// A node with a parameter file in the test's own directory.
class NodeWithParameterFileTest : public NodeTest {
protected:
    static std::filesystem::path parameter_file() { return test::test_file("parameters.bin"); }
    static NodeConfig config_with_file() {
        NodeConfig config = test_config();
        config.parameter_file = parameter_file();
        return config;
    }
    /// A node without node-ID (CiA 305) and with the CiA 301 default PDOs.
    static NodeConfig unconfigured_config() {
        NodeConfig config = config_with_file();
        config.node_id = kLssUnconfiguredNodeId;
        config.pdos.reset();
        return config;
    }

    /// Power-up of a device with `config`: the one before is switched off, a fresh dictionary
    /// and node take the device port and start.
    Node& power_up(NodeConfig config) {
        powered_node.reset();
        powered_od.emplace();
        add_device_objects(*powered_od);
        powered_node.emplace(bench.loop, *bench.device, *powered_od, std::move(config));
        powered_node->start();
        bench.run_for(1ms);
        return *powered_node;
    }

    /// The tester sends `request`; every frame the device sent in the next 5 ms.
    std::vector<std::string> exchange(const can::Frame& request) {
        const core::TimePoint sent = bench.loop.now();
        bench.tester->send(request);
        bench.run_for(5ms);
        return device_frames_since(sent);
    }
    std::vector<std::string> exchange(std::string_view request) {
        return exchange(*can::parse_candump_frame(request));
    }
    /// LSS switch state selective with the test identity (EPOS2 FW spec 7.4.2.2): the answer.
    std::vector<std::string> lss_switch_selective() {
        const LssAddress address = test_config().identity;
        exchange(
            testing::master_frame_u32(LssCommand::SwitchStateSelectiveVendorId, address.vendor_id));
        exchange(testing::master_frame_u32(LssCommand::SwitchStateSelectiveProductCode,
                                           address.product_code));
        exchange(testing::master_frame_u32(LssCommand::SwitchStateSelectiveRevisionNumber,
                                           address.revision_number));
        return exchange(testing::master_frame_u32(LssCommand::SwitchStateSelectiveSerialNumber,
                                                  address.serial_number));
    }

    ObjectDictionary stored_od = [] {
        ObjectDictionary dictionary;
        add_device_objects(dictionary);
        return dictionary;
    }();
    Node stored_node{bench.loop, *bench.device, stored_od, config_with_file()};
    std::optional<ObjectDictionary> powered_od;
    std::optional<Node> powered_node;
};

TEST_F(NodeWithParameterFileTest, ResetCommunicationRestoresTheStoredHeartbeatTime) {
    stored_node.start();
    bench.run_for(1ms);
    EXPECT_EQ(stored_node.stored_values().status, StoredValuesStatus::NoneStored);
    ASSERT_TRUE(sdo_request({0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0}));
    // CiA 301 7.5.2.13: 0x1010 sub 1 = "save".
    EXPECT_EQ(testing::candump(*sdo_request({0x23, 0x10, 0x10, 0x01, 's', 'a', 'v', 'e'})),
              "585#6010100100000000");
    ASSERT_TRUE(sdo_request({0x2B, 0x17, 0x10, 0x00, 200, 0, 0, 0}));
    bench.send("000#8205");
    bench.run_for(1ms);
    EXPECT_EQ(stored_node.stored_values().status, StoredValuesStatus::Applied);
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x17, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4B17100064000000");
}

using Frames = std::vector<std::string>;

// CiA 305 / EPOS2 FW spec 7.4: a node without node-ID gets one by LSS.
TEST_F(NodeWithParameterFileTest, UnconfiguredNodeBootsWithTheNodeIdLssConfigured) {
    const Node& unconfigured = power_up(unconfigured_config());
    EXPECT_EQ(unconfigured.nmt_state(), NmtState::Initialising);
    EXPECT_TRUE(bench.device_frames().empty()); // no boot-up without node-ID
    EXPECT_FALSE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, 0x7F));

    EXPECT_EQ(lss_switch_selective(), Frames{"7E4#4400000000000000"});
    EXPECT_EQ(exchange("7E5#110A000000000000"), Frames{"7E4#1100000000000000"}); // node-ID 10
    EXPECT_EQ(exchange("7E5#1700000000000000"), Frames{"7E4#1700000000000000"}); // stored
    // Back to waiting: the node leaves LSS through reset communication and boots as node 10.
    EXPECT_EQ(exchange("7E5#0400000000000000"), Frames{"70A#00"});
    EXPECT_EQ(unconfigured.nmt_state(), NmtState::PreOperational);
    EXPECT_EQ(unconfigured.node_id(), 10);

    // SDO server on 0x60A / 0x58A (CiA 301 7.3.5), 0x1200 and 0x1014 follow the node-ID.
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x00, 0x12, 0x01, 0, 0, 0, 0}, 10)),
              "58A#430012010A060000");
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x14, 0x10, 0x00, 0, 0, 0, 0}, 10)),
              "58A#431410008A000000");
    // TPDO1 of the predefined connection set on 0x18A: mapped, made valid, sent at SYNC.
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x00, 0x18, 0x01, 0, 0, 0, 0}, 10)),
              "58A#430018018A0100C0");
    EXPECT_EQ(sdo_write<std::uint32_t>(0x1A00, 1, 0x2000'0020, 10), "58A#60001A0100000000");
    EXPECT_EQ(sdo_write<std::uint8_t>(0x1A00, 0, 1, 10), "58A#60001A0000000000");
    EXPECT_EQ(sdo_write<std::uint8_t>(0x1800, 2, 1, 10), "58A#6000180200000000");
    EXPECT_EQ(sdo_write<std::uint32_t>(0x1800, 1, 0x4000'018A, 10), "58A#6000180100000000");
    powered_od->set_as<std::uint32_t>(kTpdoVariable, 0, 0x0102'0304);
    exchange("000#010A");
    EXPECT_EQ(exchange("080#"), Frames{"18A#04030201"});
    // EMCY on 0x8A (a SYNC with a counter is too long: 0x8240); heartbeat on 0x70A.
    EXPECT_EQ(exchange("080#01"), Frames{"08A#4082110000000000"});
    EXPECT_EQ(sdo_write<std::uint16_t>(0x1017, 0, 10, 10), "58A#6017100000000000");
    bench.run_for(6ms);
    EXPECT_EQ(device_frames(0x70A).back().frame, "70A#05");
}

TEST_F(NodeWithParameterFileTest, LssNodeIdTakesEffectAtResetCommunicationAndSurvivesPowerUp) {
    const Node& configured = power_up(config_with_file());
    EXPECT_EQ(exchange("7E5#0401000000000000"), Frames{}); // switch global: configuration
    EXPECT_EQ(exchange("7E5#1107000000000000"), Frames{"7E4#1100000000000000"});
    EXPECT_EQ(exchange("7E5#1700000000000000"), Frames{"7E4#1700000000000000"});
    EXPECT_EQ(exchange("7E5#0400000000000000"), Frames{});
    // Pending until reset communication (CiA 305): still node 5.
    EXPECT_EQ(configured.node_id(), kNode);
    EXPECT_TRUE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
    EXPECT_EQ(exchange("000#8205"), Frames{"707#00"});
    EXPECT_FALSE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
    EXPECT_TRUE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, 7));
    EXPECT_EQ(exchange("707#R"), Frames{"707#7F"}); // node guarding (CiA 301 7.2.8.3.2.1)
    EXPECT_EQ(exchange("705#R"), Frames{});
    EXPECT_EQ(exchange("000#8207"), Frames{"707#00"}); // kept across resets
    EXPECT_EQ(exchange("000#8107"), Frames{"707#00"});

    const core::TimePoint power_on = bench.loop.now();
    power_up(config_with_file());
    EXPECT_EQ(device_frames_since(power_on), Frames{"707#00"});
}

TEST_F(NodeWithParameterFileTest, LssNodeIdThatWasNotStoredIsLostAtPowerUp) {
    power_up(config_with_file());
    exchange("7E5#0401000000000000");
    exchange("7E5#1107000000000000");
    exchange("7E5#0400000000000000");
    EXPECT_EQ(exchange("000#8205"), Frames{"707#00"});
    const core::TimePoint power_on = bench.loop.now();
    power_up(config_with_file());
    EXPECT_EQ(device_frames_since(power_on), Frames{"705#00"});
}

// CiA 305: configure node-ID 0xFF takes the node-ID away at the next reset communication.
TEST_F(NodeWithParameterFileTest, NodeWhoseNodeIdLssRemovedFallsSilentButForLss) {
    const Node& configured = power_up(config_with_file());
    exchange("7E5#0401000000000000");
    EXPECT_EQ(exchange("7E5#11FF000000000000"), Frames{"7E4#1100000000000000"});
    exchange("7E5#0400000000000000");
    EXPECT_EQ(exchange("000#8205"), Frames{}); // no boot-up
    EXPECT_EQ(configured.nmt_state(), NmtState::Initialising);
    EXPECT_FALSE(sdo_request({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
    // EPOS2 FW spec 7.4.2.13: it answers identify non-configured remote slave.
    EXPECT_EQ(exchange("7E5#4C00000000000000"), Frames{"7E4#5000000000000000"});
}

TEST_F(NodeWithParameterFileTest, DamagedLssConfigurationRaisesEmcy6320AndKeepsTheConfiguredId) {
    {
        std::ofstream damaged(parameter_file().string() + ".lss", std::ios::binary);
        damaged << "EPOSPLSS\x07";
    }
    const core::TimePoint power_on = bench.loop.now();
    power_up(config_with_file());
    EXPECT_EQ(device_frames_since(power_on), (Frames{"705#00", "085#2063210000000000"}));
}

TEST_F(NodeTest, LssStoreWithoutParameterFileIsNotSupported) {
    start();
    bench.send("7E5#0401000000000000");
    bench.run_for(1ms);
    received.clear();
    bench.send("7E5#1700000000000000");
    bench.run_for(5ms);
    ASSERT_EQ(received.size(), 1u);
    EXPECT_EQ(testing::candump(received[0]), "7E4#1701000000000000"); // EPOS2 FW spec 7.4.2.6
}

TEST_F(NodeWithParameterFileTest, ActivateBitTimingReachesTheOwnerAndSilencesTheNode) {
    std::vector<std::uint32_t> switched;
    NodeConfig config = config_with_file();
    config.switch_bit_rate = [&switched](std::uint32_t rate) {
        switched.push_back(rate);
    };
    power_up(std::move(config));
    EXPECT_EQ(switched, (std::vector<std::uint32_t>{1'000'000}));
    exchange("7E5#0401000000000000");
    // EPOS2 FW spec 7.4.2.4: table 0, index 2: 500 kbit/s.
    EXPECT_EQ(exchange("7E5#1300020000000000"), Frames{"7E4#1300000000000000"});
    ASSERT_EQ(sdo_write<std::uint16_t>(0x1017, 0, 10), "585#6017100000000000");
    const core::TimePoint activated = bench.loop.now();
    bench.send("7E5#1564000000000000"); // switch delay 100 ms
    bench.run_for(150ms);
    EXPECT_EQ(switched, (std::vector<std::uint32_t>{1'000'000, 500'000}));
    EXPECT_EQ(powered_node->bit_rate(), 500'000u);
    // Two switch delays without a heartbeat, then it goes on.
    bench.run_until(activated + 199ms);
    EXPECT_EQ(device_frames(0x705, activated + 1ms), std::vector<Sent>{});
    bench.run_for(20ms);
    EXPECT_FALSE(device_frames(0x705, activated + 200ms).empty());
}

// CiA 301 7.5.2.8: 0x1007, the synchronous window after each SYNC.
TEST_F(NodeTest, RemoteRequestForASynchronousTpdoAfterTheWindowGoesUnanswered) {
    start();
    od.set_as<std::uint32_t>(kTpdoVariable, 0, 0xA1B2'C3D4);
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1800, 1, 0x185), "585#6000180100000000"); // RTR allowed
    ASSERT_EQ(sdo_write<std::uint8_t>(0x1800, 2, 252),
              "585#6000180200000000"); // synchronous, RTR only
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1007, 0, 2000), "585#6007100000000000"); // 2 ms
    bench.send("000#0105");
    bench.send("080#");
    bench.run_for(1ms);
    const core::TimePoint in_window = bench.loop.now();
    bench.send("185#R");
    bench.run_for(1ms);
    EXPECT_EQ(device_frames_since(in_window), Frames{"185#D4C3B2A1"});
    bench.run_for(2ms);
    const core::TimePoint late = bench.loop.now();
    bench.send("185#R");
    bench.run_for(5ms);
    EXPECT_EQ(device_frames_since(late), Frames{});
}

TEST_F(NodeTest, SynchronousTpdoStillQueuedWhenTheWindowClosesIsNeverSent) {
    start();
    od.set_as<std::uint32_t>(kTpdoVariable, 0, 0xA1B2'C3D4);
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1007, 0, 2000), "585#6007100000000000"); // 2 ms
    bench.send("000#0105");
    bench.run_for(1ms);
    // A babbling node between SYNC and TPDO1 in priority holds the bus for 3 ms: TPDO1 (type 1)
    // waits in the node's transmit queue until its window closes and is taken back.
    const auto babbler = bench.bus.connect("babbler");
    const can::Frame babble = *can::parse_candump_frame("100#00");
    const core::TimePoint sync_at = bench.loop.now();
    babbler->babble(babble);
    bench.send("080#");
    bench.run_for(3ms);
    babbler->stop_babbling();
    bench.run_for(5ms);
    EXPECT_EQ(device_frames_since(sync_at), Frames{});
    // Without the window it goes out once the bus is free.
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1007, 0, 0), "585#6007100000000000");
    const core::TimePoint second_sync = bench.loop.now();
    babbler->babble(babble);
    bench.send("080#");
    bench.run_for(3ms);
    babbler->stop_babbling();
    bench.run_for(5ms);
    EXPECT_EQ(device_frames_since(second_sync), Frames{"185#D4C3B2A1"});
}

TEST_F(NodeTest, SynchronousRpdoAfterTheWindowIsDiscarded) {
    start();
    ASSERT_EQ(sdo_write<std::uint8_t>(0x1400, 2, 1), "585#6000140200000000"); // synchronous
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1007, 0, 2000), "585#6007100000000000");
    bench.send("000#0105");
    bench.send("080#");
    bench.run_for(3ms); // the window closed
    bench.send("205#3412");
    bench.run_for(1ms);
    bench.send("080#");
    bench.run_for(1ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 7);
    bench.send("205#7856"); // within the window of that SYNC: applied at the next one
    bench.run_for(500us);
    bench.send("080#");
    bench.run_for(1ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(kRpdoVariable, 0), 0x5678);
}

// CiA 301 7.5.2.35: the event timer of an RPDO is its deadline.
TEST_F(NodeTest, RpdoMissingItsDeadlineRaisesEmcy8250) {
    start();
    ASSERT_EQ(sdo_write<std::uint16_t>(0x1400, 5, 100), "585#6000140500000000");
    bench.send("000#0105");
    bench.run_for(150ms);
    EXPECT_TRUE(device_frames(0x085).empty()); // monitoring starts with the first RPDO
    bench.send("205#3412");
    bench.run_for(90ms);
    bench.send("205#3412");
    bench.run_for(90ms);
    EXPECT_TRUE(device_frames(0x085).empty());
    const core::TimePoint last = bench.loop.now() - 90ms;
    bench.run_for(20ms);
    const auto emcys = device_frames(0x085);
    ASSERT_EQ(emcys.size(), 1u);
    EXPECT_EQ(emcys[0].frame, "085#5082110000000000");
    EXPECT_GE(emcys[0].at, last + 100ms);
}

TEST_F(NodeWithParameterFileTest, CorruptParameterFileRaisesEmcy6320AndRunsOnDefaults) {
    {
        std::ofstream corrupt(parameter_file(), std::ios::binary);
        corrupt << "not a parameter file";
    }
    stored_node.start();
    bench.run_for(1ms);
    EXPECT_EQ(stored_node.stored_values().status, StoredValuesStatus::Corrupt);
    // EPOS2 FW spec table 4-11: 0x6320 Software Parameter Error, error register 0010 0000b,
    // with the generic bit (CiA 301 7.5.2.2).
    EXPECT_EQ(device_frames_since({}), (Frames{"705#00", "085#2063210000000000"}));
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x17, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4B17100000000000");
}

// EPOS2 FW spec 8.2.9: restore needs permission; 0x1011 sub 5 restores the PDO COB-IDs.
TEST_F(NodeWithParameterFileTest, RestoreObjectsAskTheDeviceAndRestorePdoCobIds) {
    bool permitted = false;
    NodeConfig config = config_with_file();
    config.restore_pdo_cob_ids = true;
    config.store_restore.restore_permitted = [&permitted] {
        return permitted ? AbortCode::None : AbortCode::DeviceState;
    };
    power_up(std::move(config));
    EXPECT_EQ(sdo_write<std::uint32_t>(0x1011, 1, kLoadSignature), "585#8011100122000008");
    EXPECT_EQ(sdo_write<std::uint32_t>(0x1011, 5, kLoadSignature), "585#8011100522000008");
    permitted = true;
    // TPDO1 moved to 0x1A5, stored; "load" in sub 5 brings 0x185 back at the next save.
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1800, 1, 0x8000'0185), "585#6000180100000000");
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1800, 1, 0x8000'01A5), "585#6000180100000000");
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1010, 1, kSaveSignature), "585#6010100100000000");
    EXPECT_EQ(sdo_write<std::uint32_t>(0x1011, 5, kLoadSignature), "585#6011100500000000");
    ASSERT_EQ(sdo_write<std::uint32_t>(0x1010, 1, kSaveSignature), "585#6010100100000000");
    exchange("000#8205");
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x00, 0x18, 0x01, 0, 0, 0, 0})),
              "585#4300180185010080");
}

// CiA 301 7.3.5: the defaults that follow the node-ID, and those that do not.
TEST(PredefinedConnectionSet, MovingTheNodeIdMovesOnlyThePredefinedDefaults) {
    ObjectDictionary od;
    PdoObjectsConfig pdos = cia301_pdo_defaults(5, 2, 2);
    pdos.tpdos[1].cob_id = 0x4000'01A5; // chosen by the device, not predefined
    add_pdo_objects(od, pdos);
    add_emcy_objects(od, 5);
    add_sdo_server_objects(od, 5);
    move_node_id_defaults(od, 5, 0x42);
    od.reset_to_defaults();
    const std::vector<std::tuple<std::uint16_t, std::uint8_t, std::uint32_t>> expected = {
        {0x1014, 0, 0xC2},        {0x1200, 1, 0x642},       {0x1200, 2, 0x5C2},
        {0x1400, 1, 0x8000'0242}, {0x1401, 1, 0x8000'0342}, {0x1800, 1, 0xC000'01C2},
        {0x1801, 1, 0x4000'01A5},
    };
    for (const auto& [index, sub_index, value] : expected) {
        EXPECT_EQ(od.get_as<std::uint32_t>(index, sub_index), value)
            << std::hex << index << " sub " << int{sub_index};
    }
}

TEST(NodeErrorRegister, CommunicationCodesSetTheCommunicationBit) {
    EXPECT_EQ(error_register_bits(0x8130), error_register::kCommunication);
    EXPECT_EQ(error_register_bits(0x8240), error_register::kCommunication);
    EXPECT_EQ(error_register_bits(0x6100), error_register::kGeneric);
    EXPECT_EQ(error_register_bits(0x6320), error_register::kDeviceProfile); // EPOS2 table 4-11
}

/// The "SDO browse" acceptance: a node built from the EDS of another answers every readable
/// object with the same value.
TEST_F(NodeTest, NodeFromItsOwnEdsAnswersEveryReadWithTheSameValue) {
    auto imported = import_eds(export_eds(od, DeviceInfo{}), "node.eds", kNode);
    ASSERT_TRUE(imported) << imported.error();
    // The node under test takes over the device port, built on the imported dictionary.
    ObjectDictionary& copy = imported->dictionary;
    Node copy_node{bench.loop, *bench.device, copy, test_config()};
    copy_node.start();
    bench.run_for(1ms);

    std::size_t compared = 0;
    for (const auto& [index, object] : od.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            Bytes expected;
            if (od.read(index, sub_index, expected) != AbortCode::None) {
                continue;
            }
            EXPECT_EQ(sdo_upload(index, sub_index), expected)
                << std::hex << index << " sub " << int{sub_index};
            ++compared;
        }
    }
    EXPECT_GT(compared, 40u);
}

/// CiA 301 7.2.8.3.2: every node answers a reset node addressed to all with one boot-up.
TEST(NodesOnOneBus, ResetNodeToAllGivesOneBootUpFromEachNode) {
    ServiceBench bench;
    const auto second_port = bench.bus.connect("second device");
    ObjectDictionary first_od;
    ObjectDictionary second_od;
    NodeConfig first_config = test_config();
    NodeConfig second_config = test_config();
    second_config.node_id = kNode + 1;
    second_config.pdos = cia301_pdo_defaults(kNode + 1, 1, 1);
    Node first{bench.loop, *bench.device, first_od, first_config};
    Node second{bench.loop, *second_port, second_od, second_config};
    first.start();
    second.start();
    bench.run_for(10ms);

    std::vector<std::uint32_t> boot_ups;
    bench.tester->on_receive([&boot_ups](const can::Frame& frame) {
        if (frame.id >= 0x700) {
            boot_ups.push_back(frame.id);
        }
    });
    bench.tester->send(can::Frame::data_frame(0x000, {0x81, 0x00}));
    bench.run_for(50ms);
    std::sort(boot_ups.begin(), boot_ups.end());
    EXPECT_EQ(boot_ups, (std::vector<std::uint32_t>{0x705, 0x706}));
}

} // namespace
} // namespace eposp::canopen
