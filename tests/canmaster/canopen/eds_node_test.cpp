// Conformance of a node built from an EDS (as `eposp node` builds one), not from the services'
// own defaults: the rules of CiA 301 and CiA 305 hold for the objects the EDS brings, driven
// through raw frames only.
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/node.hpp"
#include "node_tester.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::conversation_name;
using testing::SdoConversation;

constexpr NodeId kNode = 5;

std::string entry(std::string_view section, std::string_view type, std::string_view access,
                  std::string_view value, bool mappable = false) {
    return fmt::format("[{}]\nParameterName={}\nObjectType=0x7\nDataType={}\nAccessType={}\n"
                       "DefaultValue={}\nPDOMapping={}\n\n",
                       section, section, type, access, value, mappable ? 1 : 0);
}

std::string record(std::string_view index, int sub_number) {
    return fmt::format("[{}]\nParameterName=PDO {}\nObjectType=0x9\nSubNumber={}\n\n", index, index,
                       sub_number);
}

/// A PDO's communication record: COB-ID and transmission type 255.
std::string pdo_communication(std::string_view index, std::string_view cob_id) {
    return record(index, 3) + entry(fmt::format("{}sub0", index), "0x0005", "ro", "2") +
           entry(fmt::format("{}sub1", index), "0x0007", "rw", cob_id) +
           entry(fmt::format("{}sub2", index), "0x0005", "rw", "0xFF");
}

/// A PDO's mapping record of 4 entries, the first one in use.
std::string pdo_mapping(std::string_view index, std::string_view first) {
    std::string text = record(index, 5) + entry(fmt::format("{}sub0", index), "0x0005", "rw", "1") +
                       entry(fmt::format("{}sub1", index), "0x0007", "rw", first);
    for (int sub = 2; sub <= 4; ++sub) {
        text += entry(fmt::format("{}sub{}", index, sub), "0x0007", "rw", "0");
    }
    return text;
}

/// A vendor's device as its EDS describes it: RPDO 1 and TPDO 1 valid, each mapping 0x2000;
/// 0x2001 not mappable (PDOMapping=0), 0x2002 a 64-bit value; 250 kbit/s and 1 Mbit/s; 0x1001
/// but no 0x1003; its own SYNC, EMCY and heartbeat consumer objects, as plain data.
std::string vendor_eds() {
    return "[DeviceInfo]\nVendorNumber=0x1234\nProductName=IO box\nBaudRate_250=1\n"
           "BaudRate_500=0\nBaudRate_1000=1\nLSS_Supported=1\n\n"
           "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n\n"
           "[OptionalObjects]\nSupportedObjects=9\n1=0x1400\n2=0x1600\n3=0x1800\n4=0x1A00\n"
           "5=0x1005\n6=0x1006\n7=0x1014\n8=0x1016\n9=0x1019\n\n"
           "[ManufacturerObjects]\nSupportedObjects=3\n1=0x2000\n2=0x2001\n3=0x2002\n\n" +
           entry("1000", "0x0007", "ro", "0x191") + entry("1001", "0x0005", "ro", "0") +
           record("1018", 2) + entry("1018sub0", "0x0005", "ro", "1") +
           entry("1018sub1", "0x0007", "ro", "0x1234") + entry("1005", "0x0007", "rw", "0x80") +
           entry("1006", "0x0007", "rw", "0") + entry("1014", "0x0007", "rw", "$NODEID+0x80") +
           entry("1019", "0x0005", "rw", "0") + record("1016", 3) +
           entry("1016sub0", "0x0005", "ro", "2") + entry("1016sub1", "0x0007", "rw", "0") +
           entry("1016sub2", "0x0007", "rw", "0") + pdo_communication("1400", "$NODEID+0x200") +
           pdo_mapping("1600", "0x20000020") + pdo_communication("1800", "$NODEID+0x180") +
           pdo_mapping("1A00", "0x20000020") + entry("2000", "0x0007", "rw", "0x11223344", true) +
           entry("2001", "0x0007", "rw", "0", false) + entry("2002", "0x001B", "rw", "0", true);
}

ImportedEds imported_vendor_eds() {
    auto eds = import_eds(vendor_eds(), "vendor.eds", kNode);
    if (!eds) {
        throw std::runtime_error(eds.error());
    }
    return std::move(*eds);
}

class EdsNode : public testing::NodeTester {
protected:
    EdsNode() {
        node.start();
        bench.run_for(1ms);
    }

    /// As `eposp node` configures it: the bit rates of the EDS.
    NodeConfig config() const {
        NodeConfig config;
        config.node_id = kNode;
        config.bit_rates = eds.device.bit_rates();
        return config;
    }

    ImportedEds eds = imported_vendor_eds();
    Node node{bench.loop, *bench.device, eds.dictionary, config()};
};

// --- PDO mapping (CiA 301 7.5.2.36 / 7.5.2.38): the procedure holds for an EDS's objects. ---

class EdsNodePdoMapping : public EdsNode, public ::testing::WithParamInterface<SdoConversation> {};

TEST_P(EdsNodePdoMapping, EveryReplyIsTheSpecifiedFrame) {
    expect_conversation(GetParam().steps);
}

std::vector<SdoConversation> eds_mapping_rules() {
    const testing::SdoStep invalidate_tpdo{"605#2300180185010080", {"585#6000180100000000"}};
    const testing::SdoStep no_entries{"605#2F001A0000000000", {"585#60001A0000000000"}};
    return {
        // A valid PDO's mapping is locked (0x06040043): sub-index 0 and the entries; the
        // mapping reads back unchanged.
        {"ValidTpdoKeepsItsNumberOfEntries",
         {{"605#2F001A0000000000", {"585#80001A0043000406"}},
          {"605#40001A0000000000", {"585#4F001A0001000000"}}}},
        {"ValidTpdoKeepsItsEntries",
         {{"605#23001A0100000120", {"585#80001A0143000406"}},
          {"605#40001A0100000000", {"585#43001A0120000020"}}}},
        {"ValidRpdoKeepsItsMapping",
         {{"605#2F00160000000000", {"585#8000160043000406"}},
          {"605#2300160100000120", {"585#8000160143000406"}},
          {"605#4000160100000000", {"585#4300160120000020"}}}},
        // Entries only while sub-index 0 is 0.
        {"EntryWhileTheNumberOfEntriesIsNotZero",
         {invalidate_tpdo, {"605#23001A0220000020", {"585#80001A0243000406"}}}},
        {"MissingObject",
         {invalidate_tpdo, no_entries, {"605#23001A0120000030", {"585#80001A0100000206"}}}},
        {"ObjectWhoseEdsSaysPdoMappingIs0",
         {invalidate_tpdo, no_entries, {"605#23001A0120000120", {"585#80001A0141000406"}}}},
        {"MoreThan64Bits",
         {invalidate_tpdo,
          no_entries,
          {"605#23001A0140000220", {"585#60001A0100000000"}},
          {"605#23001A0220000020", {"585#60001A0200000000"}},
          {"605#2F001A0002000000", {"585#80001A0042000406"}},
          {"605#40001A0000000000", {"585#4F001A0000000000"}}}},
        {"MoreEntriesThanTheObjectHas",
         {invalidate_tpdo, no_entries, {"605#2F001A0005000000", {"585#80001A0042000406"}}}},
        // The whole procedure: invalid, 0 entries, entries, number, valid again.
        {"ProcedureRemapsTheTpdo",
         {invalidate_tpdo,
          no_entries,
          {"605#23001A0140000220", {"585#60001A0100000000"}},
          {"605#2F001A0001000000", {"585#60001A0000000000"}},
          {"605#2300180185010000", {"585#6000180100000000"}},
          {"605#40001A0100000000", {"585#43001A0140000220"}}}},
    };
}

INSTANTIATE_TEST_SUITE_P(Rules, EdsNodePdoMapping, ::testing::ValuesIn(eds_mapping_rules()),
                         conversation_name);

TEST_F(EdsNode, ValidPdoKeepsItsCobId) {
    expect_reply("605#2300180186010000", "585#8000180130000906"); // 0x06090030
    expect_reply("605#2300140106020000", "585#8000140130000906");
}

// --- The other communication objects of the EDS follow the services' rules (CiA 301 7.5.2). ---

TEST_F(EdsNode, CommunicationObjectsOfTheEdsFollowTheServicesRules) {
    // Reserved identifiers (CiA 301 7.3.5) for EMCY and SYNC: 0x06090030.
    expect_reply("605#2314100001070000", "585#8014100030000906");
    expect_reply("605#2305100001070000", "585#8005100030000906");
    // SYNC counter overflow 1 is reserved: 0x06090030.
    expect_reply("605#2F19100001000000", "585#8019100030000906");
    // Two heartbeat consumer entries for one producer: 0x06040043.
    expect_reply("605#2316100164001000", "585#6016100100000000");
    expect_reply("605#2316100232001000", "585#8016100243000406");
}

// --- EMCY (CiA 301 7.2.7, 7.5.2.2): the error register of the EDS's 0x1001 has the generic
// bit with the error's own, and the error ends with its cause or a reset. ---

TEST_F(EdsNode, ShortRpdoErrorEndsWithTheNextRightOneAndAtAReset) {
    bench.send("000#0105"); // operational: RPDO 1 (0x205) maps 0x2000, 32 bits
    bench.run_for(1ms);
    EXPECT_EQ(exchange("205#01"), std::vector<std::string>{"085#1082110000000000"});
    expect_reply("605#4001100000000000", "585#4F01100011000000");
    // The RPDO is applied: TPDO 1, event-driven, sends the new value of 0x2000.
    EXPECT_EQ(exchange("205#01020304"),
              (std::vector<std::string>{"085#0000000000000000", "185#01020304"}));
    EXPECT_EQ(exchange("205#01"), std::vector<std::string>{"085#1082110000000000"});
    EXPECT_EQ(exchange("000#8205"), (std::vector<std::string>{"705#00", "085#0000000000000000"}));
    expect_reply("605#4001100000000000", "585#4F01100000000000");
    bench.send("000#0105");
    bench.run_for(1ms);
    EXPECT_EQ(exchange("205#01"), std::vector<std::string>{"085#1082110000000000"});
}

// --- LSS (CiA 305): the node takes the bit rates its EDS declares. ---

TEST_F(EdsNode, ConfigureBitTimingTakesTheRatesTheEdsDeclaresAndActivateAppliesIt) {
    bench.send("7E5#0401000000000000"); // switch state global: configuration
    bench.run_for(1ms);
    // Table 0 index 3 is 250 kbit/s (BaudRate_250=1): success; index 2, 500 kbit/s
    // (BaudRate_500=0), and index 4, 125 kbit/s (not listed): bit timing not supported (1).
    expect_reply("7E5#1300030000000000", "7E4#1300000000000000");
    expect_reply("7E5#1300020000000000", "7E4#1301000000000000");
    expect_reply("7E5#1300040000000000", "7E4#1301000000000000");
    EXPECT_EQ(node.bit_rate(), 1'000'000u) << "pending until activate bit timing";
    // Activate bit timing with a switch delay of 10 ms: silent for two delays, then the node
    // runs at the new rate.
    EXPECT_EQ(exchange("7E5#150A000000000000", 25ms), std::vector<std::string>{});
    EXPECT_EQ(node.bit_rate(), 250'000u);
}

TEST_F(EdsNode, WithoutNonVolatileMemoryStoreConfigurationIsNotSupported) {
    bench.send("7E5#0401000000000000");
    bench.run_for(1ms);
    expect_reply("7E5#1700000000000000", "7E4#1701000000000000");
}

} // namespace
} // namespace eposp::canopen
