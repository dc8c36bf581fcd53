// `eposp dcf`: the EPOS P's DCF and the slaves' concise DCFs of a network file, read back by the
// project's own EDS reader and concise-DCF decoder.
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/manager/concise_dcf.hpp"
#include "eposp_command.hpp"

#include <algorithm>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;

const std::string kNetwork = std::string(EPOSP_SOURCE_DIR) + "/examples/two-axis/network.yaml";

TEST(DcfCommand, TheEposPsDcfCarriesTheConfiguredValuesAndImportsBack) {
    const auto directory = scratch("dcf");
    const auto result = eposp("dcf --network " + kNetwork + " -o " + directory.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("epos-p.dcf\n"));

    const std::string text = read_file(directory / "epos-p.dcf");
    EXPECT_THAT(text, HasSubstr("[DeviceComissioning]\nNodeID=0x01\nNodeName=EPOS P\n"
                                "Baudrate=1000\nNetNumber=1\nNetworkName=network\n"
                                "CANopenManager=1\n"));
    const auto imported = canopen::import_eds(text, "epos-p.dcf");
    ASSERT_TRUE(imported) << imported.error();
    const canopen::ObjectDictionary& od = imported->dictionary;
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1006, 0), 1000u);       // sync_period: 1ms
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1400, 1), 0x182u);      // axis 1's statusword PDO
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1600, 1), 0x5281'0210u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F81, 2), 0x0Du);        // node 2: mandatory boot slave
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F85, 0x80), 0xFBu);     // the internal EPOS2's vendor
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5281, 1), 2u);            // axis 1 is node 2
}

TEST(DcfCommand, EachSlavesConciseDcfHoldsItsBootWrites) {
    const auto directory = scratch("dcf");
    ASSERT_EQ(eposp("dcf --network " + kNetwork + " -o " + directory.string()).exit_code, 0);
    for (const std::string name : {"internal-node1.cdcf", "can-node2.cdcf"}) {
        const std::string bytes = read_file(directory / name);
        const auto writes = manager::decode_concise_dcf(
            {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
        ASSERT_TRUE(writes) << name << ": " << writes.error();
        const auto has = [&](std::uint16_t index, std::uint8_t sub, canopen::Bytes value) {
            return std::ranges::any_of(*writes, [&](const manager::ConfigurationWrite& write) {
                return write.index == index && write.sub_index == sub && write.value == value;
            });
        };
        EXPECT_TRUE(has(0x1017, 0, canopen::encode(std::uint16_t{50}))) << name; // heartbeat
        EXPECT_TRUE(has(0x1A00, 3, canopen::encode(std::uint32_t{0x6064'0020}))) << name;
        EXPECT_EQ(writes->back().index, 0x6060) << name; // profile position mode last
    }
}

TEST(DcfCommand, AFileWhereTheDirectoryBelongsIsAClearError) {
    const auto file = write_source("not-a-directory", "x");
    const auto result = eposp("dcf --network " + kNetwork + " -o " + file);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp dcf: error: -o " + file + ": not a directory"));
    EXPECT_EQ(read_file(file), "x");
}

} // namespace
} // namespace eposp::device
