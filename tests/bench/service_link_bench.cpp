// The service interface's figures of docs/performance.md, in virtual time (exact and the same on
// every machine): a 64 KiB segmented download and upload over the RS-232 link (v1, 115200 baud)
// and the USB link (v2, 1 Mbit/s), both directions of the line paced, as a ratio to the line-rate
// minimum (the bytes alone at 10 bits each); and the round trip of a ReadObject through the
// gateway to an EPOS2 on the CAN bus. Then how fast the simulation runs them on this machine.
//
//   build/tests/bench/eposp_bench_service_link

#include "../device/service/memory_link_pair.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/service/client.hpp"
#include "eposp/service/paced_link.hpp"

#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <optional>

namespace {

using namespace eposp;
using namespace std::chrono_literals;

constexpr std::uint16_t kDomain = 0x3F00; // a DOMAIN added for the measurement
constexpr std::size_t kImageBytes = 64 * 1024;

struct Line {
    const char* name;
    service::Protocol protocol;
    device::ServiceProtocol port;
    service::LinkPacing pacing;
};

struct Figures {
    double download_s = 0;
    double upload_s = 0;
    double gateway_ms = 0;
    double wall_s = 0;
};

template <typename T, typename Start>
service::ClientResult<T> wait(device::EposP& device, Start start) {
    std::optional<service::ClientResult<T>> result;
    start([&](const service::ClientResult<T>& done) {
        result.emplace(done);
        device.loop().stop(); // the loop's time is then the completion's
    });
    while (!result) {
        device.loop().run_for(60s);
    }
    return *result;
}

double seconds(core::Duration d) {
    return std::chrono::duration<double>(d).count();
}

Figures measure(const Line& line) {
    const auto wall_start = std::chrono::steady_clock::now();
    device::EposP device;
    auto network = device::parse_network_file("slaves:\n  - {node: 2, kind: epos2}\n", "net.yaml");
    device.add_network(*network);
    device.boot_networks();
    device.loop().run_for(2s);
    device.objects()
        .add_variable(kDomain, "Measurement", canopen::DataType::Domain, canopen::Access::ReadWrite,
                      {})
        .max_length = 2 * kImageBytes;

    auto [host, device_side] = service::test::MemoryLink::pair(device.loop());
    auto paced = service::PacedLink::wrap(device.loop(), std::move(device_side), line.pacing);
    device::ServicePort port(device, std::move(*paced), line.port);
    service::ClientSettings settings;
    settings.protocol = line.protocol;
    settings.bits_per_second = line.pacing.bits_per_second;
    service::Client client(device.loop(), *host, settings);

    std::vector<std::uint8_t> image(kImageBytes);
    for (std::size_t i = 0; i < image.size(); ++i) {
        image[i] = static_cast<std::uint8_t>(i * 131 + (i >> 8)); // 0x90 bytes included
    }
    const service::ObjectAddress domain{std::nullopt, 0, kDomain, 0};
    Figures figures;
    core::TimePoint start = device.loop().now();
    auto written = wait<service::Done>(
        device, [&](auto done) { client.write_segmented(domain, image, done); });
    figures.download_s = written ? seconds(device.loop().now() - start) : -1;

    start = device.loop().now();
    auto read = wait<std::vector<std::uint8_t>>(
        device, [&](auto done) { client.read_segmented(domain, done); });
    figures.upload_s = read && *read == image ? seconds(device.loop().now() - start) : -1;

    constexpr int kRoundTrips = 100;
    start = device.loop().now();
    for (int i = 0; i < kRoundTrips; ++i) {
        auto type = wait<std::array<std::uint8_t, 4>>(device, [&](auto done) {
            client.read_object({std::nullopt, 2, 0x1000, 0}, done);
        });
        if (!type) {
            figures.gateway_ms = -1;
            break;
        }
    }
    if (figures.gateway_ms == 0) {
        figures.gateway_ms = 1000 * seconds(device.loop().now() - start) / kRoundTrips;
    }
    figures.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return figures;
}

} // namespace

int main() {
    const Line lines[] = {
        {"RS-232 (v1), 115200 baud", service::Protocol::V1, device::ServiceProtocol::Rs232,
         service::LinkPacing::rs232()},
        {"USB (v2), 1 Mbit/s", service::Protocol::V2, device::ServiceProtocol::Usb,
         service::LinkPacing::usb()},
    };
    fmt::print("| link | line minimum, 64 KiB | download | ratio | upload | ratio | gateway "
               "ReadObject round trip | wall time of this run |\n");
    fmt::print("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (const Line& line : lines) {
        const Figures figures = measure(line);
        const double minimum = seconds(line.pacing.time_for(kImageBytes));
        fmt::print("| {} | {:.2f} s | {:.2f} s | {:.2f}x | {:.2f} s | {:.2f}x | {:.2f} ms | "
                   "{:.2f} s |\n",
                   line.name, minimum, figures.download_s, figures.download_s / minimum,
                   figures.upload_s, figures.upload_s / minimum, figures.gateway_ms,
                   figures.wall_s);
    }
    return 0;
}
