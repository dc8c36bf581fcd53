#include "pdo_test_support.hpp"
#include "eposp/canopen/pdo_objects.hpp"

#include <array>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>
#include <vector>

// The write rules of the PDO communication and mapping objects (CiA 301 7.5.2.35 - 7.5.2.38),
// each with its abort code, and the defaults of CiA 301 and of the EPOS2 (FW spec 8.2.18 -
// 8.2.33).

namespace eposp::canopen {
namespace {

using testing::kNode;

/// One remote write of `size` bytes.
struct Write {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    std::uint32_t value = 0;
    std::size_t size = 4;
};
Write u8(std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    return {index, sub, value, 1};
}
Write u16(std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    return {index, sub, value, 2};
}
Write u32(std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    return {index, sub, value, 4};
}

AbortCode apply(ObjectDictionary& od, const Write& write) {
    Bytes data(write.size);
    for (std::size_t i = 0; i < write.size; ++i) {
        data[i] = static_cast<std::uint8_t>(write.value >> (8 * i));
    }
    return od.write(write.index, write.sub_index, data);
}

std::string hex(AbortCode code) {
    return fmt::format("0x{:08X} {}", static_cast<std::uint32_t>(code), describe(code));
}

struct RuleCase {
    std::string name;
    std::vector<Write> setup; ///< writes that must succeed first
    Write write;
    AbortCode expected = AbortCode::None;
    friend void PrintTo(const RuleCase& c, std::ostream* os) { *os << c.name; }
};

// Node 5, CiA 301 defaults: RPDO 1 at 0x1400 / 0x1600 (0x80000205), TPDO 1 at 0x1800 / 0x1A00
// (0xC0000185), all invalid and unmapped.
constexpr std::uint16_t kRpdoComm = 0x1400;
constexpr std::uint16_t kRpdoMap = 0x1600;
constexpr std::uint16_t kTpdoComm = 0x1800;
constexpr std::uint16_t kTpdoMap = 0x1A00;

const Write kRpdoValid = u32(kRpdoComm, 1, 0x205);
const Write kTpdoValid = u32(kTpdoComm, 1, 0x4000'0185);

std::vector<RuleCase> cob_id_cases() {
    std::vector<RuleCase> cases = {
        {"ValidPdoKeepsItsCanId", {kRpdoValid}, u32(kRpdoComm, 1, 0x206), AbortCode::InvalidValue},
        {"ValidPdoKeepsItsFrameFormat",
         {kRpdoValid},
         u32(kRpdoComm, 1, 0x2000'0205),
         AbortCode::InvalidValue},
        {"ValidPdoMayBeInvalidated", {kRpdoValid}, u32(kRpdoComm, 1, 0x8000'0205), AbortCode::None},
        {"InvalidPdoTakesANewCanIdAndBecomesValidAtOnce",
         {},
         u32(kRpdoComm, 1, 0x210),
         AbortCode::None},
        {"ValidTpdoMayChangeItsRtrBit", {kTpdoValid}, u32(kTpdoComm, 1, 0x185), AbortCode::None},
        {"ValidPdoTakesItsOwnCobIdAgain", {kRpdoValid}, kRpdoValid, AbortCode::None},
        {"InvalidPdoMayHoldCanId0", {}, u32(kRpdoComm, 1, 0x8000'0000), AbortCode::None},
        {"InvalidPdoMayHoldARestrictedCanId", {}, u32(kRpdoComm, 1, 0x8000'0601), AbortCode::None},
        {"BaseFrameCobIdWithBits11To28Set", {}, u32(kRpdoComm, 1, 0x805), AbortCode::InvalidValue},
        {"InvalidBaseFrameCobIdWithBits11To28Set",
         {},
         u32(kRpdoComm, 1, 0x8000'0805),
         AbortCode::InvalidValue},
        {"ExtendedCanId", {}, u32(kRpdoComm, 1, 0x2000'0805), AbortCode::None},
        {"HighestExtendedCanId", {}, u32(kTpdoComm, 1, 0x3FFF'FFFF), AbortCode::None},
    };
    // CiA 301 7.3.5: the CAN-IDs of NMT, SDO, LSS and NMT error control, at each range's ends.
    for (const std::uint32_t id : {0x000U, 0x001U, 0x07FU, 0x101U, 0x180U, 0x581U, 0x5FFU, 0x601U,
                                   0x67FU, 0x6E0U, 0x6FFU, 0x701U, 0x77FU, 0x780U, 0x7FFU}) {
        cases.push_back({fmt::format("RestrictedCanId{:03X}", id),
                         {},
                         u32(kRpdoComm, 1, id),
                         AbortCode::InvalidValue});
    }
    for (const std::uint32_t id :
         {0x080U, 0x100U, 0x181U, 0x580U, 0x600U, 0x680U, 0x6DFU, 0x700U}) {
        cases.push_back(
            {fmt::format("FreeCanId{:03X}", id), {}, u32(kRpdoComm, 1, id), AbortCode::None});
    }
    return cases;
}

std::vector<RuleCase> transmission_type_cases() {
    std::vector<RuleCase> cases;
    const auto add = [&cases](const char* pdo, std::uint16_t comm, unsigned type, AbortCode code) {
        cases.push_back(
            {fmt::format("{}TransmissionType{}", pdo, type), {}, u8(comm, 2, type), code});
    };
    for (const unsigned type : {0U, 1U, 240U, 254U, 255U}) {
        add("Rpdo", kRpdoComm, type, AbortCode::None);
    }
    for (const unsigned type : {241U, 251U, 252U, 253U}) {
        add("Rpdo", kRpdoComm, type, AbortCode::InvalidValue);
    }
    for (const unsigned type : {0U, 240U, 252U, 253U, 254U, 255U}) {
        add("Tpdo", kTpdoComm, type, AbortCode::None);
    }
    for (const unsigned type : {241U, 251U}) {
        add("Tpdo", kTpdoComm, type, AbortCode::InvalidValue);
    }
    cases.push_back({"TransmissionTypeOfValidPdoMayChange",
                     {kTpdoValid},
                     u8(kTpdoComm, 2, 1),
                     AbortCode::None});
    return cases;
}

std::vector<RuleCase> tpdo_parameter_cases() {
    return {
        {"InhibitTimeOfValidTpdoIsFixed",
         {kTpdoValid},
         u16(kTpdoComm, 3, 10),
         AbortCode::InvalidValue},
        {"InhibitTimeOfInvalidTpdo", {}, u16(kTpdoComm, 3, 10), AbortCode::None},
        {"ValidTpdoTakesItsInhibitTimeAgain", {kTpdoValid}, u16(kTpdoComm, 3, 0), AbortCode::None},
        {"SyncStartOfValidTpdoIsFixed", {kTpdoValid}, u8(kTpdoComm, 6, 3), AbortCode::InvalidValue},
        {"SyncStartOfInvalidTpdo", {}, u8(kTpdoComm, 6, 240), AbortCode::None},
        {"SyncStartAbove240", {}, u8(kTpdoComm, 6, 241), AbortCode::InvalidValue},
        {"EventTimerOfValidTpdoMayChange", {kTpdoValid}, u16(kTpdoComm, 5, 100), AbortCode::None},
        {"ReservedSubIndex4DoesNotExist", {}, u8(kTpdoComm, 4, 0), AbortCode::SubIndexDoesNotExist},
        {"RpdoHasNoInhibitTime", {}, u16(kRpdoComm, 3, 0), AbortCode::SubIndexDoesNotExist},
    };
}

std::vector<RuleCase> mapping_cases() {
    const Write controlword = u32(kRpdoMap, 1, 0x6040'0010);
    const Write one_mapped = u8(kRpdoMap, 0, 1);
    return {
        // CiA 301 7.5.2.36: invalid PDO, sub-index 0 = 0, entries, sub-index 0 = n, valid.
        {"EntryOfValidPdo", {kRpdoValid}, controlword, AbortCode::ParameterIncompatibility},
        {"EntryWhileSubIndex0IsNotZero",
         {controlword, one_mapped},
         u32(kRpdoMap, 2, 0x607A'0020),
         AbortCode::ParameterIncompatibility},
        {"CountOfValidPdo",
         {controlword, one_mapped, kRpdoValid},
         u8(kRpdoMap, 0, 0),
         AbortCode::ParameterIncompatibility},
        {"ValidPdoTakesItsEntryAgain",
         {controlword, one_mapped, kRpdoValid},
         controlword,
         AbortCode::None},
        {"ValidPdoTakesItsCountAgain",
         {controlword, one_mapped, kRpdoValid},
         one_mapped,
         AbortCode::None},
        {"MissingObject", {}, u32(kRpdoMap, 1, 0x5000'0010), AbortCode::ObjectDoesNotExist},
        {"MissingSubIndex", {}, u32(kRpdoMap, 1, 0x6040'0110), AbortCode::ObjectDoesNotExist},
        {"ObjectThatIsNotMappable", {}, u32(kRpdoMap, 1, 0x2020'0020), AbortCode::NotMappable},
        {"ReadOnlyObjectIntoRpdo", {}, u32(kRpdoMap, 1, 0x6041'0010), AbortCode::NotMappable},
        {"ReadOnlyObjectIntoTpdo", {}, u32(kTpdoMap, 1, 0x6041'0010), AbortCode::None},
        {"WriteOnlyObjectIntoTpdo", {}, u32(kTpdoMap, 1, 0x2022'0020), AbortCode::NotMappable},
        {"WriteOnlyObjectIntoRpdo", {}, u32(kRpdoMap, 1, 0x2022'0020), AbortCode::None},
        {"MoreBitsThanTheObject", {}, u32(kRpdoMap, 1, 0x6040'0011), AbortCode::NotMappable},
        {"ZeroBits", {}, u32(kRpdoMap, 1, 0x6040'0000), AbortCode::NotMappable},
        {"PartOfAReal", {}, u32(kRpdoMap, 1, 0x2006'0010), AbortCode::NotMappable},
        {"String", {}, u32(kRpdoMap, 1, 0x2021'0018), AbortCode::NotMappable},
        {"PartOfAnInteger", {}, u32(kRpdoMap, 1, 0x2002'0007), AbortCode::None},
        {"OneBitBoolean", {}, u32(kRpdoMap, 1, 0x2001'0001), AbortCode::None},
        {"ClearingAnEntry", {}, u32(kRpdoMap, 1, 0), AbortCode::None},
        // CiA 301 7.4.7.1: data types 0x0002..0x0007 as dummies, in RPDOs only.
        {"DummyInteger8", {}, u32(kRpdoMap, 1, 0x0002'0008), AbortCode::None},
        {"DummyUnsigned8", {}, u32(kRpdoMap, 1, 0x0005'0008), AbortCode::None},
        {"DummyUnsigned32", {}, u32(kRpdoMap, 1, 0x0007'0020), AbortCode::None},
        {"DummyLongerThanItsType", {}, u32(kRpdoMap, 1, 0x0007'0021), AbortCode::NotMappable},
        {"BooleanIsNoDummy", {}, u32(kRpdoMap, 1, 0x0001'0001), AbortCode::ObjectDoesNotExist},
        {"DummyInTpdo", {}, u32(kTpdoMap, 1, 0x0005'0008), AbortCode::ObjectDoesNotExist},
        {"CountAboveTheEntriesThereAre", {}, u8(kRpdoMap, 0, 9), AbortCode::PdoLengthExceeded},
        {"CountOverAnEmptyEntry", {controlword}, u8(kRpdoMap, 0, 2), AbortCode::ObjectDoesNotExist},
        {"CountOverMoreThan64Bits",
         {u32(kRpdoMap, 1, 0x2005'0040), u32(kRpdoMap, 2, 0x2001'0001)},
         u8(kRpdoMap, 0, 2),
         AbortCode::PdoLengthExceeded},
        {"CountOverExactly64Bits",
         {u32(kRpdoMap, 1, 0x607A'0020), u32(kRpdoMap, 2, 0x60FF'0020)},
         u8(kRpdoMap, 0, 2),
         AbortCode::None},
        {"CountOfZeroClearsTheMapping",
         {controlword, one_mapped},
         u8(kRpdoMap, 0, 0),
         AbortCode::None},
    };
}

class PdoRules : public ::testing::TestWithParam<RuleCase> {
protected:
    PdoRules() {
        testing::add_application_objects(od);
        add_pdo_objects(od, kNode, 4, 4);
    }
    ObjectDictionary od;
};

TEST_P(PdoRules, WriteIsRefusedWithTheSpecifiedAbortCode) {
    const RuleCase& c = GetParam();
    for (const Write& step : c.setup) {
        ASSERT_EQ(apply(od, step), AbortCode::None)
            << fmt::format("setup write {:04X}sub{}", step.index, step.sub_index);
    }
    const SubObject* target = od.find(c.write.index, c.write.sub_index);
    const Bytes before = target != nullptr ? target->value : Bytes{};
    const AbortCode code = apply(od, c.write);
    EXPECT_EQ(code, c.expected) << hex(code) << ", expected " << hex(c.expected);
    if (target != nullptr && code != AbortCode::None) {
        EXPECT_EQ(target->value, before) << "a refused write changed the value";
    }
}

std::string case_name(const ::testing::TestParamInfo<RuleCase>& info) {
    return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(CobId, PdoRules, ::testing::ValuesIn(cob_id_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(TransmissionType, PdoRules, ::testing::ValuesIn(transmission_type_cases()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(TpdoParameters, PdoRules, ::testing::ValuesIn(tpdo_parameter_cases()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(Mapping, PdoRules, ::testing::ValuesIn(mapping_cases()), case_name);

// EPOS2 FW spec tables 8-75 / 8-78: 11-bit CAN-IDs 0x181..0x57F only.
class PdoRulesEpos2 : public ::testing::TestWithParam<RuleCase> {
protected:
    PdoRulesEpos2() {
        testing::add_application_objects(od);
        add_pdo_objects(od, epos2_pdo_defaults(1));
    }
    ObjectDictionary od;
};

TEST_P(PdoRulesEpos2, WriteIsRefusedWithTheSpecifiedAbortCode) {
    const RuleCase& c = GetParam();
    for (const Write& step : c.setup) {
        ASSERT_EQ(apply(od, step), AbortCode::None);
    }
    const AbortCode code = apply(od, c.write);
    EXPECT_EQ(code, c.expected) << hex(code) << ", expected " << hex(c.expected);
}

std::vector<RuleCase> epos2_cases() {
    const Write invalidate = u32(kRpdoComm, 1, 0x8000'0201);
    return {
        {"ExtendedCanId", {invalidate}, u32(kRpdoComm, 1, 0x2000'0300), AbortCode::InvalidValue},
        {"CanId180", {invalidate}, u32(kRpdoComm, 1, 0x180), AbortCode::InvalidValue},
        {"CanId0FF", {invalidate}, u32(kRpdoComm, 1, 0x0FF), AbortCode::InvalidValue},
        {"CanId181", {invalidate}, u32(kRpdoComm, 1, 0x181), AbortCode::None},
        {"CanId57F", {invalidate}, u32(kRpdoComm, 1, 0x57F), AbortCode::None},
        {"CanId580", {invalidate}, u32(kRpdoComm, 1, 0x580), AbortCode::InvalidValue},
        {"InvalidCanId0", {invalidate}, u32(kRpdoComm, 1, 0x8000'0000), AbortCode::None},
        // 8.2.22: "To change a mapped object it is necessary to disable PDO by writing 0 to the
        // number of mapped PDO objects."
        {"MappingEntryWhileMapped",
         {invalidate},
         u32(kRpdoMap, 1, 0x607A'0020),
         AbortCode::ParameterIncompatibility},
        {"MappingCountOfValidPdo", {}, u8(kRpdoMap, 0, 0), AbortCode::ParameterIncompatibility},
        {"NineMappedObjects", {invalidate}, u8(kRpdoMap, 0, 9), AbortCode::PdoLengthExceeded},
        {"EventTimerDoesNotExist", {}, u16(kTpdoComm, 5, 0), AbortCode::SubIndexDoesNotExist},
        {"SyncStartDoesNotExist", {}, u8(kTpdoComm, 6, 0), AbortCode::SubIndexDoesNotExist},
    };
}

INSTANTIATE_TEST_SUITE_P(Epos2, PdoRulesEpos2, ::testing::ValuesIn(epos2_cases()), case_name);

/// A value that a remote read must return.
struct Expected {
    std::uint16_t index;
    std::uint8_t sub_index;
    std::uint32_t value;
};

void expect_values(const ObjectDictionary& od, const std::vector<Expected>& expected) {
    for (const Expected& e : expected) {
        Bytes data;
        ASSERT_EQ(od.read(e.index, e.sub_index, data), AbortCode::None)
            << fmt::format("{:04X}sub{}", e.index, e.sub_index);
        Bytes wide = data;
        wide.resize(4);
        EXPECT_EQ(decode<std::uint32_t>(wide), e.value)
            << fmt::format("{:04X}sub{}", e.index, e.sub_index);
    }
}

TEST(PdoObjects, Epos2DefaultsAreThoseOfItsFirmwareSpecification) {
    ObjectDictionary od;
    add_pdo_objects(od, epos2_pdo_defaults(3));
    expect_values(od, {
                          // 8.2.18 - 8.2.21: RPDO COB-ID 0x200 + 0x100 (n - 1) + node, type 255
                          {0x1400, 0, 2},
                          {0x1400, 1, 0x203},
                          {0x1400, 2, 255},
                          {0x1401, 1, 0x303},
                          {0x1401, 2, 255},
                          {0x1402, 1, 0x403},
                          {0x1402, 2, 255},
                          {0x1403, 1, 0x503},
                          {0x1403, 2, 255},
                          // 8.2.22 - 8.2.25
                          {0x1600, 0, 1},
                          {0x1600, 1, 0x6040'0010},
                          {0x1600, 2, 0},
                          {0x1600, 8, 0},
                          {0x1601, 0, 2},
                          {0x1601, 1, 0x6040'0010},
                          {0x1601, 2, 0x6060'0008},
                          {0x1602, 0, 2},
                          {0x1602, 1, 0x6040'0010},
                          {0x1602, 2, 0x607A'0020},
                          {0x1603, 0, 2},
                          {0x1603, 1, 0x6040'0010},
                          {0x1603, 2, 0x60FF'0020},
                          // 8.2.26 - 8.2.29: only TPDO 1 valid; TPDO 4 on RTR only
                          {0x1800, 0, 3},
                          {0x1800, 1, 0x4000'0183},
                          {0x1800, 2, 255},
                          {0x1800, 3, 0},
                          {0x1801, 1, 0xC000'0283},
                          {0x1801, 2, 255},
                          {0x1801, 3, 0},
                          {0x1802, 1, 0xC000'0383},
                          {0x1802, 2, 255},
                          {0x1803, 1, 0xC000'0483},
                          {0x1803, 2, 253},
                          // 8.2.30 - 8.2.33
                          {0x1A00, 0, 1},
                          {0x1A00, 1, 0x6041'0010},
                          {0x1A00, 2, 0},
                          {0x1A01, 0, 2},
                          {0x1A01, 1, 0x6041'0010},
                          {0x1A01, 2, 0x6061'0008},
                          {0x1A02, 0, 2},
                          {0x1A02, 1, 0x6041'0010},
                          {0x1A02, 2, 0x6064'0020},
                          {0x1A03, 0, 2},
                          {0x1A03, 1, 0x6041'0010},
                          {0x1A03, 2, 0x606C'0020},
                          {0x1A03, 8, 0},
                      });
    Bytes data;
    EXPECT_EQ(od.read(0x1A00, 9, data), AbortCode::SubIndexDoesNotExist);
    EXPECT_EQ(od.read(0x1404, 1, data), AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(od.read(0x1804, 1, data), AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(count_pdos(od, PdoDirection::Receive), 4U);
    EXPECT_EQ(count_pdos(od, PdoDirection::Transmit), 4U);
}

TEST(PdoObjects, Cia301DefaultsUseThePredefinedConnectionSetForTheFirstFourPdos) {
    ObjectDictionary od;
    add_pdo_objects(od, kNode, 6, 6);
    expect_values(od, {
                          {0x1400, 0, 5}, // CiA 301 7.5.2.35: sub 5, the deadline
                          {0x1400, 1, 0x8000'0205},
                          {0x1403, 1, 0x8000'0505},
                          {0x1404, 1, 0x8000'0000},
                          {0x1405, 2, 255},
                          {0x1405, 5, 0},
                          {0x1600, 0, 0},
                          {0x1800, 0, 6},
                          {0x1800, 1, 0xC000'0185},
                          {0x1801, 1, 0xC000'0285},
                          {0x1803, 1, 0xC000'0485},
                          {0x1804, 1, 0xC000'0000},
                          {0x1805, 2, 255},
                          {0x1805, 3, 0},
                          {0x1805, 5, 0},
                          {0x1805, 6, 0},
                          {0x1A05, 0, 0},
                      });
    EXPECT_EQ(count_pdos(od, PdoDirection::Receive), 6U);
    EXPECT_EQ(count_pdos(od, PdoDirection::Transmit), 6U);
}

TEST(PdoObjects, ParametersAreReadWriteAndPersistent) {
    ObjectDictionary od;
    add_pdo_objects(od, kNode, 1, 1);
    for (const std::uint16_t index : std::array<std::uint16_t, 4>{0x1400, 0x1600, 0x1800, 0x1A00}) {
        for (const auto& [sub_index, sub] : od.find(index)->subs) {
            const bool highest_sub_index = sub_index == 0 && (index == 0x1400 || index == 0x1800);
            EXPECT_EQ(sub.persistent, !highest_sub_index)
                << fmt::format("{:04X}sub{}", index, sub_index);
            EXPECT_EQ(sub.access, highest_sub_index ? Access::ReadOnly : Access::ReadWrite);
            EXPECT_FALSE(sub.pdo_mappable);
        }
    }
}

TEST(PdoObjects, DefaultMappingLongerThanTheMappingObjectIsAProgrammingError) {
    PdoObjectsConfig config = cia301_pdo_defaults(kNode, 1, 0);
    config.mapping_entries = 1;
    config.rpdos[0].mapping = {0x6040'0010, 0x6060'0008};
    ObjectDictionary od;
    EXPECT_THROW(add_pdo_objects(od, config), std::invalid_argument);
}

TEST(PdoObjects, TheFiveStepProcedureRemapsAValidPdo) {
    ObjectDictionary od;
    testing::add_application_objects(od);
    add_pdo_objects(od, epos2_pdo_defaults(1));
    // TPDO 1 is valid with the statusword mapped (EPOS2 defaults).
    EXPECT_EQ(apply(od, u32(kTpdoComm, 1, 0xC000'0181)), AbortCode::None);
    EXPECT_EQ(apply(od, u8(kTpdoMap, 0, 0)), AbortCode::None);
    EXPECT_EQ(apply(od, u32(kTpdoMap, 1, 0x6041'0010)), AbortCode::None);
    EXPECT_EQ(apply(od, u32(kTpdoMap, 2, 0x6064'0020)), AbortCode::None);
    EXPECT_EQ(apply(od, u8(kTpdoMap, 0, 2)), AbortCode::None);
    EXPECT_EQ(apply(od, u32(kTpdoComm, 1, 0x4000'0181)), AbortCode::None);
    EXPECT_EQ(read_pdo_mapping(od, PdoDirection::Transmit, 1),
              (std::vector<MappingEntry>{{0x6041, 0, 16}, {0x6064, 0, 32}}));
    EXPECT_TRUE(read_pdo_communication(od, PdoDirection::Transmit, 1).cob_id.valid());
}

TEST(PdoObjects, CommunicationParametersReadInTheirUnits) {
    ObjectDictionary od;
    add_pdo_objects(od, kNode, 0, 1);
    ASSERT_EQ(apply(od, u16(kTpdoComm, 3, 25)), AbortCode::None);
    ASSERT_EQ(apply(od, u16(kTpdoComm, 5, 40)), AbortCode::None);
    ASSERT_EQ(apply(od, u8(kTpdoComm, 6, 7)), AbortCode::None);
    const PdoCommunication comm = read_pdo_communication(od, PdoDirection::Transmit, 1);
    EXPECT_EQ(comm.inhibit_time, std::chrono::microseconds(2500));
    EXPECT_EQ(comm.event_timer, std::chrono::milliseconds(40));
    EXPECT_EQ(comm.sync_start, 7);
    EXPECT_EQ(comm.cob_id.can_id(), 0x185U);
    EXPECT_FALSE(comm.cob_id.valid());
    EXPECT_FALSE(comm.cob_id.rtr_allowed());
}

TEST(PdoObjects, PdoNumbersOutside1To512AreAProgrammingError) {
    EXPECT_EQ(pdo_communication_index(PdoDirection::Transmit, 512), 0x19FF);
    EXPECT_EQ(pdo_mapping_index(PdoDirection::Receive, 1), 0x1600);
    EXPECT_THROW(pdo_communication_index(PdoDirection::Receive, 0), std::out_of_range);
    EXPECT_THROW(pdo_mapping_index(PdoDirection::Transmit, 513), std::out_of_range);
}

} // namespace
} // namespace eposp::canopen
