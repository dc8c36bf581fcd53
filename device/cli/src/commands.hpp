#pragma once

#include <CLI/CLI.hpp>

namespace eposp::device::cli {

// Each subcommand adds itself to the application; when it is chosen and its options parse, its
// callback runs it and stores the process exit code in `exit_code`.
void add_bus_command(CLI::App& app, int& exit_code);
void add_node_command(CLI::App& app, int& exit_code);
void add_drive_command(CLI::App& app, int& exit_code);
/// `drive escon2`, under `drive` (drive_escon2_command.cpp).
void add_drive_escon2_command(CLI::App& drive, int& exit_code);
void add_check_command(CLI::App& app, int& exit_code);
void add_explain_command(CLI::App& app, int& exit_code);
void add_build_command(CLI::App& app, int& exit_code);
void add_dump_command(CLI::App& app, int& exit_code);
void add_eds_command(CLI::App& app, int& exit_code);
void add_dcf_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
void add_serve_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_plot_command(CLI::App& app, int& exit_code);
void add_download_command(CLI::App& app, int& exit_code);
void add_od_command(CLI::App& app, int& exit_code);
void add_watch_command(CLI::App& app, int& exit_code);
void add_test_command(CLI::App& app, int& exit_code);

} // namespace eposp::device::cli
