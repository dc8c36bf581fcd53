// `eposp bus` driven as a user drives it, on the files in examples/.
#include "eposp_command.hpp"

#include <filesystem>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using test::run_command;
using testing::ContainsRegex;
using testing::HasSubstr;

const std::string kNetworkLog =
    std::string(EPOSP_SOURCE_DIR) + "/examples/bus-demo/canopen-network.log";

TEST(BusCommand, VirtualReplayCarriesEveryFrameOfTheLog) {
    const auto log = scratch("bus.log");
    const auto pcap = scratch("bus.pcap");
    const auto result = eposp("bus --virtual --for 1s --replay " + kNetworkLog + " --log " +
                              log.string() + " --pcap " + pcap.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("replay: 113 frames sent, 0 refused"));
    EXPECT_THAT(result.output, HasSubstr("113 frames, 0 error frames"));

    const std::string recorded = read_file(log);
    EXPECT_EQ(std::count(recorded.begin(), recorded.end(), '\n'), 113);
    EXPECT_THAT(recorded, HasSubstr(" can0 701#00\n"));
    // pcap: 24-byte file header, then per frame a 16-byte record header and 16 bytes of data.
    EXPECT_EQ(std::filesystem::file_size(pcap), 24U + 113U * 32U);
}

TEST(BusCommand, VirtualRunsAreDeterministic) {
    const auto first = scratch("first.log");
    const auto second = scratch("second.log");
    for (const auto& log : {first, second}) {
        ASSERT_EQ(eposp("bus --virtual --bitrate 125000 --replay " + kNetworkLog + " --log " +
                        log.string())
                      .exit_code,
                  0);
    }
    EXPECT_EQ(read_file(first), read_file(second));
    EXPECT_FALSE(read_file(first).empty());
}

TEST(BusCommand, MalformedReplayFileIsAUserErrorNamingTheLine) {
    const auto bad = scratch("bad.log");
    std::ofstream(bad) << "(0.000000) can0 123#00\n(0.001000) can0 12G#00\n";
    const auto result = eposp("bus --virtual --replay " + bad.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(":2:"));
}

// Starts `eposp bus --socketcand 127.0.0.1:0 [options]` in the background of a shell script.
std::string start_real_time_bus(const std::filesystem::path& out, const std::string& options = "") {
    return start_in_background(out, "bus --socketcand 127.0.0.1:0 " + options);
}

TEST(BusCommand, AddressInUseIsAUserError) {
    const auto out = scratch("first.out");
    const auto result = run_command("sh -c '" + start_real_time_bus(out) + kEposp +
                                    " bus --socketcand $address --for 1s 2>&1; code=$?; "
                                    "kill -INT $pid; wait $pid; exit $code'");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("127.0.0.1:"));
}

TEST(BusCommand, SigintEndsARealTimeRunCleanlyWithItsSummary) {
    const auto out = scratch("bus.out");
    const auto result =
        run_command("sh -c '" + start_real_time_bus(out) + "kill -INT $pid; wait $pid'");
    EXPECT_EQ(result.exit_code, 0) << read_file(out);
    const std::string printed = read_file(out);
    EXPECT_THAT(printed, HasSubstr("interrupted"));
    EXPECT_THAT(printed, HasSubstr("bus can0 at 1000 kbit/s"));
}

// The issue's acceptance run: two independent socketcand clients (python-can) exchange frames
// through `eposp bus`, and the pcap it writes holds every one of them.
TEST(BusCommand, PythonCanClientsExchangeFramesAndThePcapHoldsThem) {
    const auto out = scratch("bus.out");
    const auto pcap = scratch("bus.pcap");
    const std::string clients =
        std::string(EPOSP_SOURCE_DIR) + "/examples/bus-demo/python_can_clients.py";
    const auto result =
        run_command("sh -c '" + start_real_time_bus(out, "--pcap " + pcap.string()) +
                    "/usr/bin/python3 " + clients +
                    " ${address%:*} ${address##*:} 2>&1; code=$?; "
                    "kill -INT $pid; wait $pid; exit $code'");
    if (result.exit_code == 77) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    ASSERT_EQ(result.exit_code, 0) << result.output << read_file(out);
    EXPECT_THAT(result.output, HasSubstr("ok: 20 frames a -> b and 20 frames b -> a"));
    // 24-byte pcap header, then 16 + 16 bytes per frame.
    EXPECT_EQ(std::filesystem::file_size(pcap), 24U + 40U * 32U);
}

// A socketcand client that sends a burst beyond its transmit queue (--socketcand-queue 4) and
// leaves: the frames it lost are in the summary, though its port is gone.
TEST(BusCommand, FramesAClientLostToItsFullQueueStayInTheSummaryAfterItLeft) {
    const auto out = scratch("bus.out");
    const auto client = scratch("client.py");
    std::ofstream(client) << R"(import socket, sys
s = socket.create_connection((sys.argv[1], int(sys.argv[2])), timeout=10)
def expect(text):
    got = b""
    while not got.endswith(text):
        chunk = s.recv(256)
        if not chunk:
            sys.exit("closed while waiting for " + text.decode())
        got += chunk
expect(b"< hi >")
s.sendall(b"< open can0 >")
expect(b"< ok >")
s.sendall(b"< rawmode >")
expect(b"< ok >")
s.sendall(b"".join(b"< send %03X 0 >" % (0x100 + i) for i in range(20)))
s.shutdown(socket.SHUT_WR)
while s.recv(4096):
    pass
)";
    const auto result = run_command("sh -c '" + start_real_time_bus(out, "--socketcand-queue 4") +
                                    "/usr/bin/python3 " + client.string() +
                                    " ${address%:*} ${address##*:} 2>&1; code=$?; " +
                                    "kill -INT $pid; wait $pid; exit $code'");
    const std::string printed = read_file(out);
    ASSERT_EQ(result.exit_code, 0) << result.output << printed;
    EXPECT_THAT(printed, HasSubstr("socketcand: socketcand-1 joined from 127.0.0.1:"));
    EXPECT_THAT(printed, HasSubstr("socketcand: socketcand-1 left (the client disconnected)"));
    // 4 or 5 of the 20 frames reach the bus (one may be on the wire already); the rest are lost.
    EXPECT_THAT(printed,
                ContainsRegex("1 left +tx +[45]  rx +0  tx-overflows +1[56]  rx-overflows +0"))
        << printed;
}

TEST(BusCommand, TheDemoRunsToTheEnd) {
    const auto dir = scratch("demo");
    const auto result = run_command("EPOSP_DEMO_DIR=" + dir.string() + " " + EPOSP_SOURCE_DIR +
                                    "/examples/bus-demo/run.sh " + kEposp + " 2>&1");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("replay: 113 frames sent"));
    EXPECT_THAT(result.output, HasSubstr("socketcand: listening on"));
}

} // namespace
} // namespace eposp::device
