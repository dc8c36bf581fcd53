#include "cli.hpp"
#include "commands.hpp"
#include "terminal_text.hpp"
#include "version.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <string_view>

namespace eposp::device {

int run_cli(int argc, char** argv) {
    CLI::App app{"eposp - a soft-PLC reimplementation of the maxon EPOS P", "eposp"};
    app.set_version_flag("--version", std::string("eposp ") + kVersion);
    app.require_subcommand(1);
    app.fallthrough(false);

    int exit_code = 0;
    cli::add_bus_command(app, exit_code);
    cli::add_node_command(app, exit_code);
    cli::add_drive_command(app, exit_code);
    cli::add_check_command(app, exit_code);
    cli::add_explain_command(app, exit_code);
    cli::add_build_command(app, exit_code);
    cli::add_dump_command(app, exit_code);
    cli::add_eds_command(app, exit_code);
    cli::add_dcf_command(app, exit_code);
    cli::add_run_command(app, exit_code);
    cli::add_serve_command(app, exit_code);
    cli::add_bench_command(app, exit_code);
    cli::add_plot_command(app, exit_code);
    cli::add_download_command(app, exit_code);
    cli::add_od_command(app, exit_code);
    cli::add_watch_command(app, exit_code);
    cli::add_test_command(app, exit_code);

    // CLI11 would only say that a subcommand is required; the user wants to know which word
    // was not one.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string_view name = argv[1];
        const CLI::App& commands = app;
        const auto known = commands.get_subcommands([](const CLI::App*) { return true; });
        if (std::ranges::none_of(known,
                                 [name](const CLI::App* sub) { return sub->get_name() == name; })) {
            fmt::print(stderr,
                       "eposp: error: '{}' is not an eposp command (eposp --help lists "
                       "them)\n",
                       cli::terminal_text(name));
            return 1;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help and --version end here with 0; every usage error is a user error: 1.
        return app.exit(error) == 0 ? 0 : 1;
    }
    return exit_code;
}

} // namespace eposp::device
