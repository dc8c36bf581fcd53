#include "eposp/can/bus_recorder.hpp"
#include "eposp/can/candump_log_reader.hpp"
#include "eposp/can/candump_log_writer.hpp"
#include "eposp/can/candump_replay.hpp"
#include "eposp/can/pcap_reader.hpp"
#include "eposp/can/pcap_writer.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <sstream>
#include <vector>

// Traces recorded from, and replayed onto, a running VirtualBus.
namespace eposp::can {
namespace {

using namespace std::chrono_literals;
using testing_support::TempFile;

struct Received {
    core::TimePoint time;
    Frame frame;
};

// A bus with a master that sends and a slave that notes what it receives, and when.
class TracedBus : public testing::Test {
protected:
    TracedBus() {
        slave_->on_receive([this](const Frame& frame) {
            received_.push_back({loop_.now(), frame});
        });
    }

    // NMT start, SYNC and an SDO request, 1 ms apart: the bus is idle for each of them.
    void schedule_master() {
        loop_.at(core::TimePoint(1ms), [this] {
            master_->send(Frame::data_frame(0x000, {0x01, 0x00}));
        });
        loop_.at(core::TimePoint(2ms), [this] { master_->send(Frame::data_frame(0x080, {})); });
        loop_.at(core::TimePoint(3ms), [this] {
            master_->send(Frame::data_frame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
        });
    }

    void run_master() {
        schedule_master();
        loop_.run_until(core::TimePoint(10ms));
    }

    std::vector<CandumpRecord> expected_log(TraceClock clock = {}) const {
        std::vector<CandumpRecord> log;
        for (const auto& [time, frame] : received_) {
            log.push_back({TraceTime(std::chrono::floor<std::chrono::microseconds>(
                               clock.to_trace(time).time_since_epoch())),
                           "can0", frame});
        }
        return log;
    }

    core::EventLoop loop_;
    VirtualBus bus_{loop_, BusConfig{.name = "can0", .bitrate = 500'000}};
    std::unique_ptr<VirtualPort> master_ = bus_.connect("master");
    std::unique_ptr<VirtualPort> slave_ = bus_.connect("slave");
    std::vector<Received> received_;
};

TEST_F(TracedBus, CandumpLogHasEveryFrameAtItsReceiveTime) {
    std::stringstream log;
    CandumpLogWriter writer{TraceOutput(log)};
    const BusRecorder recorder(bus_, writer);
    run_master();

    ASSERT_EQ(received_.size(), 3U);
    const auto read = read_candump_log(log, "log");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(*read, expected_log());
}

TEST_F(TracedBus, CandumpLogOfARealTimeRunShowsEpochTimes) {
    std::stringstream log;
    CandumpLogWriter writer{TraceOutput(log)};
    const auto clock = TraceClock::aligned(loop_.now(), TraceTime(1436509052s));
    const BusRecorder recorder(bus_, writer, clock);
    run_master();

    EXPECT_TRUE(log.str().starts_with("(1436509052.001")) << log.str();
    const auto read = read_candump_log(log, "log");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(*read, expected_log(clock));
}

TEST_F(TracedBus, ErrorFramesAreRecordedBeforeTheRepeatedFrame) {
    std::stringstream log;
    CandumpLogWriter writer{TraceOutput(log)};
    const BusRecorder recorder(bus_, writer);
    bus_.corrupt_frames([](const Frame& frame) { return frame.id == 0x080; });
    run_master();

    const auto read = read_candump_log(log, "log");
    ASSERT_TRUE(read) << read.error();
    ASSERT_EQ(read->size(), 4U) << log.str();
    EXPECT_EQ((*read)[0].frame.id, 0x000U);
    EXPECT_TRUE((*read)[1].frame.error);
    EXPECT_EQ((*read)[1].frame.dlc, 8);
    EXPECT_TRUE(log.str().find(" can0 20000") != std::string::npos) << log.str();
    EXPECT_EQ((*read)[2].frame, Frame::data_frame(0x080, {}));
    EXPECT_EQ((*read)[3].frame.id, 0x601U);
}

TEST_F(TracedBus, PcapHasEveryFrameAtItsReceiveTimeInNanoseconds) {
    const TempFile file(".pcap");
    auto output = TraceOutput::create(file.path());
    ASSERT_TRUE(output) << output.error();
    PcapWriter writer(std::move(*output));
    const BusRecorder recorder(bus_, writer);
    run_master();

    // Read while the writer is still open, as a run cut short would leave the file.
    const auto capture = read_pcap_file(file.path());
    ASSERT_TRUE(capture) << capture.error();
    ASSERT_EQ(capture->records.size(), received_.size());
    for (std::size_t i = 0; i < received_.size(); ++i) {
        EXPECT_EQ(capture->records[i].time.time_since_epoch(),
                  received_[i].time.time_since_epoch());
        EXPECT_EQ(capture->records[i].frame, received_[i].frame);
    }
}

TEST_F(TracedBus, RecordingStopsWhenTheRecorderIsDestroyed) {
    std::stringstream log;
    CandumpLogWriter writer{TraceOutput(log)};
    schedule_master();
    {
        const BusRecorder recorder(bus_, writer);
        loop_.run_until(core::TimePoint(1500us));
    }
    loop_.run_until(core::TimePoint(10ms));
    const auto read = read_candump_log(log, "log");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->size(), 1U);
}

TEST_F(TracedBus, ReplayedLogKeepsItsTimingOnTheBus) {
    // Equal frames take equal time on the wire, so receive times keep the log's spacing.
    std::istringstream log("(1436509052.000000) can0 080#\n"
                           "(1436509052.001000) can0 080#\n"
                           "(1436509052.001500) can1 000#0100\n"
                           "(1436509052.011000) can0 080#\n");
    const auto records = read_candump_log(log, "log");
    ASSERT_TRUE(records) << records.error();
    CandumpReplay replay(loop_, *master_, *records,
                         {.start = core::TimePoint(5ms), .interface_name = "can0"});
    loop_.run_until(core::TimePoint(50ms));

    EXPECT_TRUE(replay.finished());
    EXPECT_EQ(replay.report().sent, 3U);
    EXPECT_EQ(replay.report().skipped, 1U);
    ASSERT_EQ(received_.size(), 3U);
    EXPECT_GT(received_[0].time, core::TimePoint(5ms));
    EXPECT_EQ(received_[1].time - received_[0].time, 1ms);
    EXPECT_EQ(received_[2].time - received_[0].time, 11ms);
}

} // namespace
} // namespace eposp::can
