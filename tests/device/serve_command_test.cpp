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
