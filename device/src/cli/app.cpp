#include "eposp/device/cli.hpp"
#include "eposp/device/version.hpp"

#include <CLI/CLI.hpp>

namespace eposp::device {

int run_cli(int argc, char** argv) {
    CLI::App app{"eposp - a soft-PLC reimplementation of the maxon EPOS P", "eposp"};
    app.set_version_flag("--version", std::string("eposp ") + kVersion);
    app.require_subcommand(1);
    CLI11_PARSE(app, argc, argv);
    return 0;
}

} // namespace eposp::device
