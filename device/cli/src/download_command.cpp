// `eposp download --port PATH|tcp:ADDR app.epx|FILES… [--start cold|warm|hot|none]`: loads a
// program into an EPOS P over its service interface as CiA 302-3 does it
// (docs/service-interface.md, "Clients"): a running program is stopped (0x1F51), the image is
// written to 0x1F50 sub 1 by segmented transfer, then started by 0x5F51. A refused download
// says why by the flash status 0x1F57.
#include "commands.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/image_format.hpp"
#include "exit_codes.hpp"
#include "options.hpp"
#include "program_input.hpp"
#include "service_connection.hpp"

#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <unistd.h>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kDownloadCommand = "download";

struct DownloadOptions {
    ServiceClientOptions link;
    ObjectTargetOptions target;
    std::vector<std::string> files;
    std::string start = "cold";
};

// CiA 302-3 0x1F57 bits 1..7, as the EPOS P sets them (program_store.hpp FlashStatus).
std::string_view flash_status_text(std::uint32_t status) {
    switch (status >> 1 & 0x7F) {
    case 0:
        return "no error";
    case 1:
        return "no valid program";
    case 2:
        return "data format unknown: not an EPOS P program image of this version";
    case 3:
        return "data format error: the image is damaged or truncated";
    case 5:
        return "flash write error: the program memory could not be written";
    case 7:
        return "flash secured: the program runs";
    case 64:
        return "incompatible: a sound image this controller cannot run";
    default:
        return "unspecified error";
    }
}

// A bar on stderr while it is a terminal: nothing for scripts and logs.
class ProgressBar {
public:
    ProgressBar() : shown_(::isatty(STDERR_FILENO) == 1) {}
    ~ProgressBar() {
        if (drawn_) {
            fmt::print(stderr, "\n");
        }
    }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void update(std::size_t done, std::size_t total) {
        if (!shown_ || total == 0) {
            return;
        }
        constexpr std::size_t kWidth = 40;
        const std::size_t filled = done * kWidth / total;
        fmt::print(stderr, "\r[{}{}] {:3}% {}/{} bytes", std::string(filled, '#'),
                   std::string(kWidth - filled, '.'), done * 100 / total, done, total);
        std::fflush(stderr);
        drawn_ = true;
    }

private:
    bool shown_;
    bool drawn_ = false;
};

std::optional<ProgramControl> start_control(const std::string& start) {
    if (start == "cold") {
        return ProgramControl::Coldstart;
    }
    if (start == "warm") {
        return ProgramControl::Warmstart;
    }
    if (start == "hot") {
        return ProgramControl::Hotstart;
    }
    return std::nullopt;
}

class Download {
public:
    Download(ServiceConnection& connection, const ObjectTargetOptions& target)
        : connection_(connection), target_(target) {}

    int fail(const service::ClientError& error, std::string_view doing) {
        if (connection_.interrupted()) {
            return kExitInterrupted;
        }
        return report_user_error(kDownloadCommand, fmt::format("{}: {}", doing, error.message));
    }

    int run(const DownloadOptions& options, std::vector<std::uint8_t> image) {
        // The EPOS P refuses a download while its program runs (flash secured): stop it first.
        const auto state = connection_.read_object(at(kCia302ProgramControlIndex, 1));
        if (!state) {
            return fail(state.error(), "reading the program state 0x1F51");
        }
        if ((*state)[0] == static_cast<std::uint8_t>(ProgramStatus::Started)) {
            const auto stopped =
                connection_.write_object(at(kCia302ProgramControlIndex, 1),
                                         {static_cast<std::uint8_t>(ProgramControlCommand::Stop)});
            if (!stopped) {
                return fail(stopped.error(), "stopping the running program");
            }
            fmt::print("stopped the running program\n");
        }

        const std::size_t size = image.size();
        const core::TimePoint began = connection_.loop().now();
        service::ClientResult<service::Done> written = service::Done{};
        {
            ProgressBar bar;
            written = connection_.write_segmented(
                at(kProgramDataIndex, 1), std::move(image),
                [&bar](std::size_t done, std::size_t total) { bar.update(done, total); });
        }
        if (!written) {
            return refused(written.error());
        }
        const auto elapsed = std::chrono::duration<double>(connection_.loop().now() - began);
        fmt::print("downloaded {} bytes in {:.2f} s ({:.0f} bytes/s)\n", size, elapsed.count(),
                   static_cast<double>(size) / std::max(elapsed.count(), 1e-6));

        const auto control = start_control(options.start);
        if (!control) {
            return kExitSuccess;
        }
        const auto started =
            connection_.write_object(at(kProgramControlIndex, 0),
                                     canopen::encode_array(static_cast<std::uint32_t>(*control)));
        if (!started) {
            return fail(started.error(), fmt::format("starting the program ({})", options.start));
        }
        fmt::print("started ({} start)\n", options.start);
        return kExitSuccess;
    }

private:
    // The device's answer names the abort code; its flash status says why.
    int refused(const service::ClientError& error) {
        if (error.kind != service::ClientError::Kind::Refused) {
            return fail(error, "writing the program to 0x1F50");
        }
        const auto status = connection_.read_object(at(kFlashStatusIndex, 1));
        const std::uint32_t flash = status ? canopen::decode<std::uint32_t>(*status) : 0;
        const std::string why =
            status
                ? fmt::format("flash status 0x1F57 = 0x{:X}: {}", flash, flash_status_text(flash))
                : fmt::format("0x1F57 unreadable: {}", status.error().message);
        return report_user_error(
            kDownloadCommand, fmt::format("the device refused the program: {} ({})", error.message, why));
    }

    service::ObjectAddress at(std::uint16_t index, std::uint8_t sub_index) const {
        return object_address(target_, index, sub_index);
    }

    ServiceConnection& connection_;
    const ObjectTargetOptions& target_;
};

int download(const DownloadOptions& options) {
    const auto image = program_image(options.files);
    if (!image) {
        return report_user_error(kDownloadCommand, image.error());
    }
    auto connection = ServiceConnection::open(options.link);
    if (!connection) {
        return report_user_error(kDownloadCommand, connection.error());
    }
    return Download(**connection, options.target).run(options, vm::write_image(*image));
}

} // namespace

void add_download_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<DownloadOptions>();
    CLI::App* command = app.add_subcommand(
        "download", "Load a program into an EPOS P over its service interface and start it");
    command->add_option("files", options->files, "One .epx image, or the .st files of one program")
        ->required();
    add_service_client_options(*command, options->link);
    add_object_target_options(*command, options->target);
    command
        ->add_option("--start", options->start,
                     "How to start the program once loaded: cold, warm, hot, or none")
        ->capture_default_str()
        ->check(CLI::IsMember({"cold", "warm", "hot", "none"}));
    command->callback([options, &exit_code] { exit_code = download(*options); });
}

} // namespace eposp::device::cli
