// SocketCAN needs a kernel with AF_CAN; the tests that talk to an interface need vcan0 as well
// (modprobe vcan && ip link add vcan0 type vcan && ip link set vcan0 up) and skip without it.
#include "eposp/can/io/socketcan_error_frame.hpp"
#include "eposp/can/io/socketcan_port.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <net/if.h>
#include <optional>
#include <ostream>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

namespace eposp::can::io {
namespace {

using namespace std::chrono_literals;

bool kernel_has_af_can() {
    const int probe = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (probe < 0) {
        return false;
    }
    ::close(probe);
    return true;
}

constexpr const char* kVirtualInterface = "vcan0";

/// Why the interface tests cannot run here, or nothing when they can.
std::optional<std::string> reason_to_skip() {
    if (!kernel_has_af_can()) {
        return "this kernel has no AF_CAN support";
    }
    if (::if_nametoindex(kVirtualInterface) == 0) {
        return "no vcan0 interface (modprobe vcan; ip link add vcan0 type vcan; ip link set "
               "vcan0 up)";
    }
    return std::nullopt;
}

TEST(SocketCanPort, OpeningAMissingInterfaceSaysWhy) {
    core::EventLoop loop;
    auto port = SocketCanPort::open(loop, "nosuchcan7");
    ASSERT_FALSE(port);
    if (kernel_has_af_can()) {
        EXPECT_EQ(port.error(), "no such CAN interface nosuchcan7");
    } else {
        EXPECT_NE(port.error().find("no AF_CAN support"), std::string::npos) << port.error();
    }
}

TEST(SocketCanPort, RefusesANameNoInterfaceCanHave) {
    core::EventLoop loop;
    EXPECT_FALSE(SocketCanPort::open(loop, ""));
    const auto port = SocketCanPort::open(loop, "a_name_longer_than_ifnamsiz");
    ASSERT_FALSE(port);
    EXPECT_NE(port.error().find("not a network interface name"), std::string::npos);
}

TEST(SocketCanPort, NonCanInterfaceIsRefused) {
    if (!kernel_has_af_can()) {
        GTEST_SKIP() << "this kernel has no AF_CAN support";
    }
    core::EventLoop loop;
    const auto port = SocketCanPort::open(loop, "lo");
    ASSERT_FALSE(port);
    EXPECT_EQ(port.error(), "lo is not a CAN interface");
}

TEST(SocketCanPort, FramesTravelBetweenTwoSocketsOnVcan) {
    if (const auto reason = reason_to_skip()) {
        GTEST_SKIP() << *reason;
    }
    core::EventLoop loop(core::Pace::RealTime);
    auto a = SocketCanPort::open(loop, kVirtualInterface);
    auto b = SocketCanPort::open(loop, kVirtualInterface);
    ASSERT_TRUE(a) << a.error();
    ASSERT_TRUE(b) << b.error();

    const std::vector<Frame> a_sends = {Frame::data_frame(0x181, {1, 2, 3, 4, 5, 6, 7, 8}),
                                        Frame::data_frame(0x1ABCDEF0, {0xFF}, true),
                                        Frame::remote_frame(0x701, 1), Frame::data_frame(0, {})};
    const Frame b_sends = Frame::data_frame(0x7FF, {0x42});
    std::vector<Frame> a_received;
    std::vector<Frame> b_received;
    const auto check_done = [&] {
        if (a_received.size() == 1 && b_received.size() == a_sends.size()) {
            loop.stop();
        }
    };
    (*a)->on_receive([&](const Frame& frame) {
        a_received.push_back(frame);
        check_done();
    });
    (*b)->on_receive([&](const Frame& frame) {
        b_received.push_back(frame);
        check_done();
    });
    for (const Frame& frame : a_sends) {
        ASSERT_EQ((*a)->send(frame), SendStatus::Queued);
    }
    ASSERT_EQ((*b)->send(b_sends), SendStatus::Queued);
    loop.run_for(5s);

    EXPECT_EQ(b_received, a_sends);
    ASSERT_EQ(a_received.size(), 1U); // and not its own frames
    EXPECT_EQ(a_received[0], b_sends);
    EXPECT_EQ((*a)->error_state(), ErrorState::Active);
    EXPECT_EQ((*a)->name(), "vcan0");
}

TEST(SocketCanPort, InvalidFramesAreRefusedBeforeTheKernel) {
    if (const auto reason = reason_to_skip()) {
        GTEST_SKIP() << *reason;
    }
    core::EventLoop loop(core::Pace::RealTime);
    auto port = SocketCanPort::open(loop, kVirtualInterface);
    ASSERT_TRUE(port) << port.error();
    EXPECT_EQ((*port)->send(Frame::data_frame(0x800, {})), SendStatus::InvalidFrame);
}

// ---- error frames -----------------------------------------------------------------------------

Frame error_frame(std::uint32_t error_class, std::uint8_t controller_details = 0) {
    Frame frame;
    frame.error = true;
    frame.id = error_class;
    frame.dlc = CAN_ERR_DLC;
    frame.data[1] = controller_details;
    return frame;
}

struct ErrorFrameCase {
    Frame frame;
    std::optional<ErrorState> expected;
    friend void PrintTo(const ErrorFrameCase& c, std::ostream* os) {
        *os << (c.frame.error ? "error class 0x" : "data frame 0x") << std::hex << c.frame.id
            << " controller 0x" << int{c.frame.data[1]};
    }
};

class ErrorFrameMapping : public testing::TestWithParam<ErrorFrameCase> {};

TEST_P(ErrorFrameMapping, GivesTheAnnouncedState) {
    EXPECT_EQ(error_state_reported_by(GetParam().frame), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Table, ErrorFrameMapping,
    testing::Values(
        ErrorFrameCase{error_frame(CAN_ERR_BUSOFF), ErrorState::BusOff},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE), ErrorState::Passive},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_PASSIVE), ErrorState::Passive},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL | CAN_ERR_CNT, CAN_ERR_CRTL_TX_PASSIVE),
                       ErrorState::Passive},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE), ErrorState::Active},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_WARNING), ErrorState::Warning},
        ErrorFrameCase{error_frame(CAN_ERR_RESTARTED), ErrorState::Active},
        ErrorFrameCase{error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW), std::nullopt},
        ErrorFrameCase{error_frame(CAN_ERR_PROT | CAN_ERR_ACK), std::nullopt},
        ErrorFrameCase{Frame::data_frame(CAN_ERR_BUSOFF, {}), std::nullopt}));

} // namespace
} // namespace eposp::can::io
