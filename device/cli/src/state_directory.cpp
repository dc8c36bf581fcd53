#include "state_directory.hpp"

#include <cstdlib>
#include <fmt/format.h>
#include <system_error>

namespace eposp::device::cli {
namespace {

std::optional<std::filesystem::path> absolute_variable(const char* name) {
    const char* value = std::getenv(name);
    if (value == nullptr || *value == '\0' || !std::filesystem::path(value).is_absolute()) {
        return std::nullopt;
    }
    return std::filesystem::path(value);
}

core::Result<std::filesystem::path> default_state_home() {
    if (auto state = absolute_variable("XDG_STATE_HOME")) {
        return *state;
    }
    if (auto home = absolute_variable("HOME")) {
        return *home / ".local" / "state";
    }
    return core::Error{"neither XDG_STATE_HOME nor HOME is set: give --state-dir DIR"};
}

constexpr std::string_view kParameterFileName = "parameters.bin";
constexpr std::string_view kProgramFileName = "program.epx";
constexpr std::string_view kRetainFileName = "retain.bin";

core::Result<std::filesystem::path> state_directory(const std::optional<std::string>& state_dir,
                                                    std::string_view device) {
    std::filesystem::path directory;
    if (state_dir) {
        directory = *state_dir;
    } else {
        auto home = default_state_home();
        if (!home) {
            return core::Error{home.error()};
        }
        directory = *home / "eposp" / device;
    }
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory)) {
        return core::Error{fmt::format("state directory {}: {}", directory.string(),
                                       error ? error.message() : "not a directory")};
    }
    return directory;
}

core::Result<std::string> state_file(const std::optional<std::string>& state_dir,
                                     std::string_view device, std::string_view name) {
    auto directory = state_directory(state_dir, device);
    if (!directory) {
        return core::Error{directory.error()};
    }
    return (*directory / name).string();
}

} // namespace

core::Result<std::string> stored_parameters_file(const std::optional<std::string>& state_dir,
                                                 std::string_view device) {
    return state_file(state_dir, device, kParameterFileName);
}

core::Result<std::string> stored_program_file(const std::optional<std::string>& state_dir,
                                              std::string_view device) {
    return state_file(state_dir, device, kProgramFileName);
}

core::Result<std::string> stored_retain_file(const std::optional<std::string>& state_dir,
                                             std::string_view device) {
    return state_file(state_dir, device, kRetainFileName);
}

void add_state_dir_option(CLI::App& command, std::optional<std::string>& state_dir,
                          std::string_view device) {
    command.add_option(
        "--state-dir", state_dir,
        fmt::format("Directory of the non-volatile memory (0x1010 store, 0x1011 restore, LSS store "
                    "configuration); default $XDG_STATE_HOME/eposp/{0} or "
                    "~/.local/state/eposp/{0}",
                    device));
}

} // namespace eposp::device::cli
