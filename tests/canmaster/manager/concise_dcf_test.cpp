// The concise DCF of CiA 302-3: the bytes of the format, and every way a file can be broken.
#include "eposp/manager/concise_dcf.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::manager {
namespace {

using testing::HasSubstr;

TEST(ConciseDcf, EncodesCountThenIndexSubIndexSizeAndDataLittleEndian) {
    const std::vector<ConfigurationWrite> writes = {{0x1017, 0, {0x32, 0x00}},
                                                    {0x1A00, 1, {0x10, 0x00, 0x41, 0x60}}};
    EXPECT_EQ(encode_concise_dcf(writes),
              (std::vector<std::uint8_t>{0x02, 0x00, 0x00, 0x00,                    // 2 entries
                                         0x17, 0x10, 0x00, 0x02, 0x00, 0x00, 0x00,  // 0x1017/0, 2
                                         0x32, 0x00,                                //   50 ms
                                         0x00, 0x1A, 0x01, 0x04, 0x00, 0x00, 0x00,  // 0x1A00/1, 4
                                         0x10, 0x00, 0x41, 0x60}));                 //   0x60410010
    const auto decoded = decode_concise_dcf(encode_concise_dcf(writes));
    ASSERT_TRUE(decoded) << decoded.error();
    ASSERT_EQ(decoded->size(), 2u);
    EXPECT_EQ((*decoded)[1].index, 0x1A00);
    EXPECT_EQ((*decoded)[1].sub_index, 1);
    EXPECT_EQ((*decoded)[1].value, writes[1].value);
    EXPECT_EQ(decode_concise_dcf(encode_concise_dcf({}))->size(), 0u);
}

struct BrokenDcf {
    const char* name;
    std::vector<std::uint8_t> bytes;
    const char* message;
};

class ConciseDcfBroken : public testing::TestWithParam<BrokenDcf> {};

TEST_P(ConciseDcfBroken, IsAnErrorThatSaysWhere) {
    const auto decoded = decode_concise_dcf(GetParam().bytes);
    ASSERT_FALSE(decoded);
    EXPECT_THAT(decoded.error(), HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    All, ConciseDcfBroken,
    testing::Values(
        BrokenDcf{"Empty", {}, "starts with its number of entries"},
        BrokenDcf{"CutHeader", {0x01, 0x00, 0x00, 0x00, 0x17, 0x10}, "entry 1 of 1 is cut off at byte 4"},
        BrokenDcf{"DataBeyondTheEnd",
                  {0x01, 0x00, 0x00, 0x00, 0x17, 0x10, 0x00, 0x04, 0x00, 0x00, 0x00, 0x32},
                  "entry 1 of 1 (0x1017 sub 0) at byte 4: 4 bytes of data, 1 left"},
        BrokenDcf{"HugeSize",
                  {0x01, 0x00, 0x00, 0x00, 0x17, 0x10, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x32},
                  "4294967295 bytes of data, 1 left"},
        BrokenDcf{"NoData", {0x01, 0x00, 0x00, 0x00, 0x17, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00},
                  "0 bytes of data"},
        BrokenDcf{"HugeCount", {0xFF, 0xFF, 0xFF, 0xFF}, "entry 1 of 4294967295 is cut off"},
        BrokenDcf{"TrailingBytes", {0x00, 0x00, 0x00, 0x00, 0xAA}, "1 bytes after the last"}),
    [](const auto& test) { return std::string(test.param.name); });

} // namespace
} // namespace eposp::manager
