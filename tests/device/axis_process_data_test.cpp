// The axes of a network file: the PDOs the boot sets up on the slaves and on the EPOS P, the PLC
// task in step with the SYNC, and examples/two-axis moving both axes through raw process data.
#include "compile_program.hpp"
#include "eposp/canopen/pdo_mapping.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/device/axis_process_data.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using canopen::PdoDirection;

std::string read_text(const std::string& relative) {
    std::ifstream in(std::string(EPOSP_SOURCE_DIR) + "/" + relative);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

NetworkFile network(std::string_view text) {
    auto parsed = parse_network_file(text, "net.yaml");
    EXPECT_TRUE(parsed) << parsed.error();
    return *parsed;
}

constexpr std::string_view kTwoAxes = R"(
sync_period: 1ms
slaves:
  - {node: 1, port: internal, axis: 0}
  - {node: 5, axis: 1}
)";

std::vector<std::uint32_t> mapping(const canopen::ObjectDictionary& od, PdoDirection direction,
                                   std::size_t number) {
    std::vector<std::uint32_t> raw;
    for (const canopen::MappingEntry& entry : canopen::read_pdo_mapping(od, direction, number)) {
        raw.push_back(entry.raw());
    }
    return raw;
}

TEST(AxisProcessData, TheBootSetsUpEachAxisSlavesPdosAndProfilePositionMode) {
    EposP device;
    device.add_network(network(kTwoAxes));
    device.boot_networks();
    device.loop().run_for(2s);
    ASSERT_TRUE(device.network(kExternalPort).report().network_started);

    for (drives::epos2::Epos2Drive* drive :
         {&device.internal_drive(), device.simulated_slaves().front().get()}) {
        const canopen::ObjectDictionary& od = drive->objects();
        const std::uint32_t node = drive->node().node_id();
        EXPECT_EQ(mapping(od, PdoDirection::Transmit, 1),
                  (std::vector<std::uint32_t>{0x6041'0010, 0x6041'0010, 0x6064'0020}));
        EXPECT_EQ(canopen::read_pdo_communication(od, PdoDirection::Transmit, 1).transmission_type,
                  1); // synchronous
        EXPECT_EQ(od.get_as<std::uint32_t>(0x1800, 1) & 0x8000'07FF, 0x180 + node);
        EXPECT_EQ(mapping(od, PdoDirection::Receive, 1),
                  (std::vector<std::uint32_t>{0x6040'0010, 0x607A'0020}));
        EXPECT_EQ(od.get_as<std::uint32_t>(0x1400, 1), 0x200 + node);
        EXPECT_EQ(od.get_as<std::int8_t>(0x6060, 0), 1);
    }
}

TEST(AxisProcessData, TheEposPTakesEachAxisIntoTheAxisTableAndItsChannels) {
    EposP device;
    device.add_network(network(kTwoAxes));
    const canopen::ObjectDictionary& od = device.objects();
    // Axis 0 on the internal port: internal RPDO 1 (0x1500 / 0x1700) and TPDO 1 (0x1900).
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1500, 1), 0x181u);
    EXPECT_EQ(mapping(od, PdoDirection::Receive, kFirstInternalPdo),
              (std::vector<std::uint32_t>{0x5280'0210, 0xA100'0110, 0xA1C0'0120}));
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1900, 1), 0x201u);
    EXPECT_EQ(mapping(od, PdoDirection::Transmit, kFirstInternalPdo),
              (std::vector<std::uint32_t>{0xA580'0110, 0xA640'0120}));
    // Axis 1 on port 2: RPDO 1 and TPDO 1 of the CAN port, channels 2.
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1400, 1), 0x185u);
    EXPECT_EQ(mapping(od, PdoDirection::Receive, 1),
              (std::vector<std::uint32_t>{0x5281'0210, 0xA100'0210, 0xA1C0'0220}));
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1800, 1), 0x205u);
    EXPECT_EQ(canopen::read_pdo_communication(od, PdoDirection::Transmit, 1).transmission_type, 1);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5281, 1), 5u);
}

// The image has 16 entries per object: axes 16..31 use the objects of the other signedness,
// entry n - 15.
TEST(AxisProcessData, AxesAbove15UseTheOtherHalfOfTheProcessImage) {
    EposP device;
    device.add_network(network("slaves:\n  - {node: 9, axis: 20}\n"));
    EXPECT_EQ(mapping(device.objects(), PdoDirection::Receive, 1),
              (std::vector<std::uint32_t>{0x5294'0210, 0xA0C0'0510, 0xA200'0520}));
    EXPECT_EQ(mapping(device.objects(), PdoDirection::Transmit, 1),
              (std::vector<std::uint32_t>{0xA540'0510, 0xA680'0520}));
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1800, 1), 0x209u);
    const AxisChannels last = AxisChannels::of(31);
    EXPECT_EQ(last.statusword.index, 0xA0C0);
    EXPECT_EQ(last.target_position.sub_index, 16);
}

TEST(AxisProcessData, ThePlcTaskRunsHalfASyncPeriodAfterEachSync) {
    EposP device;
    device.add_network(network(kTwoAxes));
    ASSERT_FALSE(device.plc().load(compile_program(R"(
        PROGRAM Count VAR scans : DINT; END_VAR scans := scans + 1; END_PROGRAM
        CONFIGURATION C RESOURCE R ON EPOS_P
            TASK Fast (INTERVAL := T#1ms, PRIORITY := 1);
            PROGRAM P WITH Fast : Count;
        END_RESOURCE END_CONFIGURATION)")));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    // A listener on the internal bus hears the SYNCs.
    auto spy = device.internal_bus().connect("spy");
    std::vector<core::TimePoint> syncs;
    spy->on_receive([&](const can::Frame& frame) {
        if (frame.id == 0x080) {
            syncs.push_back(device.loop().now());
        }
    });
    device.loop().run_for(1s);
    ASSERT_GT(syncs.size(), 900u);
    const core::TimePoint sync = syncs.back() + 1ms; // the next SYNC, as heard on the bus
    std::vector<std::string> counts;
    for (const auto offset : {400us, 600us, 1400us, 1600us}) {
        device.loop().run_until(sync + offset);
        counts.push_back(*device.plc().value_of("P.scans"));
    }
    const long before = std::stol(counts[0]);
    EXPECT_EQ(counts,
              (std::vector<std::string>{std::to_string(before), std::to_string(before + 1),
                                        std::to_string(before + 1), std::to_string(before + 2)}));
}

TEST(AxisProcessData, TheTwoAxisExampleMovesBothAxesToTheirTargets) {
    EposP device;
    device.add_network(network(read_text("examples/two-axis/network.yaml")));
    ASSERT_FALSE(device.plc().load(compile_program(read_text("examples/two-axis/two-axis.st"))));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    device.loop().run_for(5s);

    EXPECT_EQ(*device.plc().value_of("Cell.both_done"), "TRUE");
    const auto position = [](drives::epos2::Epos2Drive& drive) {
        return drive.objects().get_as<std::int32_t>(0x6064, 0);
    };
    EXPECT_NEAR(position(device.internal_drive()), 20000, 50);
    EXPECT_NEAR(position(*device.simulated_slaves().front()), -12000, 50);
    // The program saw the positions through its process image.
    EXPECT_EQ(*device.plc().value_of("Cell.position0"),
              std::to_string(device.objects().get_as<std::int32_t>(0xA1C0, 1)));
    EXPECT_TRUE(device.plc().errors().empty());
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1003, 0), 0u);
}

} // namespace
} // namespace eposp::device
