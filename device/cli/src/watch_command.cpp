// `eposp watch --port PATH|tcp:ADDR Main.counter … [--write PATH=VALUE] [--force PATH=VALUE]
// [--unforce PATH] [--every 100ms] [--for D]`: the variables of the program an EPOS P runs, by
// path, over its service interface, through eposp's variable access object 0x5F60
// (docs/service-interface.md, "Variable access"): sub 1 names the variable, sub 2 reads or
// writes its value as an IEC literal, sub 3 forces it, sub 4 releases the force.
#include "commands.hpp"
#include "eposp/core/time.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "exit_codes.hpp"
#include "options.hpp"
#include "service_connection.hpp"
#include "terminal_text.hpp"

#include <chrono>
#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

using namespace std::chrono_literals;

constexpr std::string_view kWatchCommand = "watch";
constexpr std::uint8_t kPathSub = 1;
constexpr std::uint8_t kValueSub = 2;
constexpr std::uint8_t kForceSub = 3;
constexpr std::uint8_t kUnforceSub = 4;

struct WatchOptions {
    ServiceClientOptions link;
    ObjectTargetOptions target;
    std::vector<std::string> paths;
    std::vector<std::string> writes;
    std::vector<std::string> forces;
    std::vector<std::string> unforces;
    std::optional<core::Duration> every;
    std::optional<core::Duration> duration;
};

using Bytes = std::vector<std::uint8_t>;

Bytes bytes_of(std::string_view text) {
    return Bytes(text.begin(), text.end());
}
std::string text_of(const Bytes& bytes) {
    return std::string(bytes.begin(), bytes.end());
}

class Watch {
public:
    Watch(ServiceConnection& connection, const ObjectTargetOptions& target)
        : connection_(connection), target_(target) {}

    /// Names `path` in sub 1, then does `access` on it; the error names the variable.
    template <typename Access>
    std::optional<std::string> on_variable(const std::string& path, std::string_view doing,
                                           Access access) {
        const auto named = connection_.write_segmented(at(kPathSub), bytes_of(path));
        if (!named) {
            return fmt::format("{}: {}", terminal_text(path), explain(named.error()));
        }
        const auto error = access();
        if (error) {
            return fmt::format("{} {}: {}", doing, terminal_text(path), explain(*error));
        }
        return std::nullopt;
    }

    std::optional<service::ClientError> write_literal(std::uint8_t sub, const std::string& value) {
        const auto written = connection_.write_segmented(at(sub), bytes_of(value));
        return written ? std::nullopt : std::optional(written.error());
    }

    std::optional<service::ClientError> unforce() {
        const auto written = connection_.write_object(at(kUnforceSub), {1});
        return written ? std::nullopt : std::optional(written.error());
    }

    service::ClientResult<Bytes> read_value(const std::string& path) {
        const auto named = connection_.write_segmented(at(kPathSub), bytes_of(path));
        if (!named) {
            return named.error();
        }
        return connection_.read_segmented(at(kValueSub));
    }

    // The variable access object's abort codes in the words of `watch`.
    static std::string explain(const service::ClientError& error) {
        if (error.kind != service::ClientError::Kind::Refused) {
            return error.message;
        }
        switch (error.code) {
        case 0x06090030:
            return error.message + " (no such variable, or a value not of its type)";
        case 0x08000022:
            return error.message + " (the device has no program)";
        case 0x06010002:
            return error.message + " (the variable is read-only)";
        case 0x06020000:
            return error.message + " (the device has no variable access object 0x5F60)";
        default:
            return error.message;
        }
    }

private:
    service::ObjectAddress at(std::uint8_t sub) const {
        return object_address(target_, kVariableAccessIndex, sub);
    }

    ServiceConnection& connection_;
    const ObjectTargetOptions& target_;
};

// "PATH=VALUE" split at its first '='.
std::optional<std::pair<std::string, std::string>> assignment(const std::string& text) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
        return std::nullopt;
    }
    return std::pair{text.substr(0, equals), text.substr(equals + 1)};
}

int watch(const WatchOptions& options) {
    for (const auto& list : {options.writes, options.forces}) {
        for (const std::string& text : list) {
            if (!assignment(text)) {
                return report_user_error(
                    kWatchCommand, fmt::format("'{}' is not PATH=VALUE", terminal_text(text)));
            }
        }
    }
    if (options.paths.empty() && options.writes.empty() && options.forces.empty() &&
        options.unforces.empty()) {
        return report_user_error(kWatchCommand, "name a variable to watch (e.g. Main.counter), or "
                                           "--write, --force or --unforce");
    }
    auto connection = ServiceConnection::open(options.link);
    if (!connection) {
        return report_user_error(kWatchCommand, connection.error());
    }
    Watch watch(**connection, options.target);
    const auto failed = [&](const std::string& message) {
        return (*connection)->interrupted() ? kExitInterrupted
                                            : report_user_error(kWatchCommand, message);
    };
    for (const std::string& text : options.writes) {
        // Named, not a structured binding: clang 14 cannot capture those in a lambda.
        const auto assigned = *assignment(text);
        const std::string& path = assigned.first;
        const std::string& value = assigned.second;
        if (auto error = watch.on_variable(path, "writing",
                                           [&] { return watch.write_literal(kValueSub, value); })) {
            return failed(*error);
        }
        fmt::print("{} := {}\n", terminal_text(path), terminal_text(value));
    }
    for (const std::string& text : options.forces) {
        // Named, not a structured binding: clang 14 cannot capture those in a lambda.
        const auto assigned = *assignment(text);
        const std::string& path = assigned.first;
        const std::string& value = assigned.second;
        if (auto error = watch.on_variable(path, "forcing",
                                           [&] { return watch.write_literal(kForceSub, value); })) {
            return failed(*error);
        }
        fmt::print("{} forced to {}\n", terminal_text(path), terminal_text(value));
    }
    for (const std::string& path : options.unforces) {
        if (auto error = watch.on_variable(path, "releasing", [&] { return watch.unforce(); })) {
            return failed(*error);
        }
        fmt::print("{} released\n", terminal_text(path));
    }
    if (options.paths.empty()) {
        return kExitSuccess;
    }

    // One sample without --every or --for; otherwise one each period until --for or Ctrl-C.
    const bool repeat = options.every || options.duration;
    const core::Duration period = options.every.value_or(100ms);
    const core::TimePoint begin = (*connection)->loop().now();
    // Ctrl-C is how an endless watch ends: a success; it cuts a watch --for short: 130.
    const int interrupted = options.duration ? kExitInterrupted : kExitSuccess;
    for (core::TimePoint due = begin;; due += period) {
        std::string line =
            fmt::format("{:8.3f} s",
                        std::chrono::duration<double>((*connection)->loop().now() - begin).count());
        for (const std::string& path : options.paths) {
            const auto value = watch.read_value(path);
            if (!value) {
                return (*connection)->interrupted()
                           ? interrupted
                           : report_user_error(kWatchCommand,
                                               fmt::format("{}: {}", terminal_text(path),
                                                           Watch::explain(value.error())));
            }
            line += fmt::format("  {}={}", terminal_text(path), terminal_text(text_of(*value)));
        }
        fmt::print("{}\n", line);
        std::fflush(stdout);
        const core::TimePoint next = due + period;
        if (!repeat || (options.duration && next - begin > *options.duration)) {
            return kExitSuccess;
        }
        if (!(*connection)->pause(std::max(next - (*connection)->loop().now(), core::Duration{}))) {
            return interrupted;
        }
    }
}

} // namespace

void add_watch_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<WatchOptions>();
    CLI::App* command = app.add_subcommand(
        "watch", "Read, write and force the variables of the program an EPOS P runs, by path");
    command->add_option("paths", options->paths, "The variables to show, e.g. Main.counter");
    add_service_client_options(*command, options->link);
    add_object_target_options(*command, options->target);
    // One variable per option, so that the PATHs to show may follow it.
    command->add_option("--write", options->writes, "Set a variable once: PATH=VALUE (IEC literal)")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);
    command->add_option("--force", options->forces, "Force a variable: PATH=VALUE")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);
    command->add_option("--unforce", options->unforces, "Release a forced variable")
        ->type_name("PATH")
        ->allow_extra_args(false);
    add_duration_option(*command, "--every", options->every,
                        "Show the variables every DURATION (default 100ms once --for is given)");
    add_duration_option(*command, "--for", options->duration,
                        "Keep showing them for DURATION (otherwise until Ctrl-C with --every, "
                        "or once)");
    command->callback([options, &exit_code] { exit_code = watch(*options); });
}

} // namespace eposp::device::cli
