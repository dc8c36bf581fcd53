// `--join HOST:PORT` as a user runs it: one eposp process serves a bus over socketcand, others
// put their simulated nodes onto it.
#include "eposp_command.hpp"

#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using test::run_command;
using testing::HasSubstr;

/// A shell loop that waits (up to 30 s) until file `out` has a line starting with `prefix`.
std::string wait_for_line(const std::filesystem::path& out, const std::string& prefix) {
    return "for i in $(seq 600); do grep -q \"^" + prefix + "\" " + out.string() +
           " && break; sleep 0.05; done; ";
}

// The EPOS2 runs in one process on the bus that `eposp bus` serves in another; a third process
// joins too and reads the drive's device type over SDO (CiA 301 7.2.4.3.3): the request crosses
// two joins to reach the drive, the answer comes back the same way.
TEST(JoinCommand, ADriveJoinsTheBusAnotherProcessServes) {
    const auto bus_out = scratch("bus.out");
    const auto bus_log = scratch("bus.log");
    const auto drive_out = scratch("drive.out");
    const auto drive_log = scratch("drive.log");
    const auto request = scratch("sdo.log");
    std::ofstream(request) << "(0.000000) can0 603#4000100000000000\n";

    const auto result = run_command(
        "sh -c '" +
        start_in_background(bus_out,
                            "bus --socketcand 127.0.0.1:0 --for 20s --log " + bus_log.string()) +
        kEposp + " drive epos2 --node-id 3 --join $address --for 3s --log " + drive_log.string() +
        " > " + drive_out.string() + " 2>&1 & drive=$!; " + wait_for_line(drive_out, "join: ") +
        kEposp + " bus --join $address --replay " + request.string() +
        " --for 1s 2>&1; echo replay exit $?; wait $drive; echo drive exit $?; "
        "kill -INT $pid; wait $pid'");
    const std::string drive = read_file(drive_out);
    ASSERT_THAT(result.output, HasSubstr("replay exit 0")) << result.output << drive;
    ASSERT_THAT(result.output, HasSubstr("drive exit 0")) << result.output << drive;
    EXPECT_THAT(result.output, HasSubstr("replay: 1 frames sent, 0 refused"));
    EXPECT_THAT(drive, HasSubstr("join: bus can0 of 127.0.0.1:"));
    EXPECT_THAT(drive, HasSubstr("epos2: node 3 on bus can0"));

    // The serving bus carried the boot-up, the request and the answer (0x1000 = 0x00020192).
    const std::string served = read_file(bus_log);
    EXPECT_THAT(served, HasSubstr(" can0 703#00\n")) << served;
    EXPECT_THAT(served, HasSubstr(" can0 603#4000100000000000\n")) << served;
    EXPECT_THAT(served, HasSubstr(" can0 583#4300100092010200\n")) << served;
    // The drive's own bus got the request from the served one.
    const std::string own = read_file(drive_log);
    EXPECT_THAT(own, HasSubstr(" can0 603#4000100000000000\n")) << own;
    EXPECT_THAT(own, HasSubstr(" can0 583#4300100092010200\n")) << own;
    EXPECT_THAT(read_file(bus_out), HasSubstr("socketcand: socketcand-1 joined from 127.0.0.1:"));
}

// python-canopen guards a node through python-can 4.1's socketcand interface, which writes the
// guard request (a remote frame) as a frame without data: the node, which joined the served bus
// from another process, gets it as a remote frame and answers with the toggle bit alternating
// (CiA 301 7.2.8.3.2.1).
TEST(JoinCommand, APythonCanClientGuardsANodeThatJoinedTheBus) {
    const auto bus_out = scratch("bus.out");
    const auto node_out = scratch("node.out");
    const auto guard = scratch("guard.py");
    std::ofstream(guard) << R"(import sys, time
try:
    import can
except ImportError:
    sys.exit(77)
bus = can.Bus(interface="socketcand", host=sys.argv[1], port=int(sys.argv[2]), channel="can0")
answers = []
for _ in range(2):
    # what python-canopen's NodeGuarding sends: send_message(0x700 + node_id, None, remote=True)
    bus.send(can.Message(arbitration_id=0x705, is_extended_id=False, is_remote_frame=True))
    deadline = time.monotonic() + 5
    while time.monotonic() < deadline:
        msg = bus.recv(0.1)
        if msg is not None and msg.arbitration_id == 0x705 and list(msg.data) not in ([], [0]):
            answers.append("%02X" % msg.data[0])
            break
bus.shutdown()
print("answers", *answers)
)";
    const auto result = run_command(
        "sh -c '" + start_in_background(bus_out, "bus --socketcand 127.0.0.1:0 --for 30s") +
        kEposp + " node --eds " + EPOSP_SOURCE_DIR +
        "/examples/canopen-node/sample-device.eds --node-id 5 --join $address --for 20s > " +
        node_out.string() + " 2>&1 & node=$!; " + wait_for_line(node_out, "join: ") +
        "/usr/bin/python3 " + guard.string() +
        " ${address%:*} ${address##*:} 2>&1; code=$?; kill -INT $node; wait $node; "
        "kill -INT $pid; wait $pid; exit $code'");
    if (result.exit_code == 77) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    ASSERT_EQ(result.exit_code, 0) << result.output << read_file(node_out);
    EXPECT_THAT(result.output, HasSubstr("answers 7F FF\n")) << read_file(node_out);
}

TEST(JoinCommand, NothingListeningIsAUserError) {
    const auto result = eposp("drive epos2 --node-id 3 --join 127.0.0.1:1 --for 3s");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp drive epos2: error: --join 127.0.0.1:1: cannot "
                                         "connect to 127.0.0.1:1: Connection refused"));
}

TEST(JoinCommand, ABusTheServerDoesNotHaveIsAUserError) {
    const auto out = scratch("bus.out");
    const auto result = run_command(
        "sh -c '" + start_in_background(out, "bus --socketcand 127.0.0.1:0 --for 20s") + kEposp +
        " node --eds " + EPOSP_SOURCE_DIR +
        "/examples/canopen-node/sample-device.eds --node-id 5 --join $address --join-bus vcan7 "
        "--for 1s 2>&1; code=$?; kill -INT $pid; wait $pid; exit $code'");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("refused to open bus vcan7"));
}

TEST(JoinCommand, TheRunEndsWhenTheServerGoesAway) {
    const auto bus_out = scratch("bus.out");
    const auto drive_out = scratch("drive.out");
    const auto result =
        run_command("sh -c '" + start_in_background(bus_out, "bus --socketcand 127.0.0.1:0") +
                    kEposp + " drive epos2 --join $address --for 60s > " + drive_out.string() +
                    " 2>&1 & drive=$!; " + wait_for_line(drive_out, "join: ") +
                    "kill -INT $pid; wait $pid; wait $drive; echo drive exit $?'");
    const std::string drive = read_file(drive_out);
    EXPECT_THAT(result.output, HasSubstr("drive exit 1")) << result.output; // cut off: a failure
    EXPECT_THAT(drive, HasSubstr("join: bus can0 of 127.0.0.1:"));
    EXPECT_THAT(drive, HasSubstr(" closed the connection\n"));
    EXPECT_THAT(drive, HasSubstr("epos2: node 1 stopped in"));
}

TEST(JoinCommand, JoinIsRefusedInVirtualTime) {
    const auto result = eposp("bus --virtual --join 127.0.0.1:29536 --for 1s");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("--socketcand, --socketcan, --join) cannot take part"));
    EXPECT_EQ(eposp("bus --join-bus can1 --for 1s").exit_code, 1); // --join-bus needs --join
}

} // namespace
} // namespace eposp::device
