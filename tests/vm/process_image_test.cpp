// The DS-405 process image: which object entry each IEC address falls into, entries read and
// written by index and sub-index, and located variables copied in before and out after a task.

#include "eposp/vm/process_image.hpp"

#include <cstring>
#include <gtest/gtest.h>
#include <vector>

namespace eposp::vm {
namespace {

struct AddressCase {
    IoArea area;
    std::uint32_t byte;
    std::optional<ObjectEntry> entry;
};

class ObjectEntryOf : public ::testing::TestWithParam<AddressCase> {};

TEST_P(ObjectEntryOf, FollowsTheDocumentedLayout) {
    EXPECT_EQ(object_entry_of(GetParam().area, GetParam().byte), GetParam().entry);
}

// First and last entry of every object (EPOS P firmware specification 10.38-10.49).
INSTANTIATE_TEST_SUITE_P(
    Inputs, ObjectEntryOf,
    ::testing::Values(AddressCase{IoArea::Input, 0, ObjectEntry{0xA000, 1}},    // %IB0
                      AddressCase{IoArea::Input, 15, ObjectEntry{0xA000, 16}},  // %IB15
                      AddressCase{IoArea::Input, 16, ObjectEntry{0xA040, 1}},   // %IB16
                      AddressCase{IoArea::Input, 31, ObjectEntry{0xA040, 16}},  // %IB31
                      AddressCase{IoArea::Input, 32, ObjectEntry{0xA0C0, 1}},   // %IW16
                      AddressCase{IoArea::Input, 62, ObjectEntry{0xA0C0, 16}},  // %IW31
                      AddressCase{IoArea::Input, 64, ObjectEntry{0xA100, 1}},   // %IW32
                      AddressCase{IoArea::Input, 94, ObjectEntry{0xA100, 16}},  // %IW47
                      AddressCase{IoArea::Input, 96, ObjectEntry{0xA1C0, 1}},   // %ID24
                      AddressCase{IoArea::Input, 156, ObjectEntry{0xA1C0, 16}}, // %ID39
                      AddressCase{IoArea::Input, 160, ObjectEntry{0xA200, 1}},  // %ID40
                      AddressCase{IoArea::Input, 220, ObjectEntry{0xA200, 16}}, // %ID55
                      AddressCase{IoArea::Input, 224, std::nullopt},
                      AddressCase{IoArea::Memory, 0, std::nullopt}));

INSTANTIATE_TEST_SUITE_P(Outputs, ObjectEntryOf,
                         ::testing::Values(AddressCase{IoArea::Output, 0, ObjectEntry{0xA400, 1}},
                                           AddressCase{IoArea::Output, 16, ObjectEntry{0xA4C0, 1}},
                                           AddressCase{IoArea::Output, 32, ObjectEntry{0xA540, 1}},
                                           AddressCase{IoArea::Output, 64, ObjectEntry{0xA580, 1}},
                                           AddressCase{IoArea::Output, 96, ObjectEntry{0xA640, 1}},
                                           AddressCase{IoArea::Output, 220,
                                                       ObjectEntry{0xA680, 16}},
                                           AddressCase{IoArea::Output, 224, std::nullopt}));

TEST(ProcessImage, EntriesAreTheBytesOfTheirAddresses) {
    ProcessImage image;
    const auto entry = image.entry(0xA0C0, 2);
    ASSERT_TRUE(entry) << entry.error();
    ASSERT_EQ(entry->size(), 2u);
    (*entry)[0] = 0x34;
    (*entry)[1] = 0x12;
    EXPECT_EQ(image.inputs()[34], 0x34); // %IW17
    EXPECT_EQ(image.inputs()[35], 0x12);
    EXPECT_EQ(image.entry(0xA680, 16)->data(), image.outputs().data() + 220);
}

TEST(ProcessImage, OtherIndicesAndSubIndicesAreRefused) {
    ProcessImage image;
    EXPECT_EQ(image.entry(0xA000, 0).error(), "0xA000 has no sub-index 0");
    EXPECT_EQ(image.entry(0xA000, 17).error(), "0xA000 has no sub-index 17");
    EXPECT_EQ(image.entry(0xA080, 1).error(), "0xA080 is not a process image object");
}

// Static data of a program with a variable at each of the given bindings.
Image image_with(std::vector<IoBinding> bindings) {
    Image image;
    image.static_size = 64;
    image.bindings = std::move(bindings);
    return image;
}

template <typename T>
T load(const std::vector<std::uint8_t>& memory, std::uint32_t offset) {
    T value;
    std::memcpy(&value, memory.data() + offset, sizeof(T));
    return value;
}

TEST(ProcessImage, InputsReachEveryKindOfLocatedVariable) {
    ProcessImage process;
    process.inputs()[0] = 0xFE;                                        // %IB0 : SINT = -2
    process.inputs()[1] = 0b0000'1000;                                 // %IX1.3 = TRUE
    std::memcpy(process.inputs().data() + 32, "\x10\x27", 2);          // %IW16 : INT = 10000
    std::memcpy(process.inputs().data() + 160, "\x78\x56\x34\x12", 4); // %ID40 : UDINT
    const Image image = image_with({{IoArea::Input, Scalar::I8, 0, 0, 8},
                                    {IoArea::Input, Scalar::Bool, 1, 3, 9},
                                    {IoArea::Input, Scalar::Bool, 1, 2, 10},
                                    {IoArea::Input, Scalar::I16, 32, 0, 12},
                                    {IoArea::Input, Scalar::U32, 160, 0, 16}});
    std::vector<std::uint8_t> memory(64, 0xEE);
    process.read_inputs(image.bindings, memory);
    EXPECT_EQ(load<std::int8_t>(memory, 8), -2);
    EXPECT_EQ(memory[9], 1);
    EXPECT_EQ(memory[10], 0);
    EXPECT_EQ(load<std::int16_t>(memory, 12), 10000);
    EXPECT_EQ(load<std::uint32_t>(memory, 16), 0x12345678u);
}

TEST(ProcessImage, OutputBitsChangeOnlyTheirOwnBit) {
    ProcessImage process;
    process.outputs()[0] = 0b1000'0001;
    const Image image = image_with({{IoArea::Output, Scalar::Bool, 0, 2, 8}});
    std::vector<std::uint8_t> memory(64, 0);
    memory[8] = 1;
    process.write_outputs(image.bindings, memory);
    EXPECT_EQ(process.outputs()[0], 0b1000'0101);
    memory[8] = 0;
    process.write_outputs(image.bindings, memory);
    EXPECT_EQ(process.outputs()[0], 0b1000'0001);
}

TEST(ProcessImage, OutputWordsLandInTheirObjectEntries) {
    ProcessImage process;
    const Image image = image_with({{IoArea::Output, Scalar::I32, 96, 0, 8}}); // %QD24
    std::vector<std::uint8_t> memory(64, 0);
    const std::int32_t value = -123456;
    std::memcpy(memory.data() + 8, &value, 4);
    process.write_outputs(image.bindings, memory);
    const auto entry = process.entry(0xA640, 1);
    std::int32_t published;
    std::memcpy(&published, entry->data(), 4);
    EXPECT_EQ(published, value);
    process.clear_outputs();
    EXPECT_EQ(process.outputs()[96], 0);
}

TEST(ProcessImage, BindingsOutsideTheImageAreRefused) {
    EXPECT_FALSE(
        ProcessImage::check_bindings(image_with({{IoArea::Input, Scalar::U32, 220, 0, 8}})));
    const auto error =
        ProcessImage::check_bindings(image_with({{IoArea::Output, Scalar::U32, 224, 0, 8}}));
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message, "%Q224 is outside the process image (bytes 0..223 of the EPOS P)");
    EXPECT_FALSE(
        ProcessImage::check_bindings(image_with({{IoArea::Memory, Scalar::U32, 4000, 0, 8}})));
}

} // namespace
} // namespace eposp::vm
