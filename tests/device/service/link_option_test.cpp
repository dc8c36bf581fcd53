// The text of `--serial` / `--usb` / `--port`, and which kinds each side can open.
#include "eposp/service/link_option.hpp"
#include "eposp/service/open_link.hpp"
#include "eposp/service/pty_link.hpp"
#include "eposp/test/test_directory.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace eposp::service {
namespace {

std::string error_of(std::string_view text) {
    const auto parsed = parse_link_option(text);
    EXPECT_FALSE(parsed) << text;
    return parsed ? std::string() : parsed.error();
}

TEST(LinkOption, NamesAPseudoTerminalADevicePathOrATcpAddress) {
    EXPECT_EQ(*parse_link_option("pty"), (LinkOption{LinkOption::Kind::Pty, {}}));
    EXPECT_EQ(*parse_link_option("tcp:127.0.0.1:0"),
              (LinkOption{LinkOption::Kind::Tcp, "127.0.0.1:0"}));
    EXPECT_EQ(*parse_link_option("tcp:4001"), (LinkOption{LinkOption::Kind::Tcp, "4001"}));
    EXPECT_EQ(*parse_link_option("tcp:[::1]:4001"),
              (LinkOption{LinkOption::Kind::Tcp, "[::1]:4001"}));
    EXPECT_EQ(*parse_link_option("/dev/null"),
              (LinkOption{LinkOption::Kind::DevicePath, "/dev/null"}))
        << "a character device; whether it is a terminal is found out when it is opened";
}

TEST(LinkOption, SaysWhatIsWrong) {
    EXPECT_NE(error_of("").find("no link given"), std::string::npos);
    EXPECT_NE(error_of("tcp:").find("is not a TCP address"), std::string::npos);
    EXPECT_NE(error_of("tcp:host:port").find("is not a TCP address"), std::string::npos);
    const auto directory = eposp::test::test_directory();
    EXPECT_NE(error_of(directory.string()).find("is a directory, not a serial device"),
              std::string::npos);
    EXPECT_NE(error_of((directory / "ttyNone").string()).find("does not exist"), std::string::npos);
    const auto file = directory / "notes.txt";
    std::ofstream(file) << "x";
    EXPECT_NE(error_of(file.string()).find("is not a serial device"), std::string::npos);
}

TEST(OpenLink, TheDeviceSideOpensEachKindPacedAndTellsWhereHostsFindIt) {
    core::EventLoop loop(core::Pace::RealTime);
    auto pty = open_serving_link(loop, *parse_link_option("pty"));
    ASSERT_TRUE(pty) << pty.error();
    EXPECT_TRUE(pty->where.starts_with("/dev/pts/")) << pty->where;
    EXPECT_EQ(pty->link->pacing().bits_per_second, 115200u);

    auto tcp = open_serving_link(loop, *parse_link_option("tcp:127.0.0.1:0"),
                                 {.pacing = LinkPacing::usb()});
    ASSERT_TRUE(tcp) << tcp.error();
    EXPECT_TRUE(tcp->where.starts_with("127.0.0.1:")) << tcp->where;
    EXPECT_NE(tcp->where, "127.0.0.1:0") << "the port picked";
    EXPECT_EQ(tcp->link->pacing().bits_per_second, 1'000'000u);

    auto path = open_serving_link(loop, *parse_link_option(pty->where));
    ASSERT_TRUE(path) << path.error();
    EXPECT_EQ(path->where, pty->where);
}

TEST(OpenLink, ASymlinkIsOnlyForAPseudoTerminal) {
    core::EventLoop loop(core::Pace::RealTime);
    auto refused = open_serving_link(loop, *parse_link_option("tcp:0"),
                                     {.symlink = eposp::test::test_file("ttyEPOSP")});
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("only name a pseudo-terminal"), std::string::npos)
        << refused.error();
}

TEST(OpenLink, AClientNeedsSomethingToReach) {
    core::EventLoop loop(core::Pace::RealTime);
    auto refused = open_client_link(loop, *parse_link_option("pty"));
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("give the path that `eposp serve` printed"), std::string::npos);

    auto device = PtyLink::open(loop);
    ASSERT_TRUE(device) << device.error();
    auto client = open_client_link(loop, *parse_link_option((*device)->slave_path()), 9600);
    ASSERT_TRUE(client) << client.error();
    auto bad_rate = open_client_link(loop, *parse_link_option((*device)->slave_path()), 12345);
    EXPECT_FALSE(bad_rate);
    auto tcp = open_client_link(loop, *parse_link_option("tcp:127.0.0.1:1"));
    EXPECT_TRUE(tcp) << "connecting is asynchronous: a refusal closes the link later";
}

} // namespace
} // namespace eposp::service
