// `eposp build FILES… [-o app.epx]`: compiles the Structured Text files of one program into a
// program image, the file `eposp run`, `eposp dump` and a download take.
#include "commands.hpp"
#include "eposp/core/durable_file.hpp"
#include "eposp/vm/image_format.hpp"
#include "file_checks.hpp"
#include "options.hpp"
#include "program_input.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kBuildCommand = "build";

struct BuildOptions {
    std::vector<std::string> paths;
    std::string output; // empty: the first file's name with .epx
    bool force = false;
    ErrorFormat error_format = ErrorFormat::Human;
};

int run_build(const BuildOptions& options) {
    const auto image = compile_sources(options.paths, options.error_format);
    if (!image) {
        return report_user_error(kBuildCommand, image.error());
    }
    const std::string output =
        options.output.empty()
            ? std::filesystem::path(options.paths.front()).replace_extension(".epx").string()
            : options.output;
    if (auto problem = output_file_problem({"-o", output, OutputKind::ProgramImage}, options.paths,
                                           options.force)) {
        return report_user_error(kBuildCommand, *problem);
    }
    const auto bytes = vm::write_image(*image);
    if (auto error = core::write_file_durably(output, bytes)) {
        return report_user_error(kBuildCommand, error->message);
    }
    const auto count = [](std::size_t n, std::string_view what) {
        return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
    };
    fmt::print("{}: {} bytes, {}, {}\n", output, bytes.size(), count(image->pous.size(), "POU"),
               count(image->tasks.size(), "task"));
    return 0;
}

} // namespace

void add_build_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<BuildOptions>();
    CLI::App* command =
        app.add_subcommand("build", "Compile the Structured Text files of one program to an image");
    command->add_option("files", options->paths, "The .st files of the program")->required();
    command->add_option("-o,--output", options->output,
                        "The image file to write (default: the first file with .epx)");
    add_force_option(*command, options->force);
    add_error_format_option(*command, options->error_format);
    command->callback([options, &exit_code] { exit_code = run_build(*options); });
}

} // namespace eposp::device::cli
