// Conformance-style suite: a composed canopen::Node driven only through raw CAN frames on the
// virtual bus, as a CANopen conformance tester drives a device, with every reply checked byte
// for byte. The per-service suites test each service alone; this one tests what the node puts
// on the wire, services combined. (canopen_node_test.cpp has the node's boot-up, its SDO reads
// of 0x1000/0x1018, its stopped-state silence and its heartbeat-consumer EMCY.)
#include "eposp/canopen/node.hpp"
#include "node_tester.hpp"
#include "sdo_test_support.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::conversation_name;
using testing::SdoConversation;
using testing::SdoStep;
using testing::Sent;

constexpr NodeId kNode = 5;
/// "EPOS P conformance": 18 bytes, three segments or one block of three.
constexpr std::string_view kName = "EPOS P conformance";

/// The device's own objects, one of each kind the SDO and PDO services treat differently.
void add_device_objects(ObjectDictionary& od) {
    od.add_variable(0x2000, "u32", DataType::Unsigned32, Access::ReadWrite,
                    encode<std::uint32_t>(0x1122'3344))
        .pdo_mappable = true;
    od.add_variable(0x2001, "name", DataType::VisibleString, Access::ReadOnly,
                    encode_string(kName));
    od.add_variable(0x2002, "write-only", DataType::Unsigned32, Access::WriteOnly,
                    encode<std::uint32_t>(0));
    od.add_variable(0x2003, "domain", DataType::Domain, Access::ReadWrite, {});
    od.add_object(0x2004, "record", ObjectCode::Record);
    od.add_sub(0x2004, 1, "u16", DataType::Unsigned16, Access::ReadWrite, encode<std::uint16_t>(0));
    od.add_variable(0x2005, "u8", DataType::Unsigned8, Access::ReadWrite, encode<std::uint8_t>(0))
        .pdo_mappable = true;
    od.add_variable(0x2006, "not mappable", DataType::Unsigned32, Access::ReadWrite,
                    encode<std::uint32_t>(0));
}

NodeConfig conformance_config() {
    NodeConfig config;
    config.node_id = kNode;
    config.device_type = 0x0002'0192;
    config.identity = {
        .vendor_id = 0xFB, .product_code = 1, .revision_number = 2, .serial_number = 3};
    return config; // CiA 301 default PDOs: 4 RPDOs and 4 TPDOs, all invalid and unmapped
}

/// The tester's side of the bus, with the conformance node on it.
class Conformance : public testing::NodeTester {
protected:
    Conformance() {
        node.start();
        bench.run_for(1ms);
    }

    ObjectDictionary od = [] {
        ObjectDictionary dictionary;
        add_device_objects(dictionary);
        return dictionary;
    }();
    Node node{bench.loop, *bench.device, od, conformance_config()};
};

// --- SDO (CiA 301 7.2.4.3): whole conversations, request and reply frames byte for byte. ---

class SdoConformance : public Conformance, public ::testing::WithParamInterface<SdoConversation> {};

TEST_P(SdoConformance, EveryReplyIsTheSpecifiedFrame) {
    expect_conversation(GetParam().steps);
}

std::vector<SdoConversation> sdo_transfers() {
    return {
        {"ExpeditedUpload", {{"605#4000200000000000", {"585#4300200044332211"}}}},
        {"ExpeditedDownloadOfOneByteAndReadBack",
         {{"605#2F05200007000000", {"585#6005200000000000"}},
          {"605#4005200000000000", {"585#4F05200007000000"}}}},
        {"ExpeditedDownloadWithoutSizeIndicated",
         {{"605#2200200078563412", {"585#6000200000000000"}},
          {"605#4000200000000000", {"585#4300200078563412"}}}},
        {"ExpeditedDownloadToASubIndex",
         {{"605#2B04200134120000", {"585#6004200100000000"}},
          {"605#4004200100000000", {"585#4B04200134120000"}}}},
        // 18 bytes: 7 + 7 + 4, the last segment with n = 3 and c set; toggle 0, 1, 0.
        {"SegmentedUpload",
         {{"605#4001200000000000", {"585#4101200012000000"}},
          {"605#6000000000000000", {"585#00" + testing::hex(encode_string("EPOS P "))}},
          {"605#7000000000000000", {"585#10" + testing::hex(encode_string("conform"))}},
          {"605#6000000000000000", {"585#07" + testing::hex(encode_string("ance")) + "000000"}}}},
        {"SegmentedDownloadAndReadBack",
         {{"605#2103200009000000", {"585#6003200000000000"}},
          {"605#0001020304050607", {"585#2000000000000000"}},
          {"605#1B08090000000000", {"585#3000000000000000"}},
          {"605#4003200000000000", {"585#4103200009000000"}},
          {"605#6000000000000000", {"585#0001020304050607"}},
          {"605#7000000000000000", {"585#1B08090000000000"}}}},
        // CiA 301 7.2.4.3.9-15: block upload with CRC, one sub-block of 3 segments; the CRC
        // (CRC-16/XMODEM of the 18 bytes) is 0x5FBE.
        {"BlockUploadWithCrc",
         {{"605#A401200003000000", {"585#C601200012000000"}},
          {"605#A300000000000000",
           {"585#01" + testing::hex(encode_string("EPOS P ")),
            "585#02" + testing::hex(encode_string("conform")),
            "585#83" + testing::hex(encode_string("ance")) + "000000"}},
          {"605#A203030000000000", {"585#CDBE5F0000000000"}},
          {"605#A100000000000000", {}}}},
        // Block download of 9 bytes with CRC 0x2378, the server asking for 127 segments.
        {"BlockDownloadWithCrcAndReadBack",
         {{"605#C603200009000000", {"585#A40320007F000000"}},
          {"605#0101020304050607", {}},
          {"605#8208090000000000", {"585#A2027F0000000000"}},
          {"605#D578230000000000", {"585#A100000000000000"}},
          {"605#4003200000000000", {"585#4103200009000000"}}}},
    };
}

// CiA 301 table 22. 0x06070010 (length does not match) never occurs: every length check of the
// server knows which way the length is off and answers 0x06070012 or 0x06070013.
std::vector<SdoConversation> sdo_aborts() {
    return {
        {"UploadOfAWriteOnlyObject",
         {{"605#4002200000000000", {"585#8002200001000106"}}}}, // 0x06010001
        {"DownloadToAReadOnlyObject",
         {{"605#2301200001000000", {"585#8001200002000106"}}}}, // 0x06010002
        {"UploadOfAMissingObject",
         {{"605#4000300000000000", {"585#8000300000000206"}}}}, // 0x06020000
        {"UploadOfAMissingSubIndex",
         {{"605#4004200200000000", {"585#8004200211000906"}}}}, // 0x06090011
        {"ExpeditedDownloadTooLong",
         {{"605#2305200001020304", {"585#8005200012000706"}}}}, // 0x06070012
        {"ExpeditedDownloadTooShort",
         {{"605#2B00200001020000", {"585#8000200013000706"}}}}, // 0x06070013
        {"SegmentedDownloadLongerThanItsObject",
         {{"605#2100200005000000", {"585#8000200012000706"}}}}, // 0x06070012
        {"SegmentedDownloadShorterThanIndicated",
         {{"605#2103200009000000", {"585#6003200000000000"}},
          {"605#0501020304050600", {"585#8003200013000706"}}}}, // 0x06070013
        {"SegmentedDownloadLongerThanIndicated",
         {{"605#2103200005000000", {"585#6003200000000000"}},
          {"605#0001020304050607", {"585#8003200012000706"}}}}, // 0x06070012
        // 9 bytes indicated, 8 sent (6 unused in the last segment), with their right CRC.
        {"BlockDownloadShorterThanIndicated",
         {{"605#C603200009000000", {"585#A40320007F000000"}},
          {"605#0101020304050607", {}},
          {"605#8208000000000000", {"585#A2027F0000000000"}},
          {"605#D9AC760000000000", {"585#8003200013000706"}}}}, // 0x06070013
        {"UnknownCommandSpecifier",
         {{"605#E000200000000000", {"585#8000200001000405"}}}}, // 0x05040001
        {"SegmentWithTheWrongToggle",
         {{"605#2103200009000000", {"585#6003200000000000"}},
          {"605#1001020304050607", {"585#8003200000000305"}}}}, // 0x05030000
        {"UploadSegmentWithTheWrongToggle",
         {{"605#4001200000000000", {"585#4101200012000000"}},
          {"605#7000000000000000", {"585#8001200000000305"}}}}, // 0x05030000
        {"BlockDownloadWithTheWrongCrc",
         {{"605#C603200009000000", {"585#A40320007F000000"}},
          {"605#0101020304050607", {}},
          {"605#8208090000000000", {"585#A2027F0000000000"}},
          {"605#D579230000000000", {"585#8003200004000405"}}}}, // 0x05040004
        // A client abort ends the transfer silently; the next request starts afresh.
        {"ClientAbortEndsTheTransfer",
         {{"605#4001200000000000", {"585#4101200012000000"}},
          {"605#8001200000000405", {}},
          {"605#4000200000000000", {"585#4300200044332211"}}}},
    };
}

INSTANTIATE_TEST_SUITE_P(Transfers, SdoConformance, ::testing::ValuesIn(sdo_transfers()),
                         conversation_name);
INSTANTIATE_TEST_SUITE_P(Aborts, SdoConformance, ::testing::ValuesIn(sdo_aborts()),
                         conversation_name);

TEST_F(Conformance, StalledSegmentedTransferIsAbortedAfterTheServerTimeout) {
    const core::TimePoint requested = bench.loop.now();
    expect_reply("605#4001200000000000", "585#4101200012000000");
    bench.run_for(1100ms);
    // SdoServerConfig's 1 s after the last request: 0x05040000 on the transfer's object.
    const auto frames = sent_since(requested, 0x585);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[1].frame, "585#8001200000000405");
    EXPECT_GE(frames[1].at - requested, 1s);
    EXPECT_LT(frames[1].at - requested, 1s + 1ms);
}

// --- PDO mapping and COB-ID rules (CiA 301 7.5.2.35-38), through SDO frames. ---

std::vector<SdoConversation> pdo_mapping_rules() {
    // TPDO1: 0x1800 (communication), 0x1A00 (mapping); 0xC0000185 invalid by default.
    const SdoStep map_u32{"605#23001A0120000020", {"585#60001A0100000000"}};
    const SdoStep one_entry{"605#2F001A0001000000", {"585#60001A0000000000"}};
    const SdoStep validate{"605#2300180185010040", {"585#6000180100000000"}};
    return {
        // CiA 301 7.5.2.36: invalid PDO, entries, number of entries, valid; then the mapping
        // is locked (0x06040043) and so is the COB-ID (0x06090030). Writing a value again
        // unchanged is accepted (a tool rewriting a whole configuration).
        {"MappingChangesOnlyWhileThePdoIsInvalid",
         {map_u32,
          one_entry,
          validate,
          {"605#2F001A0000000000", {"585#80001A0043000406"}},
          {"605#23001A0108000520", {"585#80001A0143000406"}},
          {"605#2300180186010040", {"585#8000180130000906"}},
          {"605#2300180185010040", {"585#6000180100000000"}}, // the same COB-ID again
          {"605#23001801850100C0", {"585#6000180100000000"}}, // invalid again
          {"605#2F001A0000000000", {"585#60001A0000000000"}}}},
        {"EntryWhileTheNumberOfEntriesIsNotZero",
         {map_u32, one_entry, {"605#23001A0108000520", {"585#80001A0143000406"}}}},
        {"ObjectThatIsNotMappable",
         {{"605#23001A0120000620", {"585#80001A0141000406"}}}},                  // 0x06040041
        {"MissingObject", {{"605#23001A0120000030", {"585#80001A0100000206"}}}}, // 0x06020000
        {"MoreThan64Bits",
         {map_u32,
          {"605#23001A0220000020", {"585#60001A0200000000"}},
          {"605#23001A0308000520", {"585#60001A0300000000"}},
          {"605#2F001A0003000000", {"585#80001A0042000406"}}}}, // 0x06040042
    };
}

INSTANTIATE_TEST_SUITE_P(PdoMappingRules, SdoConformance, ::testing::ValuesIn(pdo_mapping_rules()),
                         conversation_name);

// --- NMT (CiA 301 7.3.2, figure 48): every command from every state, to the node, to all
// nodes (0) or to another node (ignored); the heartbeat (7.2.8.3.2.2) shows the new state. ---

struct NmtCase {
    std::string name;
    NmtState from;
    std::uint8_t command;
    NodeId addressed;
    std::vector<std::string> frames; ///< what the node sends in the 10 ms after the command
};

class NmtConformance : public Conformance, public ::testing::WithParamInterface<NmtCase> {};

TEST_P(NmtConformance, CommandIsFollowedByTheStateInTheHeartbeat) {
    const NmtCase& c = GetParam();
    sdo_write(0x1017, 0, 10, 2); // heartbeat every 10 ms
    if (c.from == NmtState::Operational) {
        bench.send("000#0105");
    } else if (c.from == NmtState::Stopped) {
        bench.send("000#0205");
    }
    bench.run_for(1ms);
    ASSERT_EQ(node.nmt_state(), c.from);
    const core::TimePoint commanded = bench.loop.now();
    bench.send(fmt::format("000#{:02X}{:02X}", c.command, c.addressed));
    bench.run_for(10ms);
    EXPECT_EQ(frames_since(commanded, 0x705), c.frames);
}

std::vector<NmtCase> nmt_cases() {
    struct Command {
        std::string_view name;
        std::uint8_t specifier;
        std::optional<NmtState> to; ///< empty: a reset, which boots again
    };
    const Command commands[] = {{"Start", 0x01, NmtState::Operational},
                                {"Stop", 0x02, NmtState::Stopped},
                                {"EnterPreOperational", 0x80, NmtState::PreOperational},
                                {"ResetNode", 0x81, std::nullopt},
                                {"ResetCommunication", 0x82, std::nullopt}};
    const std::pair<NmtState, std::string_view> states[] = {
        {NmtState::PreOperational, "PreOperational"},
        {NmtState::Operational, "Operational"},
        {NmtState::Stopped, "Stopped"}};
    // CiA 301 table 49: the heartbeat's state byte.
    const auto heartbeat = [](NmtState state) {
        switch (state) {
        case NmtState::Stopped:
            return std::string("705#04");
        case NmtState::Operational:
            return std::string("705#05");
        default:
            return std::string("705#7F");
        }
    };
    std::vector<NmtCase> cases;
    for (const auto& [from, from_name] : states) {
        for (const Command& command : commands) {
            // A reset boots again with 0x1017 at its default 0: the boot-up and no heartbeat.
            const std::vector<std::string> obeyed = command.to ? std::vector{heartbeat(*command.to)}
                                                               : std::vector<std::string>{"705#00"};
            for (const NodeId addressed : {kNode, NodeId{0}, NodeId{6}}) {
                const std::string to = addressed == kNode ? "ToTheNode"
                                       : addressed == 0   ? "ToAllNodes"
                                                          : "ToAnotherNode";
                cases.push_back({fmt::format("{}{}From{}", command.name, to, from_name), from,
                                 command.specifier, addressed,
                                 addressed == 6 ? std::vector{heartbeat(from)} : obeyed});
            }
        }
    }
    return cases;
}

std::string nmt_case_name(const ::testing::TestParamInfo<NmtCase>& info) {
    return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(EveryTransition, NmtConformance, ::testing::ValuesIn(nmt_cases()),
                         nmt_case_name);

// --- Node guarding and life guarding (CiA 301 7.2.8.3.2.1). ---

TEST_F(Conformance, NodeGuardingAnswersTheStateWithAToggleBitThatAResetClears) {
    expect_reply("705#R", "705#7F");
    expect_reply("705#R", "705#FF");
    bench.send("000#0105");
    bench.run_for(1ms);
    expect_reply("705#R", "705#05");
    bench.send("000#0205");
    bench.run_for(1ms);
    expect_reply("705#R", "705#84");
    expect_reply("000#8205", "705#00");
    expect_reply("705#R", "705#7F");
}

TEST_F(Conformance, LifeGuardingEventSendsAnEmcyAfterGuardTimeTimesLifeTimeFactor) {
    sdo_write(0x100C, 0, 10, 2); // guard time 10 ms
    sdo_write(0x100D, 0, 3, 1);  // life time factor 3
    const core::TimePoint guarded = bench.loop.now();
    expect_reply("705#R", "705#7F");
    bench.run_for(40ms);
    // EMCY 0x8130 (life guard error), error register 0x11 (communication, generic).
    const auto emcys = sent_since(guarded, 0x085);
    ASSERT_EQ(emcys.size(), 1u);
    EXPECT_EQ(emcys[0].frame, "085#3081110000000000");
    EXPECT_GE(emcys[0].at - guarded, 30ms);
    EXPECT_LT(emcys[0].at - guarded, 31ms);
}

TEST_F(Conformance, LifeGuardingRequestAfterTheEventIsAnsweredWithTheNextToggle) {
    sdo_write(0x100C, 0, 10, 2);
    sdo_write(0x100D, 0, 3, 1);
    expect_reply("705#R", "705#7F");
    bench.run_for(40ms);
    // The request also ends the life guarding event: the error reset EMCY follows.
    EXPECT_EQ(exchange("705#R"), (std::vector<std::string>{"705#FF", "085#0000000000000000"}));
}

// --- Heartbeat consumer (CiA 301 7.2.8.3.2.2, 0x1016). ---

TEST_F(Conformance, HeartbeatConsumerTimeoutSendsAnEmcyOneConsumerTimeAfterTheLastHeartbeat) {
    sdo_write(0x1016, 1, 0x0010'0014, 4); // node 0x10 within 20 ms
    for (int beat = 0; beat < 5; ++beat) {
        bench.send("710#05");
        bench.run_for(15ms);
    }
    EXPECT_EQ(frames_since(core::TimePoint{}, 0x085), std::vector<std::string>{});
    const core::TimePoint last_beat = bench.loop.now();
    bench.send("710#05");
    bench.run_for(30ms);
    const auto emcys = sent_since(last_beat, 0x085);
    ASSERT_EQ(emcys.size(), 1u);
    EXPECT_EQ(emcys[0].frame, "085#3081110000000000");
    // Monitoring runs from the reception of the heartbeat (the end of its frame).
    const core::TimePoint received = testing::end_of(last_beat, "710#05");
    EXPECT_EQ(emcys[0].at, received + 20ms);
}

TEST_F(Conformance, HeartbeatProducerSilencesNodeGuarding) {
    sdo_write(0x1017, 0, 100, 2);
    EXPECT_EQ(exchange("705#R"), std::vector<std::string>{});
}

// --- PDO timing (CiA 301 7.2.2.2, 7.5.2.35): transmission types, inhibit time, event timer. ---

class PdoTiming : public Conformance {
protected:
    /// TPDO1 on 0x185 (RTR allowed) carrying 0x2000, with the given parameters; then operational.
    void start_with_tpdo(std::uint8_t transmission_type, std::uint16_t inhibit_100us = 0,
                         std::uint16_t event_timer_ms = 0) {
        sdo_write(0x1A00, 1, 0x2000'0020, 4);
        sdo_write(0x1A00, 0, 1, 1);
        sdo_write(0x1800, 2, transmission_type, 1);
        sdo_write(0x1800, 3, inhibit_100us, 2);
        sdo_write(0x1800, 5, event_timer_ms, 2);
        sdo_write(0x1800, 1, 0x185, 4);
        bench.send("000#0105");
        bench.run_for(1ms);
    }
    /// Sends `count` SYNCs 1 ms apart; returns after which of them (1-based) a TPDO came.
    std::vector<int> syncs_answered(int count) {
        std::vector<int> answered;
        for (int sync = 1; sync <= count; ++sync) {
            if (!exchange("080#", 1ms).empty()) {
                answered.push_back(sync);
            }
        }
        return answered;
    }
};

class SynchronousTransmission : public PdoTiming, public ::testing::WithParamInterface<int> {};

TEST_P(SynchronousTransmission, TypeNIsSentAfterEveryNthSync) {
    const int type = GetParam();
    start_with_tpdo(static_cast<std::uint8_t>(type));
    EXPECT_EQ(syncs_answered(2 * type), (std::vector<int>{type, 2 * type}));
}

INSTANTIATE_TEST_SUITE_P(Types1To240, SynchronousTransmission, ::testing::Values(1, 2, 5, 240));

TEST_F(PdoTiming, Type252SendsOnRtrTheDataSampledAtTheLastSync) {
    start_with_tpdo(252);
    EXPECT_EQ(exchange("080#"), std::vector<std::string>{});
    sdo_write(0x2000, 0, 0xAABB'CCDD, 4);
    expect_reply("185#R", "185#44332211");
    exchange("080#");
    expect_reply("185#R", "185#DDCCBBAA");
}

TEST_F(PdoTiming, Type253SendsOnRtrOnlyWithTheCurrentData) {
    start_with_tpdo(253);
    EXPECT_EQ(exchange("080#"), std::vector<std::string>{});
    sdo_write(0x2000, 0, 0xAABB'CCDD, 4);
    expect_reply("185#R", "185#DDCCBBAA");
}

TEST_F(PdoTiming, NoTpdoAnswersAnRtrWhenItsCobIdForbidsIt) {
    start_with_tpdo(253);
    bench.send("000#8005");
    bench.run_for(1ms);
    sdo_write(0x1800, 1, 0x8000'0185, 4);
    sdo_write(0x1800, 1, 0x4000'0185, 4); // bit 30: no RTR allowed
    bench.send("000#0105");
    bench.run_for(1ms);
    EXPECT_EQ(exchange("185#R"), std::vector<std::string>{});
}

class EventDrivenTransmission : public PdoTiming,
                                public ::testing::WithParamInterface<std::uint8_t> {};

TEST_P(EventDrivenTransmission, InhibitTimeSpacesChangesAndTheEventTimerRepeats) {
    const core::TimePoint started = bench.loop.now();
    start_with_tpdo(GetParam(), 100, 50); // inhibit 10 ms, event timer 50 ms
    sdo_write(0x2000, 0, 0xAABB'CCDD, 4); // changed within the inhibit time
    bench.run_for(120ms);
    const auto tpdos = sent_since(started, 0x185);
    ASSERT_EQ(tpdos.size(), 4u);
    EXPECT_EQ(tpdos[0].frame, "185#44332211"); // on entering operational
    EXPECT_EQ(tpdos[1].frame, "185#DDCCBBAA");
    // The inhibit time runs from when the node queued the first TPDO, at the end of the NMT
    // command: the frame itself started 3 bits (intermission) later.
    EXPECT_EQ(tpdos[1].at, tpdos[0].at - std::chrono::microseconds(can::kIntermissionBits) + 10ms);
    EXPECT_EQ(tpdos[2].at - tpdos[1].at, 50ms);
    EXPECT_EQ(tpdos[3].at - tpdos[2].at, 50ms);
}

INSTANTIATE_TEST_SUITE_P(Types254And255, EventDrivenTransmission,
                         ::testing::Values(std::uint8_t{254}, std::uint8_t{255}));

// --- EMCY (CiA 301 7.2.7): the frame, the error history 0x1003 and the COB-ID 0x1014. ---

class EmcyConformance : public Conformance {
protected:
    /// RPDO1 on 0x205 mapping 0x2000 (4 bytes); operational.
    void start_with_rpdo() {
        sdo_write(0x1600, 1, 0x2000'0020, 4);
        sdo_write(0x1600, 0, 1, 1);
        sdo_write(0x1400, 1, 0x205, 4);
        bench.send("000#0105");
        bench.run_for(1ms);
    }
};

TEST_F(EmcyConformance, TooShortRpdoRaisesPdoLengthErrorIntoTheErrorHistory) {
    start_with_rpdo();
    // 0x8210: PDO not processed due to length error; error register 0x11 (communication and,
    // with every error, generic: CiA 301 7.5.2.2).
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{"085#1082110000000000"});
    EXPECT_EQ(od.get_as<std::uint32_t>(0x2000, 0), 0x1122'3344u);
    expect_reply("605#4001100000000000", "585#4F01100011000000");
    expect_reply("605#4003100000000000", "585#4F03100001000000");
    expect_reply("605#4003100100000000", "585#4303100110820000");
    // Only 0 may be written to sub-index 0, and it empties the history (CiA 301 7.5.2.6).
    expect_reply("605#2F03100001000000", "585#8003100030000906");
    expect_reply("605#2F03100000000000", "585#6003100000000000");
    expect_reply("605#4003100000000000", "585#4F03100000000000");
}

// --- Error lifetime (CiA 301 7.2.7.1): an error ends with its cause, with the error reset
// EMCY 0x0000 and the register bits it held cleared. ---

TEST_F(EmcyConformance, RpdoOfTheRightLengthEndsTheLengthError) {
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{"085#1082110000000000"});
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{}) << "one EMCY per error event";
    EXPECT_EQ(exchange("205#05060708"), std::vector<std::string>{"085#0000000000000000"});
    EXPECT_EQ(od.get_as<std::uint32_t>(0x2000, 0), 0x0807'0605u);
    expect_reply("605#4001100000000000", "585#4F01100000000000");
    // The next short RPDO is a new error event.
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{"085#1082110000000000"});
}

TEST_F(EmcyConformance, TooLongRpdoErrorEndsWithTheNextRpdoOfTheRightLength) {
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102030405"), std::vector<std::string>{"085#2082110000000000"});
    EXPECT_EQ(exchange("205#01020304"), std::vector<std::string>{"085#0000000000000000"});
}

TEST_F(EmcyConformance, ShortRpdoAfterALongOneEndsTheOneAndRaisesTheOther) {
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102030405"), std::vector<std::string>{"085#2082110000000000"});
    EXPECT_EQ(exchange("205#01"),
              (std::vector<std::string>{"085#1082110000000000", "085#0000110000000000"}));
}

struct ResetCase {
    std::string name;
    std::string command;
};

class EmcyReset : public EmcyConformance, public ::testing::WithParamInterface<ResetCase> {};

// CiA 301 7.3.2.2.1: the reset brings 0x1001 back to its power-on value; the error reset EMCY
// follows the boot-up, and a short RPDO after the restart is a new error event.
TEST_P(EmcyReset, ResetEndsTheErrorAndTheNextOneIsSignalledAgain) {
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{"085#1082110000000000"});
    EXPECT_EQ(exchange(GetParam().command),
              (std::vector<std::string>{"705#00", "085#0000000000000000"}));
    expect_reply("605#4001100000000000", "585#4F01100000000000");
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{"085#1082110000000000"});
}

INSTANTIATE_TEST_SUITE_P(NmtResets, EmcyReset,
                         ::testing::Values(ResetCase{"ResetNode", "000#8105"},
                                           ResetCase{"ResetCommunication", "000#8205"}),
                         [](const ::testing::TestParamInfo<ResetCase>& reset) {
                             return reset.param.name;
                         });

// CiA 301 7.5.2.6 empties the history; the register shows the errors still active.
TEST_F(EmcyConformance, EmptyingTheHistoryKeepsTheRegisterOfTheActiveError) {
    start_with_rpdo();
    bench.send("205#0102");
    bench.run_for(1ms);
    expect_reply("605#2F03100000000000", "585#6003100000000000");
    expect_reply("605#4001100000000000", "585#4F01100011000000");
}

TEST_F(EmcyConformance, NextHeartbeatEndsTheHeartbeatEvent) {
    sdo_write(0x1016, 1, 0x0010'0014, 4); // node 0x10 within 20 ms
    bench.send("710#05");
    bench.run_for(30ms);
    EXPECT_EQ(frames_since(core::TimePoint{}, 0x085),
              std::vector<std::string>{"085#3081110000000000"});
    EXPECT_EQ(exchange("710#05"), std::vector<std::string>{"085#0000000000000000"});
    expect_reply("605#4001100000000000", "585#4F01100000000000");
}

TEST_F(EmcyConformance, SyncOfTheRightLengthEndsTheSyncLengthError) {
    sdo_write(0x1019, 0, 10, 1); // SYNCs carry a counter
    EXPECT_EQ(exchange("080#"), std::vector<std::string>{"085#4082110000000000"});
    EXPECT_EQ(exchange("080#"), std::vector<std::string>{});
    EXPECT_EQ(exchange("080#01"), std::vector<std::string>{"085#0000000000000000"});
}

TEST_F(EmcyConformance, InvalidEmcyCobIdSendsNothing) {
    sdo_write(0x1014, 0, 0x8000'0085, 4);
    start_with_rpdo();
    EXPECT_EQ(exchange("205#0102"), std::vector<std::string>{});
}

// --- LSS (CiA 305): requests on 0x7E5, replies on 0x7E4, reserved bytes zero. ---

class LssConformance : public Conformance {};

TEST_F(LssConformance, InquireServicesAnswerTheIdentityAndTheNodeId) {
    bench.send("7E5#0401000000000000"); // switch state global: configuration
    bench.run_for(1ms);
    expect_reply("7E5#5A00000000000000", "7E4#5AFB000000000000");
    expect_reply("7E5#5B00000000000000", "7E4#5B01000000000000");
    expect_reply("7E5#5C00000000000000", "7E4#5C02000000000000");
    expect_reply("7E5#5D00000000000000", "7E4#5D03000000000000");
    expect_reply("7E5#5E00000000000000", "7E4#5E05000000000000");
}

TEST_F(LssConformance, InWaitingStateOnlyIdentificationIsAnswered) {
    EXPECT_EQ(exchange("7E5#5A00000000000000"), std::vector<std::string>{});
    EXPECT_EQ(exchange("7E5#1107000000000000"), std::vector<std::string>{});
}

TEST_F(LssConformance, SwitchStateSelectiveIsConfirmedAfterTheSerialNumber) {
    EXPECT_EQ(exchange("7E5#40FB000000000000"), std::vector<std::string>{});
    EXPECT_EQ(exchange("7E5#4101000000000000"), std::vector<std::string>{});
    EXPECT_EQ(exchange("7E5#4202000000000000"), std::vector<std::string>{});
    expect_reply("7E5#4303000000000000", "7E4#4400000000000000");
}

TEST_F(LssConformance, SwitchStateSelectiveOfAnotherDeviceIsNotConfirmed) {
    bench.send("7E5#40FB000000000000");
    bench.send("7E5#4101000000000000");
    bench.send("7E5#4202000000000000");
    EXPECT_EQ(exchange("7E5#4304000000000000"), std::vector<std::string>{});
}

TEST_F(LssConformance, IdentifyRemoteSlaveAnswersWhenTheIdentityIsInTheRanges) {
    for (const char* request :
         {"7E5#46FB000000000000", "7E5#4701000000000000", "7E5#4800000000000000",
          "7E5#4910000000000000", "7E5#4A00000000000000"}) {
        EXPECT_EQ(exchange(request), std::vector<std::string>{}) << request;
    }
    expect_reply("7E5#4B03000000000000", "7E4#4F00000000000000");
}

TEST_F(LssConformance, ConfiguredNodeDoesNotAnswerIdentifyNonConfigured) {
    EXPECT_EQ(exchange("7E5#4C00000000000000"), std::vector<std::string>{});
}

TEST_F(LssConformance, ConfiguredNodeIdTakesEffectAtResetCommunication) {
    bench.send("7E5#0401000000000000");
    bench.run_for(1ms);
    expect_reply("7E5#1107000000000000", "7E4#1100000000000000");
    // 0 and 128..254 are invalid node-IDs: error code 1 (CiA 305 8.3.2.1).
    expect_reply("7E5#1180000000000000", "7E4#1101000000000000");
    bench.send("7E5#0400000000000000"); // back to waiting
    bench.run_for(1ms);
    expect_reply("000#8205", "707#00");
    expect_reply("607#4000100000000000", "587#4300100092010200");
}

TEST_F(LssConformance, BitTimingAndStoreAreRefusedWhereTheDeviceCannotDoThem) {
    bench.send("7E5#0401000000000000");
    bench.run_for(1ms);
    // No bit rate switch and no parameter file in this node: "not supported" (error code 1).
    expect_reply("7E5#1300000000000000", "7E4#1301000000000000");
    expect_reply("7E5#1700000000000000", "7E4#1701000000000000");
}

} // namespace
} // namespace eposp::canopen
