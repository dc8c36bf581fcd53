// `eposp check FILES…`: parses the Structured Text files of one program, resolves every name
// across them and prints the diagnostics like a compiler. Quiet when all is well.
#include "commands.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/sema/resolver.hpp"
#include "options.hpp"

#include <fmt/format.h>
#include <memory>
#include <string>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kCommand = "check";

int run_check(const std::vector<std::string>& paths) {
    compiler::SourceManager sources;
    compiler::Diagnostics diagnostics;
    std::vector<compiler::ast::CompilationUnit> units;
    for (const std::string& path : paths) {
        const auto file = sources.load(path);
        if (!file) {
            return report_user_error(kCommand, file.error());
        }
        units.push_back(compiler::parse(sources, *file, diagnostics));
    }
    // A file with syntax errors yields no declarations: resolving the others against it would
    // only add errors about names that are in fact declared.
    if (!diagnostics.has_errors()) {
        compiler::sema::resolve(units, diagnostics);
    }
    fmt::print(stderr, "{}", compiler::render(diagnostics, sources));
    return diagnostics.has_errors() ? 1 : 0;
}

} // namespace

void add_check_command(CLI::App& app, int& exit_code) {
    auto paths = std::make_shared<std::vector<std::string>>();
    CLI::App* command = app.add_subcommand(
        "check", "Check Structured Text files of one program for syntax and name errors");
    command->add_option("files", *paths, "The .st files of the program, checked together")
        ->required();
    command->callback([paths, &exit_code] { exit_code = run_check(*paths); });
}

} // namespace eposp::device::cli
