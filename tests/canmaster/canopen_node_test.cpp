#include "canopen_service_bench.hpp"
#include "eposp/canmaster/canopen/eds_export.hpp"
#include "eposp/canmaster/canopen/eds_import.hpp"
#include "eposp/canmaster/canopen/node.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <unistd.h>
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

    /// The server's answer to one request frame, or nullopt when it stays silent.
    std::optional<can::Frame> sdo_request(std::vector<std::uint8_t> bytes) {
        received.clear();
        bench.tester->send(can::Frame::data_frame(0x600 + kNode, bytes));
        bench.run_for(5ms);
        for (const auto& frame : received) {
            if (frame.id == 0x580u + kNode) {
                return frame;
            }
        }
        return std::nullopt;
    }
    /// An SDO upload, expedited or segmented (CiA 301 7.2.4.3.3 - 7.2.4.3.6); nullopt when
    /// aborted or unanswered.
    std::optional<Bytes> sdo_upload(std::uint16_t index, std::uint8_t sub_index) {
        const auto lo = static_cast<std::uint8_t>(index & 0xFF);
        const auto hi = static_cast<std::uint8_t>(index >> 8);
        auto reply = sdo_request({0x40, lo, hi, sub_index, 0, 0, 0, 0});
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
            reply = sdo_request({static_cast<std::uint8_t>(0x60 | toggle), 0, 0, 0, 0, 0, 0, 0});
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
    /// The device's frames with `id` from `from` on.
    std::vector<Sent> device_frames(std::uint32_t id, core::TimePoint from = {}) const {
        std::vector<Sent> out;
        for (const auto& sent : bench.device_frames()) {
            if (sent.at >= from && can::parse_candump_frame(sent.frame)->id == id) {
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
    const auto frames = bench.device_frames();
    std::vector<std::string> since_stop;
    for (const auto& sent : frames) {
        if (sent.at >= stopped) {
            since_stop.push_back(sent.frame);
        }
    }
    EXPECT_EQ(since_stop, (std::vector<std::string>{"705#04", "705#04", "705#04"}));
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
    // CiA 301 7.2.7.3.1: code 0x8130, error register 0x10 (EPOS2 FW spec table 4-11).
    const auto emcys = device_frames(0x085);
    ASSERT_EQ(emcys.size(), 1u);
    EXPECT_EQ(emcys[0].frame, "085#3081100000000000");
    EXPECT_EQ(testing::candump(*sdo_request({0x40, 0x01, 0x10, 0x00, 0, 0, 0, 0})),
              "585#4F01100010000000");
}

/// A node with a parameter file in a directory of its own (per process: parallel ctest runs).
class NodeWithParameterFileTest : public NodeTest {
protected:
    static std::filesystem::path directory() {
        return std::filesystem::temp_directory_path() /
               ("eposp_node_test_" + std::to_string(::getpid()));
    }
    NodeWithParameterFileTest() { std::filesystem::create_directories(directory()); }
    ~NodeWithParameterFileTest() override { std::filesystem::remove_all(directory()); }

    ObjectDictionary stored_od = [] {
        ObjectDictionary dictionary;
        add_device_objects(dictionary);
        return dictionary;
    }();
    Node stored_node{bench.loop, *bench.device, stored_od, [] {
                         NodeConfig config = test_config();
                         config.parameter_file = directory() / "parameters.bin";
                         return config;
                     }()};
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

TEST(NodeErrorRegister, CommunicationCodesSetTheCommunicationBit) {
    EXPECT_EQ(error_register_bits(0x8130), error_register::kCommunication);
    EXPECT_EQ(error_register_bits(0x8240), error_register::kCommunication);
    EXPECT_EQ(error_register_bits(0x6100), error_register::kGeneric);
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

} // namespace
} // namespace eposp::canopen
