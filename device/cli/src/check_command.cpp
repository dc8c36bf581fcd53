// `eposp check FILES…`: checks the Structured Text files of one program (parse, names, types,
// checks; no code generation, so no image) and prints the diagnostics like a compiler. Quiet
// when all is well.
#include "commands.hpp"
#include "options.hpp"
#include "program_input.hpp"

#include <memory>
#include <string>
#include <vector>

namespace eposp::device::cli {

void add_check_command(CLI::App& app, int& exit_code) {
    auto paths = std::make_shared<std::vector<std::string>>();
    auto format = std::make_shared<ErrorFormat>(ErrorFormat::Human);
    CLI::App* command =
        app.add_subcommand("check", "Check the Structured Text files of one program for errors");
    command->add_option("files", *paths, "The .st files of the program, checked together")
        ->required();
    add_error_format_option(*command, *format);
    command->callback([paths, format, &exit_code] {
        const auto checked = check_sources(*paths, *format);
        exit_code = checked ? 0 : report_user_error("check", checked.error());
    });
}

} // namespace eposp::device::cli
