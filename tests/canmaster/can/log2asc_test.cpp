#include "eposp/can/candump_log_writer.hpp"
#include "eposp/test/run_command.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

// Checks that can-utils' own reader accepts our candump logs.
namespace eposp::can {
namespace {

using namespace std::chrono_literals;
using testing_support::TempFile;

const std::filesystem::path kLog2asc = "/usr/bin/log2asc";

TEST(Log2asc, ConvertsOurCandumpLog) {
    if (!std::filesystem::exists(kLog2asc)) {
        GTEST_SKIP() << "log2asc (can-utils) not installed";
    }
    const TempFile file(".log");
    {
        auto output = TraceOutput::create(file.path());
        ASSERT_TRUE(output) << output.error();
        CandumpLogWriter writer(std::move(*output));
        const auto t0 = TraceTime(1436509052s);
        Frame protocol_violation = Frame::data_frame(0x88, {0, 0, 0x90, 0x08, 0, 0, 0x08, 0});
        protocol_violation.error = true;
        writer.record(t0, "can0", Frame::data_frame(0x000, {0x01, 0x00}));
        writer.record(t0 + 974us, "can0", protocol_violation);
        writer.record(t0 + 1076us, "can0", Frame::data_frame(0x080, {}));
        writer.record(t0 + 2022us, "can0", Frame::data_frame(0x1ABCDEF0, {0x11}, true));
        writer.record(t0 + 2124us, "can0", Frame::remote_frame(0x701, 1));
    }

    auto run =
        test::run_command(kLog2asc.string() + " -I '" + file.path().string() + "' can0 2>&1");

    ASSERT_EQ(run.exit_code, 0);
    auto lines = run.lines();
    ASSERT_GE(lines.size(), 3U);
    lines.erase(lines.begin(), lines.begin() + 3); // date, base and events headers
    const std::vector<std::string> expected = {
        "   0.000000 1  0               Rx   d 2 01 00",
        "   0.000974 1  ErrorFrame",
        "   0.001076 1  80              Rx   d 0",
        "   0.002022 1  1ABCDEF0x       Rx   d 1 11",
        "   0.002124 1  701             Rx   r 1",
    };
    EXPECT_EQ(lines, expected);
}

} // namespace
} // namespace eposp::can
