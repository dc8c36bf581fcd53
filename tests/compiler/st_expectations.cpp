// Checks one .st file against the diagnostics written in it, next to the lines they concern
// (LLVM's FileCheck -verify and RuSTy's tests in spirit; docs/diagnostics.md):
//
//     x := totl;               // expect: E0201
//     y := a / 0 + b / 0;      // expect: E0408 E0408
//     k : INT := k + 1;        // expect: E0313 "defined through itself"
//     // expect-unlocated: W0407      (a diagnostic about the program as a whole)
//
// Every diagnostic must be expected on its line (by code, and by a text its message contains
// where one is quoted after the code), and every expectation met; ctest runs
// this once per file of tests/compiler/diagnostics (registered by glob when configuring).
// Exit status 0 when the file's diagnostics are exactly its expectations, 1 otherwise.
#include "eposp/compiler/compiler.hpp"
#include "eposp/compiler/diagnostic_code.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fmt/format.h>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace {

/// A diagnostic expected: its code, and a text its message contains (none: any message).
struct Expected {
    std::string code;
    std::string text;
};
using Expectations = std::map<std::uint32_t, std::vector<Expected>>; // line 0: unlocated

void add_codes(std::vector<Expected>& to, std::string_view codes) {
    std::size_t at = 0;
    while (at < codes.size()) {
        while (at < codes.size() && std::isspace(static_cast<unsigned char>(codes[at]))) {
            ++at;
        }
        if (at < codes.size() && codes[at] == '"' && !to.empty()) {
            const std::size_t close = std::min(codes.find('"', at + 1), codes.size());
            to.back().text = std::string(codes.substr(at + 1, close - at - 1));
            at = close + 1;
            continue;
        }
        std::size_t end = at;
        while (end < codes.size() && !std::isspace(static_cast<unsigned char>(codes[end]))) {
            ++end;
        }
        if (end > at) {
            to.push_back({std::string(codes.substr(at, end - at)), {}});
        }
        at = end;
    }
}

/// Takes the expectation `diagnostic` meets from `expected`: one whose text its message contains
/// before one that expects any message.
bool meet(std::vector<Expected>& expected, const std::string& code, const std::string& message) {
    auto it = std::find_if(expected.begin(), expected.end(), [&](const Expected& e) {
        return e.code == code && !e.text.empty() && message.find(e.text) != std::string::npos;
    });
    if (it == expected.end()) {
        it = std::find_if(expected.begin(), expected.end(),
                          [&](const Expected& e) { return e.code == code && e.text.empty(); });
    }
    if (it == expected.end()) {
        return false;
    }
    expected.erase(it);
    return true;
}

// The expectations of each line, and the names in them that are no code (a typo would otherwise
// expect nothing).
Expectations read_expectations(const eposp::compiler::SourceManager& sources,
                               eposp::compiler::FileId file, std::vector<std::string>& bad) {
    constexpr std::string_view kHere = "// expect:";
    constexpr std::string_view kUnlocated = "// expect-unlocated:";
    Expectations expected;
    const std::string& text = sources.text(file);
    std::uint32_t line_number = 0;
    for (std::size_t start = 0; start < text.size();) {
        ++line_number;
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = std::string_view(text).substr(start, end - start);
        start = end + 1;
        for (const auto& [marker, on] :
             {std::pair{kHere, line_number}, std::pair{kUnlocated, 0U}}) {
            const std::size_t found = line.find(marker);
            if (found != std::string_view::npos) {
                add_codes(expected[on], line.substr(found + marker.size()));
            }
        }
    }
    for (const auto& [line, codes] : expected) {
        for (const Expected& one : codes) {
            if (!eposp::compiler::find_diagnostic_code(one.code)) {
                bad.push_back(fmt::format("line {}: '{}' is no diagnostic code", line, one.code));
            }
        }
    }
    return expected;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: eposp_st_expectations FILE.st\n", stderr);
        return 2;
    }
    eposp::compiler::SourceManager sources;
    const auto file = sources.load(argv[1]);
    if (!file) {
        std::fprintf(stderr, "%s\n", file.error().c_str());
        return 2;
    }
    std::vector<std::string> problems;
    Expectations expected = read_expectations(sources, *file, problems);
    eposp::compiler::Diagnostics diagnostics;
    const std::vector<eposp::compiler::FileId> files = {*file};
    eposp::compiler::compile(sources, files, diagnostics);

    for (const auto& diagnostic : diagnostics.all()) {
        const std::string code(eposp::compiler::describe(diagnostic.code).name);
        const std::uint32_t line = diagnostic.range.file == *file ? diagnostic.range.begin.line : 0;
        if (!meet(expected[line], code, diagnostic.message)) {
            problems.push_back("unexpected: " + render(diagnostic, sources));
        }
    }
    for (const auto& [line, codes] : expected) {
        for (const auto& [code, text] : codes) {
            const std::string what = text.empty() ? code : fmt::format("{} \"{}\"", code, text);
            problems.push_back(
                line == 0 ? fmt::format("expected {} (unlocated), not reported", what)
                          : fmt::format("{}:{}: expected {}, not reported", argv[1], line, what));
        }
    }
    for (const std::string& problem : problems) {
        std::fprintf(stderr, "%s\n", problem.c_str());
    }
    return problems.empty() ? 0 : 1;
}
