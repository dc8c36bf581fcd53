// EPOS2 FW spec table 4-11 as printed: code, error register as "0000 0010b", fault reaction
// code and the position reset mark; the drive's table must say the same.
#include "eposp/drives/epos2/device_errors.hpp"

#include <gtest/gtest.h>
#include <string>

namespace eposp::drives::epos2 {
namespace {

struct PrintedRow {
    std::uint16_t code;
    const char* error_register;
    char reaction;
    bool position_reset;
};

constexpr PrintedRow kTable4_11[] = {
    {0x1000, "0000 0001b", 'd', false}, {0x2310, "0000 0010b", 'd', false},
    {0x2320, "0000 0010b", 'd', false}, {0x3210, "0000 0100b", 'd', false},
    {0x3220, "0000 0100b", 'd', false}, {0x4210, "0000 1000b", 'd', false},
    {0x5113, "0000 0100b", 'd', false}, {0x5114, "0000 0100b", 'd', false},
    {0x6100, "0010 0000b", 'd', false}, {0x6320, "0010 0000b", 'f', false},
    {0x7320, "0010 0000b", 'd', true},  {0x8110, "0001 0000b", 'a', false},
    {0x8111, "0001 0000b", 'a', false}, {0x8120, "0001 0000b", 'a', false},
    {0x8130, "0001 0000b", 'a', false}, {0x8150, "0001 0000b", 'a', false},
    {0x81FD, "0001 0000b", 'a', false}, {0x81FE, "0001 0000b", 'a', false},
    {0x81FF, "0001 0000b", 'a', false}, {0x8210, "0001 0000b", 'a', false},
    {0x8611, "0010 0000b", 'f', false}, {0xFF01, "1000 0000b", 'd', true},
    {0xFF02, "1000 0000b", 'd', true},  {0xFF03, "1000 0000b", 'd', true},
    {0xFF04, "1000 0000b", 'd', true},  {0xFF06, "1000 0000b", 'f', false},
    {0xFF07, "1000 0000b", 'f', false}, {0xFF08, "1000 0000b", 'f', true},
    {0xFF09, "1000 0000b", 'f', false}, {0xFF0A, "1000 0000b", 'd', true},
    {0xFF0B, "0010 0000b", 'd', false}, {0xFF0C, "0010 0000b", 'f', false},
    {0xFF0D, "0010 0000b", 'd', false}, {0xFF0F, "0010 0000b", 'd', false},
    {0xFF10, "0010 0000b", 'f', false}, {0xFF11, "0010 0000b", 'd', false},
    {0xFF12, "0010 0000b", 'd', false},
};

std::string printed_register(std::uint8_t bits) {
    std::string text;
    for (int bit = 7; bit >= 0; --bit) {
        text += ((bits >> bit) & 1U) != 0 ? '1' : '0';
        if (bit == 4) {
            text += ' ';
        }
    }
    return text + 'b';
}

char printed_reaction(motion::FaultClass reaction) {
    switch (reaction) {
    case motion::FaultClass::Communication:
        return 'a';
    case motion::FaultClass::Device:
        return 'f';
    case motion::FaultClass::Critical:
        return 'd';
    }
    return '?';
}

TEST(Table4_11, EveryRowAsPrinted) {
    ASSERT_EQ(device_errors().size(), std::size(kTable4_11));
    for (std::size_t i = 0; i < std::size(kTable4_11); ++i) {
        const PrintedRow& printed = kTable4_11[i];
        const DeviceError& row = device_errors()[i];
        SCOPED_TRACE(printed.code);
        EXPECT_EQ(row.code, printed.code);
        EXPECT_EQ(printed_register(row.error_register), printed.error_register);
        EXPECT_EQ(printed_reaction(row.reaction), printed.reaction);
        EXPECT_EQ(row.position_reset, printed.position_reset);
        EXPECT_EQ(&device_error(printed.code), &row);
    }
}

TEST(Table4_11, CodesOutsideTheTableAreProgrammingErrors) {
    EXPECT_THROW(device_error(0x0000), std::invalid_argument);
    EXPECT_THROW(device_error(0x8140), std::invalid_argument);
}

} // namespace
} // namespace eposp::drives::epos2
