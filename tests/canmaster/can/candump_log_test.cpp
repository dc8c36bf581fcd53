#include "eposp/can/candump_log_reader.hpp"
#include "eposp/can/candump_log_writer.hpp"
#include "eposp/can/trace_clock.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::can {
namespace {

using namespace std::chrono_literals;
using testing_support::TempFile;

TEST(TraceClock, VirtualRunStartsAtZero) {
    EXPECT_EQ(TraceClock().to_trace(core::TimePoint(1500us)), TraceTime(1500us));
}

TEST(TraceClock, AddsTheEpochOffset) {
    const TraceClock clock(1436509052s);
    EXPECT_EQ(clock.to_trace(core::TimePoint(249713us)), TraceTime(1436509052s + 249713us));
}

TEST(TraceClock, AlignedClockReadsTheWallTimeAtTheGivenLoopTime) {
    const auto clock = TraceClock::aligned(core::TimePoint(2s), TraceTime(1436509052s));
    EXPECT_EQ(clock.to_trace(core::TimePoint(2s)), TraceTime(1436509052s));
    EXPECT_EQ(clock.to_trace(core::TimePoint(3s)), TraceTime(1436509053s));
}

TEST(CandumpLogWriter, WritesOneFlushedLinePerFrame) {
    std::ostringstream out;
    CandumpLogWriter writer{TraceOutput(out)};
    writer.record(TraceTime(1ms), "can0", Frame::data_frame(0x000, {0x01, 0x00}));
    EXPECT_EQ(out.str(), "(0000000000.001000) can0 000#0100\n");
    writer.record(TraceTime(2ms), "can1", Frame::remote_frame(0x701, 1));
    EXPECT_EQ(out.str(), "(0000000000.001000) can0 000#0100\n"
                         "(0000000000.002000) can1 701#R1\n");
    EXPECT_TRUE(writer.good());
}

TEST(CandumpLogWriter, FileIsCompleteBeforeTheWriterCloses) {
    const TempFile file(".log");
    auto output = TraceOutput::create(file.path());
    ASSERT_TRUE(output) << output.error();
    CandumpLogWriter writer(std::move(*output));
    writer.record(TraceTime(1s), "can0", Frame::data_frame(0x080, {}));
    EXPECT_EQ(file.contents(), "(0000000001.000000) can0 080#\n");
}

TEST(TraceOutput, CreatingAFileInAMissingDirectoryFailsWithReason) {
    const auto output = TraceOutput::create("/nonexistent-eposp-dir/bus.log");
    ASSERT_FALSE(output);
    EXPECT_EQ(output.error(),
              "cannot create /nonexistent-eposp-dir/bus.log: No such file or directory");
}

TEST(CandumpLogReader, ReadsEveryLineInOrder) {
    std::istringstream in("(1436509052.249713) can0 123#DEADBEEF\n"
                          "(1436509052.250000) can1 12345678#R2\n"
                          "(1436509052.250100) can0 20000004#0004000000000000\n");
    const auto records = read_candump_log(in, "bus.log");
    ASSERT_TRUE(records) << records.error();
    ASSERT_EQ(records->size(), 3U);
    EXPECT_EQ((*records)[0].frame, Frame::data_frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
    EXPECT_EQ((*records)[1].interface_name, "can1");
    EXPECT_EQ((*records)[1].frame, Frame::remote_frame(0x12345678, 2, true));
    EXPECT_EQ((*records)[2].time, TraceTime(1436509052s + 250100us));
    EXPECT_TRUE((*records)[2].frame.error);
}

TEST(CandumpLogReader, SkipsLinesThatAreNotFramesAsCanplayerDoes) {
    std::istringstream in("# recorded by hand\n"
                          "\n"
                          "(1.000000) can0 080#\n"
                          "DROPCOUNT: dropped 2 CAN frames on 'can0' socket (total drops 2)\n"
                          "(1.001000) can0 080#\n");
    const auto records = read_candump_log(in, "bus.log");
    ASSERT_TRUE(records) << records.error();
    EXPECT_EQ(records->size(), 2U);
}

TEST(CandumpLogReader, ErrorNamesSourceAndLine) {
    std::istringstream in("(1.000000) can0 080#\n"
                          "# comment\n"
                          "(1.001000) can0 080#0\n");
    const auto records = read_candump_log(in, "bus.log");
    ASSERT_FALSE(records);
    EXPECT_EQ(records.error(), "bus.log:3: data byte 1 has only one hex digit");
}

TEST(CandumpLogReader, EmptyLogHasNoRecords) {
    std::istringstream in("");
    const auto records = read_candump_log(in, "bus.log");
    ASSERT_TRUE(records) << records.error();
    EXPECT_TRUE(records->empty());
}

TEST(CandumpLogReader, FileErrorsNameTheFile) {
    const TempFile file(".log");
    {
        std::ofstream out(file.path());
        out << "(1.000000) can0 999#\n";
    }
    const auto records = read_candump_log_file(file.path());
    ASSERT_FALSE(records);
    EXPECT_EQ(records.error(),
              file.path().string() + ":1: standard identifier 0x999 is above 0x7FF");
}

TEST(CandumpLogReader, MissingFileIsAnError) {
    const auto records = read_candump_log_file("/nonexistent-eposp-dir/bus.log");
    ASSERT_FALSE(records);
    EXPECT_EQ(records.error(),
              "cannot open /nonexistent-eposp-dir/bus.log: No such file or directory");
}

TEST(CandumpLog, WrittenLogReadsBack) {
    std::stringstream log;
    CandumpLogWriter writer{TraceOutput(log)};
    const CandumpRecord written[] = {
        {TraceTime(10us), "can0", Frame::data_frame(0x601, {0x40, 0x00, 0x10, 0x00})},
        {TraceTime(20us), "can0", Frame::data_frame(0x1ABCDEF0, {}, true)},
        {TraceTime(30us), "can1", Frame::remote_frame(0x123, 8)},
    };
    for (const auto& record : written) {
        writer.record(record.time, record.interface_name, record.frame);
    }
    const auto read = read_candump_log(log, "log");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(*read, std::vector<CandumpRecord>(std::begin(written), std::end(written)));
}

} // namespace
} // namespace eposp::can
