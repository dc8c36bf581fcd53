// The image file: a written image reads back equal, and any other byte string is refused with
// a reason, never a crash or a hang.

#include "eposp/vm/image_format.hpp"
#include "sample_image.hpp"

#include <boost/crc.hpp>
#include <gtest/gtest.h>
#include <random>

namespace eposp::vm::test {
namespace {

TEST(ImageFormat, WriteThenReadGivesTheSameImage) {
    const auto image = sample_image();
    const auto bytes = write_image(image);
    const auto read = read_image(bytes);
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(*read, image);
    EXPECT_EQ(write_image(*read), bytes);
}

TEST(ImageFormat, ASubrangeKeepsItsBounds) {
    auto image = sample_image();
    TypeDescriptor level;
    level.name = "Level";
    level.scalar = Scalar::I16;
    level.size = 2;
    level.subrange = true;
    level.lowest = -10;
    level.highest = 100;
    image.types.push_back(level);
    const auto read = read_image(write_image(image));
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->types.back(), image.types.back());
}

TEST(ImageFormat, AnEnumerationKeepsItsNamesAndValues) {
    auto image = sample_image();
    TypeDescriptor step;
    step.name = "Step";
    step.scalar = Scalar::I16;
    step.size = 2;
    step.enumerators = {{"Idle", 0}, {"Travel", 7}, {"Back", -1}};
    image.types.push_back(step);
    const auto read = read_image(write_image(image));
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->types.back(), image.types.back());
}

TEST(ImageFormat, AReadOnlyAccessPathStaysReadOnly) {
    auto image = sample_image();
    image.symbols.push_back(
        {"Counter", image.symbols.front().type, image.symbols.front().offset, true});
    const auto read = read_image(write_image(image));
    ASSERT_TRUE(read) << read.error();
    EXPECT_TRUE(read->symbols.back().read_only);
    EXPECT_FALSE(read->symbols.front().read_only);
}

TEST(ImageFormat, EventTasksKeepTheirSingleVariableAndTheirHostEvent) {
    auto image = sample_image();
    Task by_event = image.tasks.front();
    by_event.name = "OnSync";
    by_event.kind = TaskKind::Event;
    by_event.interval_ns = 0;
    by_event.event = "rpdo internal 1";
    Task by_both = by_event;
    by_both.name = "OnBoth";
    by_both.event_offset = 0;
    image.tasks.push_back(by_event);
    image.tasks.push_back(by_both);
    const auto read = read_image(write_image(image));
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->tasks, image.tasks);
    EXPECT_FALSE(read->tasks[1].event_offset);
    EXPECT_EQ(read->tasks[2].event_offset, 0u);
}

void set_u32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) {
        bytes[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
    }
}

// Recomputes the header's checksum so that a test reaches the decoder behind it.
void reseal(std::vector<std::uint8_t>& bytes) {
    boost::crc_32_type crc;
    crc.process_bytes(bytes.data() + kImageHeaderSize, bytes.size() - kImageHeaderSize);
    set_u32(bytes, 8, static_cast<std::uint32_t>(bytes.size() - kImageHeaderSize));
    set_u32(bytes, 12, crc.checksum());
}

struct Corruption {
    const char* name;
    void (*corrupt)(std::vector<std::uint8_t>&);
    const char* reason;
};

void PrintTo(const Corruption& c, std::ostream* os) {
    *os << c.name;
}

class ImageCorruption : public ::testing::TestWithParam<Corruption> {};

TEST_P(ImageCorruption, IsRefusedWithItsReason) {
    auto bytes = write_image(sample_image());
    GetParam().corrupt(bytes);
    const auto read = read_image(bytes);
    ASSERT_FALSE(read);
    EXPECT_EQ(read.error(), GetParam().reason);
}

INSTANTIATE_TEST_SUITE_P(
    Header, ImageCorruption,
    ::testing::Values(
        Corruption{"BadMagic", [](auto& b) { b[0] = 'X'; }, "not a program image (bad magic)"},
        Corruption{"Empty", [](auto& b) { b.clear(); }, "not a program image (bad magic)"},
        Corruption{"HeaderCut", [](auto& b) { b.resize(10); }, "truncated image header"},
        Corruption{"OtherVersion", [](auto& b) { b[4] = 99; },
                   "image version 99 is not supported (expected 5)"},
        Corruption{"ReservedHeaderByte", [](auto& b) { b[7] = 9; },
                   "reserved header bytes are not zero"},
        Corruption{"FlippedBit", [](auto& b) { b[40] ^= 0x10; },
                   "image checksum mismatch (corrupt file)"}));

INSTANTIATE_TEST_SUITE_P(
    Sections, ImageCorruption,
    ::testing::Values(Corruption{"MissingSection",
                                 [](auto& b) {
                                     // erase, not resize: GCC 12 at -O1 sees a resize that
                                     // could grow and fails -Wstringop-overflow.
                                     b.erase(b.end() - 5, b.end());
                                     reseal(b);
                                 },
                                 "section imports missing or truncated"},
                      Corruption{"TrailingData",
                                 [](auto& b) {
                                     b.push_back(0);
                                     reseal(b);
                                 },
                                 "unexpected data after the last section"},
                      Corruption{"WrongSectionOrder",
                                 [](auto& b) {
                                     b[kImageHeaderSize] = 2;
                                     reseal(b);
                                 },
                                 "section code missing or truncated"},
                      Corruption{"BooleanOtherThan0Or1", // the import's has_result
                                 [](auto& b) {
                                     b[b.size() - 11] = 2;
                                     reseal(b);
                                 },
                                 "section imports: invalid boolean 2"},
                      Corruption{
                          "HugeElementCount",
                          [](auto& b) {
                              set_u32(b, kImageHeaderSize + 8, 0x10000000);
                              reseal(b);
                          },
                          "section code: element count 268435456 larger than the data left"}));

TEST(ImageFormat, TruncationIsRefusedWithTheSizeMismatch) {
    auto bytes = write_image(sample_image());
    bytes.pop_back();
    const auto read = read_image(bytes);
    ASSERT_FALSE(read);
    EXPECT_EQ(read.error().rfind("image size mismatch", 0), 0U) << read.error();
}

TEST(ImageFormat, EveryPrefixOfAnImageIsRefused) {
    const auto bytes = write_image(sample_image());
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        auto prefix = std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + n);
        if (prefix.size() >= kImageHeaderSize) {
            reseal(prefix); // get past the checksum, into the section decoder
        }
        EXPECT_FALSE(read_image(prefix)) << "prefix of " << n << " bytes";
    }
}

TEST(ImageFormat, RandomBytesBehindAValidHeaderAreRefused) {
    std::mt19937 random(4);
    const auto valid = write_image(sample_image());
    for (int trial = 0; trial < 500; ++trial) {
        auto bytes = valid;
        // Mutate a few payload bytes, then make the checksum right again.
        const int mutations = 1 + trial % 8;
        for (int m = 0; m < mutations; ++m) {
            bytes[kImageHeaderSize + random() % (bytes.size() - kImageHeaderSize)] =
                static_cast<std::uint8_t>(random());
        }
        reseal(bytes);
        const auto read = read_image(bytes); // may succeed: then the verifier must judge it
        if (!read) {
            EXPECT_FALSE(read.error().empty());
        }
    }
    for (int trial = 0; trial < 100; ++trial) {
        std::vector<std::uint8_t> garbage(random() % 300);
        for (auto& byte : garbage) {
            byte = static_cast<std::uint8_t>(random());
        }
        EXPECT_FALSE(read_image(garbage));
    }
}

} // namespace
} // namespace eposp::vm::test
