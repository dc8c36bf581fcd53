// `eposp explain [CODE]`: what a diagnostic's code means, with a program that produces it and
// the same program fixed (the compiler's catalogue, diagnostic_catalogue.def); without a code,
// every code with its title.
#include "commands.hpp"
#include "eposp/compiler/diagnostic_code.hpp"
#include "options.hpp"

#include <fmt/format.h>
#include <memory>
#include <optional>

namespace eposp::device::cli {
namespace {

void print_catalogue() {
    for (const compiler::DiagnosticInfo& info : compiler::diagnostic_catalogue()) {
        fmt::print("{}  {:<8} {}\n", info.name, compiler::stage_name(info.stage), info.title);
    }
}

// The explanation in lines of at most 79 characters, broken between words.
void print_wrapped(std::string_view text) {
    constexpr std::size_t kWidth = 79;
    std::size_t column = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        const std::string_view word = text.substr(start, end - start);
        if (column > 0 && column + 1 + word.size() > kWidth) {
            fmt::print("\n");
            column = 0;
        } else if (column > 0) {
            fmt::print(" ");
            ++column;
        }
        fmt::print("{}", word);
        column += word.size();
        start = end + 1;
    }
    fmt::print("\n");
}

void print_example(std::string_view heading, std::string_view example) {
    if (example.empty()) {
        return;
    }
    fmt::print("\n{}:\n\n", heading);
    for (std::size_t start = 0; start < example.size();) {
        const std::size_t end = std::min(example.find('\n', start), example.size());
        fmt::print("    {}\n", example.substr(start, end - start));
        start = end + 1;
    }
}

void print_explanation(const compiler::DiagnosticInfo& info) {
    fmt::print("{} ({}, {}): {}\n\n", info.name,
               info.severity == compiler::Severity::Error ? "error" : "warning",
               compiler::stage_name(info.stage), info.title);
    print_wrapped(info.explanation);
    print_example("This produces it", info.wrong);
    print_example("Fixed", info.right);
}

} // namespace

void add_explain_command(CLI::App& app, int& exit_code) {
    auto code = std::make_shared<std::string>();
    CLI::App* command = app.add_subcommand(
        "explain", "Explain a compiler diagnostic's code (E0201), or list every code");
    command->add_option("code", *code, "The code in brackets after a diagnostic, as E0201");
    command->callback([code, &exit_code] {
        if (code->empty()) {
            print_catalogue();
            return;
        }
        const std::optional<compiler::DiagnosticCode> found = compiler::find_diagnostic_code(*code);
        if (!found) {
            exit_code = report_user_error(
                "explain",
                fmt::format("no diagnostic has the code '{}' (eposp explain lists them)", *code));
            return;
        }
        print_explanation(compiler::describe(*found));
    });
}

} // namespace eposp::device::cli
