#include "eposp/can/pcap_writer.hpp"
#include "eposp/test/run_command.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <string_view>
#include <vector>

// Checks that Wireshark's own reader accepts our pcap files and decodes CANopen from them.
namespace eposp::can {
namespace {

using namespace std::chrono_literals;
using testing_support::TempFile;

const std::filesystem::path kTshark = "/usr/bin/tshark";

// Runs tshark on `file`, decoding CAN payloads as CANopen, one line of `|`-separated fields per
// frame.
test::CommandResult decode_as_canopen(const std::filesystem::path& file,
                                      std::initializer_list<std::string_view> fields) {
    std::string command = kTshark.string() + " -r '" + file.string() +
                          "' -d can.subdissector,canopen -T fields -E separator='|'";
    for (const auto field : fields) {
        command += " -e ";
        command += field;
    }
    return test::run_command(command + " 2>/dev/null");
}

TEST(Tshark, DecodesOurPcapAsCanopen) {
    if (!std::filesystem::exists(kTshark)) {
        GTEST_SKIP() << "tshark not installed";
    }
    const TempFile file(".pcap");
    {
        auto output = TraceOutput::create(file.path());
        ASSERT_TRUE(output) << output.error();
        PcapWriter writer(std::move(*output));
        const auto t0 = TraceTime(1436509052s);
        writer.record(t0 + 1ns, "can0", Frame::data_frame(0x000, {0x01, 0x00}));
        writer.record(t0 + 2ns, "can0", Frame::data_frame(0x080, {}));
        writer.record(t0 + 3ns, "can0",
                      Frame::data_frame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
        writer.record(t0 + 4ns, "can0", Frame::data_frame(0x181, {0x37, 0x06}));
        writer.record(t0 + 5ns, "can0", Frame::data_frame(0x701, {0x05}));
    }

    const auto run = decode_as_canopen(
        file.path(), {"frame.time_epoch", "frame.protocols", "_ws.col.Protocol", "_ws.col.Info"});

    ASSERT_EQ(run.exit_code, 0);
    const std::vector<std::string> expected = {
        "1436509052.000000001|can:canopen|CANopen|NMT: Start remote node [All]",
        "1436509052.000000002|can|CANopen|SYNC",
        "1436509052.000000003|can:canopen|CANopen|Default-SDO (rx): Initiate upload request",
        "1436509052.000000004|can:canopen|CANopen|PDO1 (tx)",
        "1436509052.000000005|can:canopen|CANopen|NMT Error Control: Operational [0x1]",
    };
    EXPECT_EQ(run.lines(), expected);
}

TEST(Tshark, ShowsErrorRemoteAndExtendedFrames) {
    if (!std::filesystem::exists(kTshark)) {
        GTEST_SKIP() << "tshark not installed";
    }
    const TempFile file(".pcap");
    {
        auto output = TraceOutput::create(file.path());
        ASSERT_TRUE(output) << output.error();
        PcapWriter writer(std::move(*output));
        Frame protocol_violation = Frame::data_frame(0x08, {0, 0, 0x04, 0, 0, 0, 0, 0});
        protocol_violation.error = true;
        writer.record(TraceTime(1s), "can0", protocol_violation);
        writer.record(TraceTime(2s), "can0", Frame::remote_frame(0x701, 1));
        writer.record(TraceTime(3s), "can0", Frame::data_frame(0x1ABCDEF0, {0x11}, true));
    }

    const auto run = decode_as_canopen(
        file.path(), {"can.flags.err", "can.flags.rtr", "can.flags.xtd", "can.len", "can.id"});

    ASSERT_EQ(run.exit_code, 0);
    const std::vector<std::string> expected = {
        "1|||8|", // an error frame has no identifier of its own
        "0|1|0|1|1793",
        "0|0|1|1|448585456",
    };
    EXPECT_EQ(run.lines(), expected);
}

} // namespace
} // namespace eposp::can
