// `eposp plot axes.csv -o axes.svg`: draws an axis trace of `eposp run --trace` as an SVG
// picture: position, velocity and current over time per axis, the PLCopen state under the
// position.
#include "commands.hpp"
#include "eposp/device/axis_plot.hpp"
#include "file_checks.hpp"
#include "options.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <memory>

namespace eposp::device::cli {

namespace {

struct PlotOptions {
    std::string trace;
    std::string output;
    bool force = false;
};

core::Result<std::string> plot(const PlotOptions& options) {
    if (!options.output.ends_with(".svg")) {
        return core::Error{"-o: the plot is an SVG picture: name it .svg (" + options.output + ")"};
    }
    if (auto problem = input_file_problem(options.trace, "an axis trace")) {
        return core::Error{*problem};
    }
    const std::string inputs[] = {options.trace};
    if (auto problem = output_file_problem({"-o", options.output, OutputKind::SvgPicture}, inputs,
                                           options.force)) {
        return core::Error{*problem};
    }
    std::error_code error;
    std::ifstream in(options.trace);
    if (!in) {
        return core::Error{"cannot open " + options.trace};
    }
    auto axes = read_axis_trace(in, options.trace);
    if (!axes) {
        return core::Error{axes.error()};
    }
    // Written beside and renamed, so a failed write leaves no half picture behind.
    const std::string partial = options.output + ".partial";
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out << plot_svg(*axes);
        if (!out.flush()) {
            std::filesystem::remove(partial, error);
            return core::Error{"cannot write " + options.output};
        }
    }
    std::filesystem::rename(partial, options.output, error);
    if (error) {
        std::filesystem::remove(partial, error);
        return core::Error{"cannot write " + options.output};
    }
    return fmt::format("{}: {} axes", options.output, axes->size());
}

} // namespace

void add_plot_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<PlotOptions>();
    CLI::App* command =
        app.add_subcommand("plot", "Draw an axis trace (eposp run --trace) as an SVG picture");
    command->add_option("trace", options->trace, "The axis trace, a CSV file")->required();
    command->add_option("-o,--output", options->output, "The picture to write (.svg)")->required();
    add_force_option(*command, options->force);
    command->callback([options, &exit_code] {
        const auto result = plot(*options);
        if (!result) {
            exit_code = report_user_error("plot", result.error());
            return;
        }
        fmt::print("{}\n", *result);
    });
}

} // namespace eposp::device::cli
