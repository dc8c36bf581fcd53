// The pseudo-terminal link with hosts that open its slave with plain POSIX calls. The loop runs
// in real time, waiting on the pty; every wait ends as soon as what it waits for has happened.
#include "eposp/service/paced_link.hpp"
#include "eposp/service/pty_link.hpp"
#include "eposp/test/test_directory.hpp"
#include "link_test_support.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace eposp::service {
namespace {

using namespace test;
namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), {}};
}

class PtyLinkTest : public testing::Test {
protected:
    void open_link(PtyLinkOptions options = {}) {
        auto opened = PtyLink::open(loop, std::move(options));
        ASSERT_TRUE(opened) << opened.error();
        link = std::move(*opened);
        recorder = std::make_unique<LinkRecorder>(*link);
    }

    core::EventLoop loop{core::Pace::RealTime};
    std::unique_ptr<PtyLink> link;
    std::unique_ptr<LinkRecorder> recorder;
};

TEST_F(PtyLinkTest, BytesTravelBothWaysBetweenTheLinkAndAHostOnTheSlave) {
    open_link();
    ASSERT_TRUE(link->slave_path().starts_with("/dev/pts/")) << link->slave_path();
    EXPECT_EQ(link->name(), "pty " + link->slave_path());
    PosixHost host(link->slave_path());
    ASSERT_TRUE(host.is_open());

    // Raw mode: 0x0D, 0x0A, 0x03 (^C), 0x04 (^D), 0x11 (XON) and 0x90 pass unchanged.
    const std::string request("\x90\x02\x10\x02\x0D\x0A\x03\x04\x11\x00", 10);
    ASSERT_TRUE(host.write(request));
    ASSERT_TRUE(run_until(loop, [&] { return recorder->received.size() == request.size(); }));
    EXPECT_EQ(recorder->received, request);

    const std::string answer("O\x0D\x0A\x00\xFF", 5);
    link->send(bytes_of(answer));
    ASSERT_TRUE(run_until(loop, [&] {
        host.read_available();
        return host.received().size() == answer.size() &&
               link->statistics().bytes_sent == answer.size();
    }));
    EXPECT_EQ(host.received(), answer);
    EXPECT_EQ(link->statistics().bytes_received, request.size());
}

TEST_F(PtyLinkTest, AHostClosingIsAHangUpAndTheNextHostIsServed) {
    open_link();
    {
        PosixHost first(link->slave_path());
        ASSERT_TRUE(first.write("first"));
        ASSERT_TRUE(run_until(loop, [&] { return recorder->received == "first"; }));
    }
    ASSERT_TRUE(run_until(loop, [&] { return !recorder->events.empty(); }));
    ASSERT_EQ(recorder->events.size(), 1u);
    EXPECT_EQ(recorder->events[0].kind, LinkEvent::Kind::HungUp);
    EXPECT_FALSE(link->host_present());
    EXPECT_FALSE(link->closed());

    link->send(bytes_of("for nobody")); // dropped: no host is there
    EXPECT_EQ(link->statistics().bytes_dropped_no_host, 10u);

    PosixHost second(link->slave_path());
    ASSERT_TRUE(second.is_open());
    ASSERT_TRUE(second.write("second"));
    ASSERT_TRUE(run_until(loop, [&] { return recorder->received == "firstsecond"; }));
    ASSERT_TRUE(run_until(loop, [&] { return link->host_present(); }));
    link->send(bytes_of("answer"));
    ASSERT_TRUE(run_until(loop, [&] {
        second.read_available();
        return second.received().size() >= 6;
    }));
    EXPECT_EQ(second.received(), "answer"); // nothing meant for the first host
    EXPECT_EQ(link->statistics().hang_ups, 1u);
}

TEST_F(PtyLinkTest, WhatTheLastHostLeftUnreadIsNotReadByTheNext) {
    open_link();
    {
        PosixHost first(link->slave_path());
        link->send(bytes_of("stale answer"));
        ASSERT_TRUE(run_until(loop, [&] { return link->statistics().bytes_sent == 12; }));
    } // closes without reading it
    // An answer on its way when the host left, before the link has noticed: the kernel keeps it
    // for whoever opens the slave next.
    link->send(bytes_of("late answer"));
    ASSERT_TRUE(run_until(loop, [&] { return !link->host_present(); }));

    PosixHost second(link->slave_path());
    ASSERT_TRUE(run_until(loop, [&] { return link->host_present(); }));
    ASSERT_TRUE(second.write("?"));
    ASSERT_TRUE(run_until(loop, [&] { return recorder->received == "?"; }));
    link->send(bytes_of("fresh"));
    ASSERT_TRUE(run_until(loop, [&] {
        second.read_available();
        return second.received().size() >= 5;
    }));
    EXPECT_EQ(second.received(), "fresh");
}

TEST_F(PtyLinkTest, OutputForAHostThatDoesNotReadIsBoundedAndTheNewestIsDropped) {
    open_link({.max_unsent_bytes = 1000});
    PosixHost host(link->slave_path()); // never reads
    const std::string chunk(4096, 'x');
    for (int i = 0; i < 64; ++i) { // 256 KiB: far more than the kernel's buffer and ours
        link->send(bytes_of(chunk));
        loop.run_for(1ms);
    }
    constexpr std::uint64_t kTotal = 64 * 4096;
    const LinkStatistics statistics = link->statistics();
    EXPECT_GT(statistics.bytes_dropped_full, 0u);
    EXPECT_LE(kTotal - statistics.bytes_sent - statistics.bytes_dropped_full, 1000u)
        << "at most the bound is queued";

    // The host reads again: what was queued arrives, whole and in order.
    ASSERT_TRUE(run_until(loop, [&] {
        host.read_available();
        const LinkStatistics now = link->statistics();
        return now.bytes_sent + now.bytes_dropped_full == kTotal &&
               host.received().size() == now.bytes_sent;
    }));
    EXPECT_EQ(host.received(), std::string(host.received().size(), 'x'));
    EXPECT_FALSE(link->closed());
}

TEST_F(PtyLinkTest, AHostLeavingDuringAPacedAnswerLosesOnlyTheRestOfIt) {
    open_link();
    PtyLink* pty = link.get();
    auto paced = PacedLink::wrap(loop, std::move(link), LinkPacing::rs232()); // 100 ms
    ASSERT_TRUE(paced) << paced.error();
    LinkRecorder paced_recorder(**paced);
    {
        PosixHost first(pty->slave_path());
        (*paced)->send(bytes_of(std::string(1152, 'a')));
        ASSERT_TRUE(run_until(loop, [&] {
            first.read_available();
            return first.received().size() >= 100;
        }));
        EXPECT_LT(first.received().size(), 1152u) << "paced: not all at once";
    } // leaves in the middle of the answer
    ASSERT_TRUE(run_until(loop, [&] { return !paced_recorder.events.empty(); }));
    EXPECT_EQ(paced_recorder.events[0].kind, LinkEvent::Kind::HungUp);
    EXPECT_EQ((*paced)->queued_bytes(), 0u);
    const LinkStatistics statistics = (*paced)->statistics();
    EXPECT_EQ(statistics.bytes_sent + statistics.bytes_dropped_no_host, 1152u);

    PosixHost second(pty->slave_path());
    ASSERT_TRUE(run_until(loop, [&] { return pty->host_present(); }));
    (*paced)->send(bytes_of("fresh"));
    ASSERT_TRUE(run_until(loop, [&] {
        second.read_available();
        return second.received().size() >= 5;
    }));
    EXPECT_EQ(second.received(), "fresh");
}

TEST_F(PtyLinkTest, ClosingTheLinkHangsUpTheHost) {
    open_link();
    PosixHost host(link->slave_path());
    link.reset();
    EXPECT_FALSE(host.read_available()) << "the host reads EIO or end of file";
}

TEST_F(PtyLinkTest, TheSymlinkPointsToTheSlaveAndIsRemovedAtClose) {
    const fs::path symlink = eposp::test::test_file("ttyEPOSP");
    open_link({.symlink = symlink});
    EXPECT_EQ(link->symlink_path(), symlink);
    ASSERT_TRUE(fs::is_symlink(symlink));
    EXPECT_EQ(fs::read_symlink(symlink), link->slave_path());

    PosixHost host(symlink.string()); // the symlink works as the device
    ASSERT_TRUE(host.write("via link"));
    ASSERT_TRUE(run_until(loop, [&] { return recorder->received == "via link"; }));
    host.close();

    link.reset();
    EXPECT_FALSE(fs::exists(fs::symlink_status(symlink)));
}

TEST_F(PtyLinkTest, TheSymlinkDoesNotReplaceAFileOrAForeignSymlink) {
    const fs::path file = eposp::test::test_file("ttyEPOSP");
    std::ofstream(file) << "user data";
    auto refused = PtyLink::open(loop, {.symlink = file});
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("is not a symlink"), std::string::npos) << refused.error();
    EXPECT_EQ(read_file(file), "user data");

    const fs::path foreign = eposp::test::test_file("ttyOther");
    fs::create_symlink(file, foreign);
    auto refused_link = PtyLink::open(loop, {.symlink = foreign});
    ASSERT_FALSE(refused_link);
    EXPECT_NE(refused_link.error().find("not replaced"), std::string::npos) << refused_link.error();
    EXPECT_EQ(fs::read_symlink(foreign), file);
}

TEST_F(PtyLinkTest, ASymlinkLeftToAVanishedPseudoTerminalIsReplaced) {
    const fs::path symlink = eposp::test::test_file("ttyEPOSP");
    fs::create_symlink("/dev/pts/999999", symlink); // an earlier run that did not close
    open_link({.symlink = symlink});
    EXPECT_EQ(fs::read_symlink(symlink), link->slave_path());
}

} // namespace
} // namespace eposp::service
