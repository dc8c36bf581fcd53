#include "options.hpp"

#include <cstdio>
#include <fmt/format.h>

namespace eposp::device::cli {

int report_user_error(std::string_view command, std::string_view message) {
    fmt::print(stderr, "eposp {}: error: {}\n", command, message);
    return 1;
}

CLI::Option* add_duration_option(CLI::App& command, const std::string& name,
                                 std::optional<core::Duration>& target,
                                 const std::string& description) {
    return command
        .add_option_function<std::string>(
            name,
            [&target](const std::string& text) {
                target = core::parse_duration(text);
                if (!target) {
                    throw CLI::ValidationError(
                        "--for", "'" + text + "' is not a duration (examples: 10s, 250ms, 2m)");
                }
            },
            description)
        ->type_name("DURATION");
}

CLI::Option* add_engine_option(CLI::App& command, vm::Engine& target) {
    return command
        .add_option_function<std::string>(
            "--engine",
            [&target](const std::string& name) {
                target = name == "interpreter" ? vm::Engine::Interpreter : vm::Engine::Compiled;
            },
            "What runs the program: compiled (machine code where the build can) or interpreter")
        ->check(CLI::IsMember({"compiled", "interpreter"}))
        ->default_str(target == vm::Engine::Compiled ? "compiled" : "interpreter");
}

} // namespace eposp::device::cli
