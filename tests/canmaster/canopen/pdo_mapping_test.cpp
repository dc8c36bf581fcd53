#include "eposp/canopen/pdo_mapping.hpp"
#include "pdo_test_support.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>
#include <vector>

// Bit packing of PDO data (CiA 301 7.1.2 bit order, 7.5.2.36 / 7.5.2.38 mapping entries):
// values packed without gaps from bit 0 of byte 0, each least significant bit first.

namespace eposp::canopen {
namespace {

using testing::add_application_object;
using testing::add_application_objects;
using testing::PdoNode;
using testing::Sent;

std::vector<MappingEntry> entries(std::initializer_list<std::uint32_t> raws) {
    std::vector<MappingEntry> out;
    for (const std::uint32_t raw : raws) {
        out.push_back(MappingEntry::from_raw(raw));
    }
    return out;
}

PdoMapping resolve(const ObjectDictionary& od, std::initializer_list<std::uint32_t> raws,
                   PdoDirection direction) {
    auto resolution = PdoMapping::resolve(od, entries(raws), direction);
    EXPECT_EQ(resolution.error, AbortCode::None);
    return resolution.mapping;
}

// The payload's bytes; those beyond its size stay zero, so that equal payloads compare equal (a
// TPDO compares them to skip an unchanged event).
Bytes packed(const PdoMapping& mapping) {
    const PdoPayload payload = mapping.pack();
    for (std::size_t i = payload.size; i < payload.data.size(); ++i) {
        EXPECT_EQ(payload.data[i], 0) << "byte " << i << " beyond the payload";
    }
    return {payload.bytes().begin(), payload.bytes().end()};
}

class PdoMappingTest : public ::testing::Test {
protected:
    PdoMappingTest() { add_application_objects(od); }
    ObjectDictionary od;
};

// BOOLEAN 1 bit, UNSIGNED8 as 7 bits, UNSIGNED16, INTEGER32: 56 bits in 7 bytes.
const std::initializer_list<std::uint32_t> kPacked = {0x2001'0001, 0x2002'0007, 0x2003'0010,
                                                      0x2004'0020};
// true | 0x55 << 1 = 0xAB, then 0xBEEF and -2 little-endian.
const Bytes kPackedBytes = {0xAB, 0xEF, 0xBE, 0xFE, 0xFF, 0xFF, 0xFF};

TEST(PdoMappingEntry, RoundTripsThroughItsRawForm) {
    const MappingEntry entry = MappingEntry::from_raw(0x6041'0210);
    EXPECT_EQ(entry, (MappingEntry{0x6041, 0x02, 16}));
    EXPECT_EQ(entry.raw(), 0x6041'0210U);
    EXPECT_TRUE(is_dummy(MappingEntry::from_raw(0x0002'0008)));
    EXPECT_TRUE(is_dummy(MappingEntry::from_raw(0x0007'0020)));
    EXPECT_FALSE(is_dummy(MappingEntry::from_raw(0x0001'0001)));
    EXPECT_FALSE(is_dummy(MappingEntry::from_raw(0x0008'0020)));
}

TEST_F(PdoMappingTest, PacksOneSevenSixteenAndThirtyTwoBitsWithoutGaps) {
    od.set_as(0x2001, 0, true);
    od.set_as(0x2002, 0, std::uint8_t{0x55});
    od.set_as(0x2003, 0, std::uint16_t{0xBEEF});
    od.set_as(0x2004, 0, std::int32_t{-2});
    const PdoMapping mapping = resolve(od, kPacked, PdoDirection::Transmit);
    EXPECT_EQ(mapping.bits(), 56U);
    EXPECT_EQ(mapping.size(), 7U);
    EXPECT_EQ(packed(mapping), kPackedBytes);
}

TEST_F(PdoMappingTest, UnpacksOneSevenSixteenAndThirtyTwoBits) {
    resolve(od, kPacked, PdoDirection::Receive).unpack(od, kPackedBytes);
    EXPECT_TRUE(od.get_as<bool>(0x2001, 0));
    EXPECT_EQ(od.get_as<std::uint8_t>(0x2002, 0), 0x55);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x2003, 0), 0xBEEF);
    EXPECT_EQ(od.get_as<std::int32_t>(0x2004, 0), -2);
}

TEST_F(PdoMappingTest, TpdoSendsTheLowBitsOfAShortInteger) {
    od.set_as(0x2003, 0, std::uint16_t{0xABCD});
    EXPECT_EQ(packed(resolve(od, {0x2003'000C}, PdoDirection::Transmit)), (Bytes{0xCD, 0x0B}));
}

TEST_F(PdoMappingTest, ShortUnsignedIntegerIsZeroExtended) {
    resolve(od, {0x2002'0004}, PdoDirection::Receive).unpack(od, Bytes{0xFF});
    EXPECT_EQ(od.get_as<std::uint8_t>(0x2002, 0), 0x0F);
}

TEST_F(PdoMappingTest, ShortSignedIntegerIsSignExtended) {
    const PdoMapping nibble = resolve(od, {0x2007'0004}, PdoDirection::Receive);
    nibble.unpack(od, Bytes{0x0F});
    EXPECT_EQ(od.get_as<std::int8_t>(0x2007, 0), -1);
    nibble.unpack(od, Bytes{0x07});
    EXPECT_EQ(od.get_as<std::int8_t>(0x2007, 0), 7);
    resolve(od, {0x2004'0018}, PdoDirection::Receive).unpack(od, Bytes{0x00, 0x00, 0x80});
    EXPECT_EQ(od.get_as<std::int32_t>(0x2004, 0), -8'388'608);
}

TEST_F(PdoMappingTest, EightBooleansShareOneByte) {
    for (std::uint16_t i = 0; i < 8; ++i) {
        add_application_object(od, static_cast<std::uint16_t>(0x2100 + i), DataType::Boolean,
                               Access::ReadWrite, encode(i % 3 == 0));
    }
    const PdoMapping mapping = resolve(od,
                                       {0x2100'0001, 0x2101'0001, 0x2102'0001, 0x2103'0001,
                                        0x2104'0001, 0x2105'0001, 0x2106'0001, 0x2107'0001},
                                       PdoDirection::Transmit);
    EXPECT_EQ(packed(mapping), (Bytes{0b0100'1001}));
    resolve(od,
            {0x2100'0001, 0x2101'0001, 0x2102'0001, 0x2103'0001, 0x2104'0001, 0x2105'0001,
             0x2106'0001, 0x2107'0001},
            PdoDirection::Receive)
        .unpack(od, Bytes{0b1000'0010});
    EXPECT_EQ(od.get(0x2101, 0), Bytes{1});
    EXPECT_EQ(od.get(0x2107, 0), Bytes{1});
    EXPECT_EQ(od.get(0x2100, 0), Bytes{0});
    EXPECT_EQ(od.get(0x2103, 0), Bytes{0});
}

TEST_F(PdoMappingTest, DummyEntriesSkipTheirBitsOnReception) {
    od.set_as(0x2002, 0, std::uint8_t{0x11});
    resolve(od, {0x0005'0008, 0x2003'0010, 0x0002'0008}, PdoDirection::Receive)
        .unpack(od, Bytes{0x99, 0x34, 0x12, 0x77});
    EXPECT_EQ(od.get_as<std::uint16_t>(0x2003, 0), 0x1234);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x2002, 0), 0x11);
}

TEST_F(PdoMappingTest, SizeRoundsUpToWholeBytes) {
    EXPECT_EQ(resolve(od, {0x2001'0001}, PdoDirection::Transmit).size(), 1U);
    EXPECT_EQ(resolve(od, {0x2001'0001, 0x2002'0008}, PdoDirection::Transmit).size(), 2U);
    EXPECT_EQ(resolve(od, {0x2005'0040}, PdoDirection::Transmit).size(), 8U);
    EXPECT_TRUE(resolve(od, {}, PdoDirection::Transmit).empty());
}

TEST_F(PdoMappingTest, ResolutionReportsTheFirstFault) {
    EXPECT_EQ(PdoMapping::resolve(od, entries({0x6040'0010, 0x5000'0010, 0x2020'0020}),
                                  PdoDirection::Receive)
                  .error,
              AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(
        PdoMapping::resolve(od, entries({0x6040'0010, 0x2020'0020}), PdoDirection::Receive).error,
        AbortCode::NotMappable);
    EXPECT_EQ(
        PdoMapping::resolve(od, entries({0x2005'0040, 0x2001'0001}), PdoDirection::Receive).error,
        AbortCode::PdoLengthExceeded);
}

TEST_F(PdoMappingTest, PackReadsWhatTheDeviceReads) {
    od.find(0x2003, 0)->on_read = [] {
        return encode(std::uint16_t{0x4242});
    };
    EXPECT_EQ(packed(resolve(od, {0x2003'0010}, PdoDirection::Transmit)), (Bytes{0x42, 0x42}));
}

// The mapping keeps where its values are, not the values: each pack reads them anew, a read
// hook added after the resolution included.
TEST_F(PdoMappingTest, PackReadsTheValuesOfItsMomentNotThoseOfTheResolution) {
    const PdoMapping mapping = resolve(od, kPacked, PdoDirection::Transmit);
    od.set_as(0x2001, 0, true);
    od.set_as(0x2002, 0, std::uint8_t{0x55});
    od.set_as(0x2003, 0, std::uint16_t{0xBEEF});
    od.set_as(0x2004, 0, std::int32_t{-2});
    EXPECT_EQ(packed(mapping), kPackedBytes);
    od.set_as(0x2004, 0, std::int32_t{1});
    EXPECT_EQ(packed(mapping), (Bytes{0xAB, 0xEF, 0xBE, 0x01, 0x00, 0x00, 0x00}));
    od.find(0x2003, 0)->on_read = [] {
        return encode(std::uint16_t{0x4242});
    };
    EXPECT_EQ(packed(mapping), (Bytes{0xAB, 0x42, 0x42, 0x01, 0x00, 0x00, 0x00}));
}

TEST_F(PdoMappingTest, UnpackTellsTheChangeListeners) {
    std::vector<std::uint16_t> changed;
    od.on_change(0x2003,
                 [&changed](std::uint16_t index, std::uint8_t) { changed.push_back(index); });
    resolve(od, {0x2003'0010}, PdoDirection::Receive).unpack(od, Bytes{1, 2});
    EXPECT_EQ(changed, (std::vector<std::uint16_t>{0x2003}));
}

TEST_F(PdoMappingTest, KnowsWhatItMaps) {
    const PdoMapping mapping =
        resolve(od, {0x0005'0008, 0x2003'0010, 0x2002'0008, 0x2003'0010}, PdoDirection::Receive);
    EXPECT_TRUE(mapping.maps(0x2003, 0));
    EXPECT_FALSE(mapping.maps(0x2003, 1));
    EXPECT_FALSE(mapping.maps(0x0005, 0));
    EXPECT_EQ(mapping.mapped_indices(), (std::vector<std::uint16_t>{0x2003, 0x2002}));
}

// Every fixed-size type at its full length behind a BOOLEAN, so that it straddles bytes (the
// 64-bit types alone): packed as its little-endian bits, and unpacked to the same value.
struct WidthCase {
    DataType type;
    friend void PrintTo(const WidthCase& c, std::ostream* os) { *os << to_string(c.type); }
};

class PdoMappingWidth : public ::testing::TestWithParam<WidthCase> {};

TEST_P(PdoMappingWidth, ValueRoundTripsAtAnOddBitOffset) {
    const DataType type = GetParam().type;
    const std::size_t size = *fixed_size(type);
    const auto bits = static_cast<std::uint32_t>(size * 8);
    const bool behind_flag = bits < 64;
    Bytes value(size);
    std::uint64_t pattern = 0;
    for (std::size_t i = 0; i < size; ++i) {
        value[i] = static_cast<std::uint8_t>(0x81 + 0x11 * i);
        pattern |= std::uint64_t{value[i]} << (8 * i);
    }
    ObjectDictionary sender;
    ObjectDictionary receiver;
    for (ObjectDictionary* od : {&sender, &receiver}) {
        add_application_object(*od, 0x2001, DataType::Boolean, Access::ReadWrite, encode(true));
        add_application_object(*od, 0x3000, type, Access::ReadWrite, Bytes(size));
    }
    sender.set(0x3000, 0, value);
    const std::uint32_t entry = 0x3000'0000 | bits;
    const auto raws = behind_flag ? std::vector<std::uint32_t>{0x2001'0001, entry}
                                  : std::vector<std::uint32_t>{entry};
    std::vector<MappingEntry> mapped;
    for (const std::uint32_t raw : raws) {
        mapped.push_back(MappingEntry::from_raw(raw));
    }
    const auto tx = PdoMapping::resolve(sender, mapped, PdoDirection::Transmit);
    ASSERT_EQ(tx.error, AbortCode::None);
    const Bytes payload = packed(tx.mapping);

    const std::uint64_t word = behind_flag ? (pattern << 1 | 1) : pattern;
    Bytes expected(behind_flag ? size + 1 : size);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        expected[i] = static_cast<std::uint8_t>(word >> (8 * i));
    }
    EXPECT_EQ(payload, expected);

    const auto rx = PdoMapping::resolve(receiver, mapped, PdoDirection::Receive);
    ASSERT_EQ(rx.error, AbortCode::None);
    rx.mapping.unpack(receiver, payload);
    EXPECT_EQ(receiver.get(0x3000, 0), value);
}

std::string width_case_name(const ::testing::TestParamInfo<WidthCase>& info) {
    return std::string(to_string(info.param.type));
}

INSTANTIATE_TEST_SUITE_P(
    AllFixedSizeTypes, PdoMappingWidth,
    ::testing::Values(WidthCase{DataType::Integer8}, WidthCase{DataType::Unsigned8},
                      WidthCase{DataType::Integer16}, WidthCase{DataType::Unsigned16},
                      WidthCase{DataType::Integer24}, WidthCase{DataType::Unsigned24},
                      WidthCase{DataType::Integer32}, WidthCase{DataType::Unsigned32},
                      WidthCase{DataType::Real32}, WidthCase{DataType::Integer40},
                      WidthCase{DataType::Unsigned40}, WidthCase{DataType::Integer48},
                      WidthCase{DataType::Unsigned48}, WidthCase{DataType::Integer56},
                      WidthCase{DataType::Unsigned56}, WidthCase{DataType::Integer64},
                      WidthCase{DataType::Unsigned64}, WidthCase{DataType::Real64}),
    width_case_name);

// The same layouts over the bus, byte for byte.
TEST(PdoBitPacking, RpdoStoresABitPackedFrame) {
    PdoNode node;
    ASSERT_EQ(testing::configure_pdo(node.od, PdoDirection::Receive, 1,
                                     {0x205, kEventDrivenProfile, kPacked}),
              AbortCode::None);
    node.operational();
    node.send("205#ABEFBEFEFFFFFF");
    node.run_for(std::chrono::milliseconds(1));
    EXPECT_TRUE(node.od.get_as<bool>(0x2001, 0));
    EXPECT_EQ(node.od.get_as<std::uint8_t>(0x2002, 0), 0x55);
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x2003, 0), 0xBEEF);
    EXPECT_EQ(node.od.get_as<std::int32_t>(0x2004, 0), -2);
    EXPECT_TRUE(node.emcy.empty());
}

TEST(PdoBitPacking, TpdoSendsABitPackedFrame) {
    PdoNode node;
    node.od.set_as(0x2001, 0, true);
    node.od.set_as(0x2002, 0, std::uint8_t{0x55});
    node.od.set_as(0x2003, 0, std::uint16_t{0xBEEF});
    node.od.set_as(0x2004, 0, std::int32_t{-2});
    ASSERT_EQ(testing::configure_pdo(node.od, PdoDirection::Transmit, 1, {0x185, 1, kPacked}),
              AbortCode::None);
    node.operational();
    node.sync();
    node.run_for(std::chrono::milliseconds(1));
    const auto sync = node.tester_frames().at(0);
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{{testing::next_start_after(sync), "185#ABEFBEFEFFFFFF"}}));
}

} // namespace
} // namespace eposp::canopen
