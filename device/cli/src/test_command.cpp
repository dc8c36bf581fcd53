// `eposp test FILES… [--network net.yaml] [--filter GLOB] [--junit report.xml] [--jobs N]
// [--seed N] [--timeout 10s] [--coverage] [--lcov FILE]`: runs the ST test suites of the files
// (docs/testing-plc-code.md), each in a fresh EPOS P in virtual time, and reports like a CI test
// runner: each failure as `file:line: Suite.Test: …`, then `N passed, N failed`.
#include "commands.hpp"
#include "eposp/compiler/diagnostics_json.hpp"
#include "eposp/core/durable_file.hpp"
#include "eposp/plctest/lcov_writer.hpp"
#include "eposp/plctest/reports.hpp"
#include "eposp/plctest/test_run.hpp"
#include "exit_codes.hpp"
#include "file_checks.hpp"
#include "options.hpp"
#include "program_input.hpp"
#include "terminal_text.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <set>
#include <thread>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kTestCommand = "test";

struct TestOptions {
    std::vector<std::string> paths;
    std::optional<std::string> network;
    std::string filter;
    std::optional<std::string> junit;
    std::optional<std::string> lcov;
    bool coverage = false;
    unsigned jobs = std::max(1U, std::thread::hardware_concurrency());
    std::optional<core::Duration> timeout;
    std::optional<std::uint64_t> seed;
    vm::Engine engine = vm::default_engine();
    bool force = false;
    ErrorFormat error_format = ErrorFormat::Human;
};

std::optional<std::string> options_problem(const TestOptions& options) {
    if (options.timeout && *options.timeout <= core::Duration::zero()) {
        return "--timeout " + core::format_duration(*options.timeout) +
               ": a test needs some machine time to run (e.g. 10s)";
    }
    for (auto path = options.paths.begin(); path != options.paths.end(); ++path) {
        if (auto problem = input_file_problem(*path, "an ST file")) {
            return problem;
        }
        // Twice in one program, its POUs would be declared twice (here or by another name).
        std::error_code error;
        for (auto earlier = options.paths.begin(); earlier != path; ++earlier) {
            if (std::filesystem::equivalent(*earlier, *path, error)) {
                return *path + " is given twice (also as " + *earlier + ")";
            }
        }
    }
    std::vector<std::string> inputs = options.paths;
    if (options.network) {
        if (auto problem = input_file_problem(*options.network, "a network file")) {
            return "--network " + *problem;
        }
        inputs.push_back(*options.network);
    }
    std::vector<OutputFile> outputs;
    if (options.junit) {
        outputs.push_back({"--junit", *options.junit, OutputKind::JunitReport});
    }
    if (options.lcov) {
        outputs.push_back({"--lcov", *options.lcov, OutputKind::LcovTracefile});
    }
    return output_files_problem(outputs, inputs, options.force);
}

/// Prints each compilation's diagnostics as JSON lines on stdout, each once: every suite's
/// program holds the same files, so the same warning would otherwise come once per suite.
plctest::DiagnosticsObserver json_diagnostics_printer() {
    return [printed = std::make_shared<std::set<std::string>>()](
               const compiler::Diagnostics& diagnostics, const compiler::SourceManager& sources) {
        const std::string lines = compiler::render_json(diagnostics, sources);
        for (std::size_t begin = 0, end; begin < lines.size(); begin = end + 1) {
            end = lines.find('\n', begin);
            if (end == std::string::npos) {
                end = lines.size();
            }
            if (std::string line = lines.substr(begin, end - begin);
                !line.empty() && printed->insert(line).second) {
                fmt::print("{}\n", line);
            }
        }
    };
}

std::optional<std::string> write_text(const std::string& path, const std::string& text) {
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    if (auto error = core::write_file_durably(path, bytes)) {
        return error->message;
    }
    return std::nullopt;
}

int run_test_command(const TestOptions& options) {
    if (auto problem = options_problem(options)) {
        return report_user_error(kTestCommand, *problem);
    }
    plctest::TestRunOptions run_options;
    run_options.paths = options.paths;
    run_options.filter = plctest::TestFilter(options.filter);
    run_options.jobs = options.jobs;
    run_options.seed = options.seed;
    run_options.settings.engine = options.engine;
    run_options.settings.coverage = options.coverage || options.lcov;
    if (options.error_format == ErrorFormat::Json) {
        run_options.observe_diagnostics = json_diagnostics_printer();
    }
    if (options.timeout) {
        run_options.settings.timeout = *options.timeout;
    }
    if (options.network) {
        auto network = load_network_file(*options.network);
        if (!network) {
            return report_user_error(kTestCommand, network.error());
        }
        run_options.settings.network = std::move(*network);
    }
    auto run = plctest::run_tests(run_options);
    if (!run) {
        // The files' own mistakes, already `file:line: error: …` as the compiler writes them
        // (on stderr also with --error-format json, whose lines went to stdout).
        const std::string text = terminal_text(run.error());
        fmt::print(stderr, "{}{}", text, text.ends_with('\n') ? "" : "\n");
        return kExitUserError;
    }
    if (run->sources.suites.empty()) {
        return report_user_error(kTestCommand,
                                 "no test suite in the files: a suite is a FUNCTION_BLOCK or "
                                 "PROGRAM whose body calls TEST('name')");
    }
    if (run->suites.empty() && !options.filter.empty()) {
        // A mistyped filter must not pass a CI job that ran nothing.
        return report_user_error(kTestCommand, "--filter '" + options.filter + "' selects no test");
    }
    fmt::print("{}", terminal_text(plctest::console_report(run->suites)));
    if (run_options.settings.coverage) {
        fmt::print("coverage:\n{}", vm::coverage_summary(run->coverage));
    }
    if (options.junit) {
        if (auto error = write_text(*options.junit, plctest::junit_xml(run->suites))) {
            return report_user_error(kTestCommand, "--junit: " + *error);
        }
    }
    if (options.lcov) {
        std::map<std::string, std::string> files;
        for (const auto& [pou, coverage] : run->coverage.pous) {
            if (std::string file = run->sources.file_of(pou); !file.empty()) {
                files.emplace(pou, std::move(file));
            }
        }
        if (auto error = write_text(*options.lcov,
                                    plctest::lcov_tracefile(run->coverage, files, "eposp_test"))) {
            return report_user_error(kTestCommand, "--lcov: " + *error);
        }
    }
    return plctest::totals(run->suites).failed == 0 ? kExitSuccess : kExitUserError;
}

} // namespace

void add_test_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<TestOptions>();
    CLI::App* command = app.add_subcommand(
        "test", "Run the ST test suites of the files in virtual time (docs/testing-plc-code.md)");
    command->add_option("files", options->paths, "The program under test and its test files")
        ->required();
    command->add_option("--network", options->network,
                        "The machine under the program (YAML, docs/network.md); default: the "
                        "EPOS P with its internal EPOS2 as axis 0");
    command->add_option("--filter", options->filter,
                        "Run only the tests whose Suite.Test matches: globs separated by ':', "
                        "and after a '-' the ones to leave out");
    command->add_option("--junit", options->junit, "Write a JUnit XML report to FILE");
    command->add_flag("--coverage", options->coverage,
                      "Print which lines and branches of each POU the tests ran");
    command->add_option("--lcov", options->lcov,
                        "Write the coverage as an lcov tracefile to FILE (implies --coverage)");
    command->add_option("--jobs,-j", options->jobs, "Suites run at once (default: the cores)")
        ->check(whole_number_in(1, 256));
    command->add_option("--seed", options->seed,
                        "Start the suites in an order shuffled by N (each has a device of its "
                        "own: the results must not change)");
    add_duration_option(*command, "--timeout", options->timeout,
                        "Machine time one test may take (default 10s)");
    add_engine_option(*command, options->engine);
    add_force_option(*command, options->force);
    add_error_format_option(*command, options->error_format);
    command->callback([options, &exit_code] { exit_code = run_test_command(*options); });
}

} // namespace eposp::device::cli
