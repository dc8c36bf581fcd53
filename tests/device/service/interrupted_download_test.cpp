#include "../compile_program.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/service/commands.hpp"
#include "eposp/service/v1_host_link.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "eposp/test/test_directory.hpp"
#include "eposp/vm/image_format.hpp"
#include "memory_link_pair.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <random>

// A program download over a service link that the host drops at a random byte, 100 times on
// each protocol: the EPOS P keeps the old program or takes the new one whole, in memory and in its
// program file, and serves the next host (issue 14; docs/service-interface.md, "Program
// download and program control").

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using service::test::MemoryLink;

constexpr int kTrials = 100; // per protocol: 200 in all

constexpr const char* kOld = R"(
    PROGRAM Main VAR old_counter : DINT; END_VAR old_counter := old_counter + 1; END_PROGRAM)";
// Longer than the old one, so that the download takes many segments.
constexpr const char* kNew = R"(
    PROGRAM Main
    VAR a, b, c, d : ARRAY[0..31] OF DINT; i : INT; total : LINT; END_VAR
    FOR i := 0 TO 31 DO a[i] := a[i] + i; b[i] := a[i] * 2; c[i] := b[i] - a[i]; END_FOR;
    FOR i := 0 TO 31 DO d[i] := c[i] MOD 7; total := total + d[i]; END_FOR;
    END_PROGRAM)";

canopen::Bytes image_of(const char* source) {
    return vm::write_image(compile_program(source));
}

/// The requests of a download by segments of 63 bytes.
std::vector<service::Frame> download_requests(const canopen::Bytes& image) {
    std::vector<service::Frame> requests;
    const service::ObjectAddress program{std::nullopt, 0, kProgramDataIndex, 1};
    requests.push_back(service::encode_request(
        service::InitiateSegmentedWrite{program, static_cast<std::uint32_t>(image.size())}));
    bool toggle = false;
    for (std::size_t sent = 0; sent < image.size(); toggle = !toggle) {
        const std::size_t length = std::min<std::size_t>(63, image.size() - sent);
        service::SegmentWrite segment;
        segment.control = {static_cast<std::uint8_t>(length), toggle, sent + length < image.size()};
        segment.data.assign(image.begin() + static_cast<std::ptrdiff_t>(sent),
                            image.begin() + static_cast<std::ptrdiff_t>(sent + length));
        requests.push_back(service::encode_request(segment));
        sent += length;
    }
    return requests;
}

/// A host that runs a download over a memory link to the port, one request after the answer
/// of the one before, and drops the link once it has sent `budget` bytes (mid-frame, mid-
/// handshake, wherever that falls).
class DroppingHost {
public:
    DroppingHost(EposP& device, ServiceProtocol protocol, std::uint64_t budget)
        : device_(device), protocol_(protocol), budget_(budget) {
        auto [host, device_side] = MemoryLink::pair(device.loop());
        link_ = std::move(host);
        device_end_ = device_side.get();
        port_ = std::make_unique<ServicePort>(device, std::move(device_side), protocol);
        v1_.emplace([this](std::span<const std::uint8_t> bytes) { write(bytes); },
                    [this](const service::V1Completion& done) {
                        answered_ = done.outcome == service::V1Outcome::Answered;
                    });
        v2_.emplace([this](const service::Frame&) { answered_ = true; });
        link_->on_receive([this](std::span<const std::uint8_t> bytes) {
            if (protocol_ == ServiceProtocol::Rs232) {
                v1_->receive(bytes);
            } else {
                v2_->receive(bytes);
            }
        });
    }

    /// Runs the requests until the budget is spent; true when every one was answered.
    bool run(const std::vector<service::Frame>& requests) {
        for (const service::Frame& request : requests) {
            answered_ = false;
            if (protocol_ == ServiceProtocol::Rs232) {
                v1_->request(request);
            } else {
                write(service::encode_v2(request));
            }
            for (int ms = 0; ms < 20 && !answered_ && !dropped_; ++ms) {
                device_.loop().run_for(1ms);
            }
            if (dropped_) {
                device_end_->close_from_peer(); // the device sees the host hang up
                device_.loop().run_for(10ms);
                return false;
            }
            if (!answered_) {
                ADD_FAILURE() << "a request was not answered";
                return false;
            }
        }
        return true;
    }

private:
    void write(std::span<const std::uint8_t> bytes) {
        if (dropped_) {
            return;
        }
        const std::size_t allowed =
            static_cast<std::size_t>(std::min<std::uint64_t>(budget_, bytes.size()));
        link_->send(bytes.first(allowed));
        budget_ -= allowed;
        dropped_ = allowed < bytes.size() || budget_ == 0;
    }

    EposP& device_;
    ServiceProtocol protocol_;
    std::uint64_t budget_;
    bool dropped_ = false;
    bool answered_ = false;
    std::unique_ptr<MemoryLink> link_;
    MemoryLink* device_end_ = nullptr;
    std::unique_ptr<ServicePort> port_;
    std::optional<service::V1HostLink> v1_;
    std::optional<service::V2Decoder> v2_;
};

/// How many bytes a host sends for the whole download: on v1 the opcode, Len-1, the data, the
/// CRC and its two 'O' to the answer; on v2 the stuffed frames.
std::uint64_t bytes_of_download(ServiceProtocol protocol,
                                const std::vector<service::Frame>& requests) {
    std::uint64_t total = 0;
    for (const auto& request : requests) {
        total += protocol == ServiceProtocol::Usb ? service::encode_v2(request).size()
                                                  : 1 + 1 + request.data.size() + 2 + 2;
    }
    return total;
}

canopen::Bytes stored_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class InterruptedDownload : public testing::TestWithParam<ServiceProtocol> {};

TEST_P(InterruptedDownload, NeverLeavesABrokenProgram) {
    const canopen::Bytes old_image = image_of(kOld);
    const canopen::Bytes new_image = image_of(kNew);
    const auto requests = download_requests(new_image);
    ASSERT_GT(requests.size(), 20u);
    EposPConfig config;
    config.program_file = test::test_file("program.epx");
    std::mt19937_64 random(1400 + static_cast<int>(GetParam()));
    int kept_old = 0;
    int took_new = 0;
    int reported = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        EposP device(config);
        ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, old_image),
                  canopen::AbortCode::None);
        const std::uint64_t total = bytes_of_download(GetParam(), requests);
        const std::uint64_t budget = std::uniform_int_distribution<std::uint64_t>(1, total)(random);
        DroppingHost host(device, GetParam(), budget);
        const bool finished = host.run(requests);

        canopen::Bytes loaded;
        ASSERT_EQ(device.objects().read(kProgramDataIndex, 1, loaded), canopen::AbortCode::None);
        ASSERT_TRUE(loaded == old_image || loaded == new_image)
            << "trial " << trial << ": dropped after " << budget << " of " << total << " bytes";
        EXPECT_EQ(stored_file(config.program_file), loaded) << "trial " << trial;
        // An interruption after the transfer began says so: 0x1F57 "data format error" and
        // 0x6186 in the history (before it began, nothing happened to say anything of).
        const auto flash_status = device.objects().get_as<std::uint32_t>(kFlashStatusIndex, 1);
        if (loaded == new_image) {
            EXPECT_EQ(flash_status, 0u) << "trial " << trial;
        } else if (flash_status != 0) {
            EXPECT_EQ(flash_status, 3u << 1) << "trial " << trial;
            EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x6186u);
            ++reported;
        }
        (loaded == old_image ? kept_old : took_new)++;
        if (finished) {
            EXPECT_EQ(loaded, new_image);
        }

        // The next host downloads the new program whole.
        DroppingHost next(device, GetParam(), std::numeric_limits<std::uint64_t>::max());
        ASSERT_TRUE(next.run(requests)) << "trial " << trial;
        canopen::Bytes now;
        device.objects().read(kProgramDataIndex, 1, now);
        EXPECT_EQ(now, new_image);
    }
    EXPECT_GT(kept_old, kTrials / 2) << "most drops fall before the last segment";
    EXPECT_GT(reported, kTrials / 2) << "and after the transfer began";
    RecordProperty("kept_old", kept_old);
    RecordProperty("took_new", took_new);
}

INSTANTIATE_TEST_SUITE_P(Protocols, InterruptedDownload,
                         testing::Values(ServiceProtocol::Rs232, ServiceProtocol::Usb),
                         [](const testing::TestParamInfo<ServiceProtocol>& param) {
                             return param.param == ServiceProtocol::Rs232 ? "Rs232" : "Usb";
                         });

} // namespace
} // namespace eposp::device
