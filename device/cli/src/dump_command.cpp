// `eposp dump app.epx|FILES…`: the program image as text, the way a disassembler shows a binary:
// sizes, tasks, POUs, symbols, I/O bindings, retain ranges, imports, then the code.
#include "commands.hpp"
#include "eposp/vm/disassembler.hpp"
#include "options.hpp"
#include "program_input.hpp"

#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {

void add_dump_command(CLI::App& app, int& exit_code) {
    auto paths = std::make_shared<std::vector<std::string>>();
    CLI::App* command =
        app.add_subcommand("dump", "Disassemble a program image (or the image of ST files)");
    command->add_option("files", *paths, "One .epx image, or the .st files of one program")
        ->required();
    command->callback([paths, &exit_code] {
        const auto image = program_image(*paths);
        if (!image) {
            exit_code = report_user_error("dump", image.error());
            return;
        }
        fmt::print("{}", vm::disassemble(*image));
    });
}

} // namespace eposp::device::cli
