// The device-path link on the slave of a PtyLink: the way `eposp download` reaches `eposp serve`.
#include "eposp/service/device_path_link.hpp"
#include "eposp/service/pty_link.hpp"
#include "eposp/test/test_directory.hpp"
#include "link_test_support.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <termios.h>
#include <unistd.h>

namespace eposp::service {
namespace {

using namespace test;

class DevicePathLinkTest : public testing::Test {
protected:
    void SetUp() override {
        auto opened = PtyLink::open(loop);
        ASSERT_TRUE(opened) << opened.error();
        device = std::move(*opened);
        device_recorder = std::make_unique<LinkRecorder>(*device);
    }

    core::EventLoop loop{core::Pace::RealTime};
    std::unique_ptr<PtyLink> device;
    std::unique_ptr<LinkRecorder> device_recorder;
};

TEST_F(DevicePathLinkTest, ReachesTheDeviceThroughThePseudoTerminalsSlave) {
    auto opened = DevicePathLink::open(loop, device->slave_path());
    ASSERT_TRUE(opened) << opened.error();
    DevicePathLink& client = **opened;
    LinkRecorder client_recorder(client);
    EXPECT_EQ(client.name(), device->slave_path());

    const std::string request("\x10\x01\x41\x60\x00\x00\x9A\xC3\x0D\x0A\x03", 11);
    client.send(bytes_of(request));
    ASSERT_TRUE(run_until(loop, [&] { return device_recorder->received.size() == 11; }));
    EXPECT_EQ(device_recorder->received, request);

    const std::string answer("O\x00\x11\x13\x0D", 5);
    device->send(bytes_of(answer));
    ASSERT_TRUE(run_until(loop, [&] { return client_recorder.received.size() == 5; }));
    EXPECT_EQ(client_recorder.received, answer);
}

TEST_F(DevicePathLinkTest, SetsRaw8N1AtTheRateAsked) {
    auto opened = DevicePathLink::open(loop, device->slave_path(), {.baud = 57600});
    ASSERT_TRUE(opened) << opened.error();
    // The settings are the pseudo-terminal's, as any other opener of the slave sees them.
    const int fd = ::open(device->slave_path().c_str(), O_RDWR | O_NOCTTY);
    ASSERT_GE(fd, 0);
    termios settings{};
    ASSERT_EQ(::tcgetattr(fd, &settings), 0);
    ::close(fd);
    EXPECT_EQ(::cfgetospeed(&settings), B57600);
    EXPECT_EQ(settings.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
    EXPECT_EQ(settings.c_cflag & (PARENB | CSTOPB | CRTSCTS), 0u);
    EXPECT_EQ(settings.c_lflag & (ICANON | ECHO | ISIG), 0u);
}

TEST_F(DevicePathLinkTest, ARateTermiosCannotSetIsRefused) {
    EXPECT_TRUE(termios_supports_baud(115200));
    EXPECT_FALSE(termios_supports_baud(100000));
    auto refused = DevicePathLink::open(loop, device->slave_path(), {.baud = 100000});
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("100000 baud is not a rate"), std::string::npos)
        << refused.error();
}

TEST_F(DevicePathLinkTest, WhatIsNotASerialDeviceIsRefused) {
    const auto directory = eposp::test::test_directory();
    auto is_directory = DevicePathLink::open(loop, directory);
    ASSERT_FALSE(is_directory);
    EXPECT_NE(is_directory.error().find("is a directory"), std::string::npos)
        << is_directory.error();

    auto missing = DevicePathLink::open(loop, directory / "ttyNone");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().find("No such file"), std::string::npos) << missing.error();

    const auto file = directory / "file";
    std::ofstream(file) << "x";
    auto regular = DevicePathLink::open(loop, file);
    ASSERT_FALSE(regular);
    EXPECT_NE(regular.error().find("not a serial device"), std::string::npos) << regular.error();
}

TEST_F(DevicePathLinkTest, TheDeviceGoingAwayClosesTheLink) {
    auto opened = DevicePathLink::open(loop, device->slave_path());
    ASSERT_TRUE(opened) << opened.error();
    DevicePathLink& client = **opened;
    LinkRecorder recorder(client);
    device.reset(); // `eposp serve` ends
    ASSERT_TRUE(run_until(loop, [&] { return client.closed(); }));
    ASSERT_EQ(recorder.events.size(), 1u);
    EXPECT_EQ(recorder.events[0].kind, LinkEvent::Kind::Closed);
    EXPECT_NE(recorder.events[0].text.find("hung up"), std::string::npos)
        << recorder.events[0].text;
    client.send(bytes_of("after"));
    EXPECT_EQ(client.statistics().bytes_dropped_no_host, 5u);
}

} // namespace
} // namespace eposp::service
