// Checks the typing stage against a snapshot: the typed tree of FILE.st (types::dump_typed: each
// expression's type, constant value and call target) must equal FILE.typed beside it. ctest runs
// this once per file of tests/compiler/types/snapshots (registered by glob when configuring). With
// --update it writes FILE.typed instead, to be read and committed when a change of the typing
// stage is meant. Exit status 0 when they agree, 1 when not, 2 on bad input.
#include "eposp/compiler/types/front_end.hpp"
#include "eposp/compiler/types/typed_dump.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

std::string typed_tree(const eposp::compiler::types::FrontEnd& front_end) {
    std::string text;
    for (const auto& unit : front_end.units) {
        text += eposp::compiler::types::dump_typed(*front_end.program, unit);
    }
    return text;
}

/// The first line where the two texts differ, for the failure message.
std::string first_difference(const std::string& expected, const std::string& actual) {
    std::istringstream want(expected);
    std::istringstream got(actual);
    std::string a;
    std::string b;
    for (int line = 1;; ++line) {
        const bool more_a = static_cast<bool>(std::getline(want, a));
        const bool more_b = static_cast<bool>(std::getline(got, b));
        if (!more_a && !more_b) {
            return "";
        }
        if (!more_a || !more_b || a != b) {
            return "line " + std::to_string(line) + ":\n  expected: " + (more_a ? a : "(end)") +
                   "\n  actual:   " + (more_b ? b : "(end)");
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    const bool update = argc == 3 && std::string_view(argv[2]) == "--update";
    if (argc != 2 && !update) {
        std::fputs("usage: eposp_typed_snapshot FILE.st [--update]\n", stderr);
        return 2;
    }
    const std::string source_path = argv[1];
    const std::string snapshot_path = source_path.substr(0, source_path.rfind('.')) + ".typed";
    eposp::compiler::SourceManager sources;
    const auto file = sources.load(source_path);
    if (!file) {
        std::fprintf(stderr, "%s\n", file.error().c_str());
        return 2;
    }
    eposp::compiler::Diagnostics diagnostics;
    const std::vector<eposp::compiler::FileId> files = {*file};
    const auto front_end = eposp::compiler::types::analyse(sources, files, diagnostics);
    if (!front_end->program) {
        // Snapshots are of programs that type; refused ones belong to tests/compiler/diagnostics.
        std::fprintf(stderr, "%s", render(diagnostics, sources).c_str());
        return 2;
    }
    const std::string actual = typed_tree(*front_end);
    if (update) {
        std::ofstream(snapshot_path, std::ios::binary) << actual;
        return 0;
    }
    std::ifstream snapshot(snapshot_path, std::ios::binary);
    if (!snapshot) {
        std::fprintf(stderr, "%s: no snapshot; write it with --update\n", snapshot_path.c_str());
        return 1;
    }
    std::ostringstream expected;
    expected << snapshot.rdbuf();
    const std::string difference = first_difference(expected.str(), actual);
    if (!difference.empty()) {
        std::fprintf(stderr, "%s differs from the typed tree of %s at %s\n", snapshot_path.c_str(),
                     source_path.c_str(), difference.c_str());
        return 1;
    }
    return 0;
}
