// `eposp serve`: the EPOS P in real time with port 2 open over socketcand, reached by an
// independent tool (python-can) as a service tool on a real bus would.
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;

const std::string kExample = std::string(EPOSP_SOURCE_DIR) + "/examples/two-axis/";

TEST(ServeCommand, APythonCanToolReadsTheEposPBySdoAndSeesTheAxesPdos) {
    const auto out = scratch("serve.out");
    const std::string tool = std::string(EPOSP_SOURCE_DIR) + "/tests/device/epos_p_service_tool.py";
    const auto result = test::run_command(
        "sh -c '" +
        start_in_background(out, "serve " + kExample + "two-axis.st --network " + kExample +
                                     "network.yaml --socketcand 127.0.0.1:0 --for 30s") +
        "/usr/bin/python3 " + tool + " ${address%:*} ${address##*:} 1 2>&1; code=$?; " +
        "kill -INT $pid; wait $pid; exit $code'");
    if (result.exit_code == 77) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    ASSERT_EQ(result.exit_code, 0) << result.output << read_file(out);
    EXPECT_THAT(result.output, HasSubstr("device type: 0x00000195"));
    const std::string served = read_file(out);
    EXPECT_THAT(served, HasSubstr("socketcand: socketcand-1 joined from 127.0.0.1:"));
    EXPECT_THAT(served, HasSubstr("interrupted"));
    EXPECT_THAT(served, HasSubstr("boot-up of port 2 (CAN): network started"));
}

// Axis 1 is an EPOS2 in another process (`eposp drive epos2 --join`): the EPOS P boots it over
// socketcand, sets up its PDOs, and the two-axis program moves it to its target.
TEST(ServeCommand, AnExternalSlaveInAnotherProcessIsBootedAndMoved) {
    const auto network = write_source("external.yaml", R"(sync_period: 2ms
slaves:
  - {node: 1, port: internal, axis: 0}
  - {node: 3, kind: external, axis: 1, heartbeat: 500ms}
)");
    const auto out = scratch("serve.out");
    const auto drive_out = scratch("drive.out");
    const auto result = test::run_command(
        "sh -c '" +
        start_in_background(out, "serve " + kExample + "two-axis.st --network " + network +
                                     " --socketcand 127.0.0.1:0 --for 8s --watch Cell.both_done") +
        kEposp + " drive epos2 --node-id 3 --join $address --join-bus external --for 7s > " +
        drive_out.string() + " 2>&1; echo drive exit $?; wait $pid; echo serve exit $?'");
    const std::string served = read_file(out);
    const std::string drive = read_file(drive_out);
    EXPECT_THAT(result.output, HasSubstr("drive exit 0")) << drive;
    EXPECT_THAT(served, HasSubstr("boot-up of port 2 (CAN): network started\n  node 3: booted at"))
        << served;
    EXPECT_THAT(served, HasSubstr("Cell.both_done = TRUE")) << served;
    EXPECT_THAT(drive, HasSubstr("epos2: node 3 stopped in Operation Enable")) << drive;
}

TEST(ServeCommand, AnAddressInUseOrMalformedIsAClearError) {
    const auto result = eposp("serve --socketcand not-an-address --for 1s");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp serve: error: --socketcand"));
}

TEST(ServeCommand, WithoutProgramItBootsTheNetworkAlone) {
    const auto result = eposp("serve --network " + kExample + "network.yaml --for 1s");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("boot-up of port 1 (internal): network started"));
    EXPECT_THAT(result.output, HasSubstr("boot-up of port 2 (CAN): network started"));
}

} // namespace
} // namespace eposp::device
