// The USB link's framing (v2): encode_v2 and V2Decoder against the guide's vectors, round trips,
// byte stuffing and resynchronisation (docs/service-interface.md, "Links and framing").

#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "random_frame.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::service {
namespace {

using test::Bytes;
using test::bytes;

const Frame kReadStatusword{0x10, bytes({0x41, 0x60, 0x00, 0x01})};
const Bytes kReadStatuswordBytes =
    bytes({0x90, 0x02, 0x10, 0x02, 0x41, 0x60, 0x00, 0x01, 0x64, 0xCF});
const Frame kWriteTarget{0x11, bytes({0x7A, 0x60, 0x00, 0x01, 0x90, 0x00, 0x00, 0x00})};
const Bytes kWriteTargetBytes = bytes(
    {0x90, 0x02, 0x11, 0x04, 0x7A, 0x60, 0x00, 0x01, 0x90, 0x90, 0x00, 0x00, 0x00, 0xE6, 0xD2});
const Frame kAnswer{0x00, bytes({0, 0, 0, 0, 0x37, 0x06, 0, 0})};
const Bytes kAnswerBytes =
    bytes({0x90, 0x02, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x37, 0x06, 0x00, 0x00, 0x99, 0xCA});

// A decoder that records what it finds.
struct Recorder {
    std::vector<Frame> frames;
    std::vector<V2Error> errors;
    V2Decoder decoder{[this](const Frame& frame) { frames.push_back(frame); },
                      [this](V2Error error) {
                          errors.push_back(error);
                      }};
    void feed(const Bytes& data) { decoder.receive(data); }
};

Bytes concat(std::initializer_list<Bytes> parts) {
    Bytes out;
    for (const Bytes& part : parts) {
        out.insert(out.end(), part.begin(), part.end());
    }
    return out;
}

TEST(V2Framing, EncodesTheGuidesVectorsByteForByte) {
    EXPECT_EQ(encode_v2(kReadStatusword), kReadStatuswordBytes);
    EXPECT_EQ(encode_v2(kWriteTarget), kWriteTargetBytes);
    EXPECT_EQ(encode_v2(kAnswer), kAnswerBytes);
}

TEST(V2Framing, DecodesTheGuidesVectors) {
    Recorder recorder;
    recorder.feed(concat({kReadStatuswordBytes, kWriteTargetBytes, kAnswerBytes}));
    EXPECT_EQ(recorder.frames, (std::vector<Frame>{kReadStatusword, kWriteTarget, kAnswer}));
    EXPECT_TRUE(recorder.errors.empty());
    EXPECT_FALSE(recorder.decoder.mid_frame());
}

TEST(V2Framing, DecodesAFrameFedOneByteAtATime) {
    Recorder recorder;
    for (std::size_t i = 0; i < kWriteTargetBytes.size(); ++i) {
        EXPECT_TRUE(recorder.frames.empty());
        recorder.feed(Bytes{kWriteTargetBytes[i]});
        EXPECT_EQ(recorder.decoder.mid_frame(), i + 1 < kWriteTargetBytes.size()) << i;
    }
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kWriteTarget});
}

TEST(V2Framing, StuffsEvery0x90AfterTheStartIncludingOpcodeLenAndCrc) {
    // 72 words: Len is 0x48; opcode 0x90; data all 0x90.
    const Frame frame{0x90, Bytes(2 * 72, 0x90)};
    const Bytes encoded = encode_v2(frame);
    ASSERT_EQ(encoded[2], 0x90);
    ASSERT_EQ(encoded[3], 0x90);
    std::size_t dles = 0;
    for (std::size_t i = 2; i < encoded.size(); ++i) {
        dles += encoded[i] == 0x90 ? 1 : 0;
    }
    EXPECT_EQ(dles % 2, 0u) << "every 0x90 after 0x90 0x02 comes in pairs";
    Recorder recorder;
    recorder.feed(encoded);
    EXPECT_EQ(recorder.frames, std::vector<Frame>{frame});
}

TEST(V2Framing, RandomFramesRoundTripThroughEncoderAndDecoder) {
    std::mt19937 random(4711);
    Recorder recorder;
    std::vector<Frame> sent;
    Bytes stream;
    for (int i = 0; i < 2000; ++i) {
        // Every fourth frame is mostly 0x90, so stuffing meets every field.
        sent.push_back(test::random_frame(random, 0, 255, i % 4 == 0 ? 0.7 : 0.0));
        const Bytes encoded = encode_v2(sent.back());
        stream.insert(stream.end(), encoded.begin(), encoded.end());
    }
    // Fed in random pieces, as a USB driver hands them over.
    std::uniform_int_distribution<std::size_t> piece(1, 700);
    for (std::size_t at = 0; at < stream.size();) {
        const std::size_t n = std::min(piece(random), stream.size() - at);
        recorder.decoder.receive(std::span(stream).subspan(at, n));
        at += n;
    }
    EXPECT_EQ(recorder.frames, sent);
    EXPECT_TRUE(recorder.errors.empty());
}

TEST(V2Framing, CarriesMaxSizeFramesOf255Words) {
    std::mt19937 random(255);
    const Frame frame = test::random_frame(random, 255, 255, 0.3);
    Recorder recorder;
    recorder.feed(encode_v2(frame));
    EXPECT_EQ(recorder.frames, std::vector<Frame>{frame});
    EXPECT_THROW(encode_v2(Frame{0x10, Bytes(2 * 256)}), std::invalid_argument);
    EXPECT_THROW(encode_v2(Frame{0x10, Bytes(5)}), std::invalid_argument);
}

TEST(V2Framing, CarriesAFrameWithoutData) {
    Recorder recorder;
    recorder.feed(encode_v2(Frame{0x42, {}}));
    EXPECT_EQ(recorder.frames, (std::vector<Frame>{Frame{0x42, {}}}));
}

TEST(V2Framing, DropsAFrameWithAWrongCrcAndDecodesTheNext) {
    Bytes corrupt = kReadStatuswordBytes;
    corrupt[5] ^= 0x01;
    Recorder recorder;
    recorder.feed(concat({corrupt, kAnswerBytes}));
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kAnswer});
    EXPECT_EQ(recorder.errors, std::vector<V2Error>{V2Error::CrcError});
    EXPECT_EQ(recorder.decoder.counters().crc_errors, 1u);
}

TEST(V2Framing, DropsAFrameWithAStuffingErrorAndResynchronisesOnTheNextStart) {
    // 0x90 0x41 inside a frame: neither a stuffed 0x90 nor a new start.
    const Bytes broken = bytes({0x90, 0x02, 0x10, 0x02, 0x90, 0x41, 0x60, 0x00, 0x01, 0x64, 0xCF});
    Recorder recorder;
    recorder.feed(concat({broken, kAnswerBytes}));
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kAnswer});
    EXPECT_EQ(recorder.errors, std::vector<V2Error>{V2Error::StuffingError});
    EXPECT_EQ(recorder.decoder.counters().stuffing_errors, 1u);
}

TEST(V2Framing, AStartInsideAFrameDropsItAndBeginsTheNewOne) {
    // The first frame is cut after its Len and two data bytes.
    const Bytes cut(kWriteTargetBytes.begin(), kWriteTargetBytes.begin() + 6);
    Recorder recorder;
    recorder.feed(concat({cut, kReadStatuswordBytes}));
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kReadStatusword});
    EXPECT_EQ(recorder.errors, std::vector<V2Error>{V2Error::Interrupted});
}

TEST(V2Framing, ALenLongerThanWhatFollowsBeforeTheNextStartDropsTheFrame) {
    // Len 0x20 words, but only one word and then the next frame.
    const Bytes too_long = bytes({0x90, 0x02, 0x10, 0x20, 0x41, 0x60});
    Recorder recorder;
    recorder.feed(concat({too_long, kAnswerBytes}));
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kAnswer});
    EXPECT_EQ(recorder.decoder.counters().interrupted, 1u);
}

TEST(V2Framing, SkipsGarbageBetweenFrames) {
    // Including a stuffed pair followed by 0x02, which is data of a frame whose start was
    // missed, not a start.
    const Bytes garbage = bytes({0x00, 0x02, 0x41, 0x90, 0x90, 0x02, 0x17, 0x90, 0x55});
    Recorder recorder;
    recorder.feed(concat({garbage, kReadStatuswordBytes, garbage, kAnswerBytes}));
    EXPECT_EQ(recorder.frames, (std::vector<Frame>{kReadStatusword, kAnswer}));
    EXPECT_TRUE(recorder.errors.empty());
    EXPECT_EQ(recorder.decoder.counters().skipped_bytes, 2 * garbage.size());
}

TEST(V2Framing, TimeoutMidFrameDropsItAndTheNextFrameDecodes) {
    Recorder recorder;
    recorder.feed(Bytes(kAnswerBytes.begin(), kAnswerBytes.begin() + 7));
    ASSERT_TRUE(recorder.decoder.mid_frame());
    recorder.decoder.on_timeout();
    EXPECT_FALSE(recorder.decoder.mid_frame());
    EXPECT_EQ(recorder.errors, std::vector<V2Error>{V2Error::Timeout});
    // The rest of the stalled frame arrives late: skipped, then the next frame decodes.
    recorder.feed(Bytes(kAnswerBytes.begin() + 7, kAnswerBytes.end()));
    recorder.feed(kReadStatuswordBytes);
    EXPECT_EQ(recorder.frames, std::vector<Frame>{kReadStatusword});
}

TEST(V2Framing, TimeoutOutsideAFrameChangesNothing) {
    Recorder recorder;
    recorder.decoder.on_timeout();
    EXPECT_TRUE(recorder.errors.empty());
    EXPECT_EQ(recorder.decoder.counters().timeouts, 0u);
}

} // namespace
} // namespace eposp::service
