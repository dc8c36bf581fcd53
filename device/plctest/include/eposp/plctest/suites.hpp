#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/core/result.hpp"
#include "eposp/plctest/test_results.hpp"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace eposp::plctest {

/// A test suite: a FUNCTION_BLOCK or PROGRAM whose body calls TEST().
struct Suite {
    std::string name;
    compiler::ast::PouKind kind = compiler::ast::PouKind::FunctionBlock;
    SourcePlace place;
    /// Its test doubles: the FUNCTION_BLOCK each named FB is replaced by while this suite runs,
    /// from `{attribute 'mock' := 'FB_Valve => FB_ValveDouble'}` just above its declaration.
    std::map<std::string, std::string> mocks{};
    /// The machine it runs on, from `{attribute 'network' := 'machine.yaml'}` just above its
    /// declaration (relative to its file's folder); else the command's --network.
    std::optional<std::string> network{};
};

/// The attributes on the lines just above a suite's declaration.
struct SuiteAttributes {
    std::map<std::string, std::string> mocks;
    std::optional<std::string> network; ///< as written
};

/// What the test files hold: their suites and where each POU is declared.
struct TestSources {
    std::vector<std::string> paths;
    std::vector<Suite> suites; ///< in file and source order
    /// Each POU's file by its name in upper case (IEC names are case-insensitive), for reports.
    std::map<std::string, std::string> pou_files;

    /// The file of `pou` (any case); empty for a library's.
    std::string file_of(std::string_view pou) const;
};

/// Sees the diagnostics of every compilation a test run makes (the files' parse, then each
/// suite's program), errors and warnings, for a caller that prints them in a form of its own.
using DiagnosticsObserver =
    std::function<void(const compiler::Diagnostics&, const compiler::SourceManager&)>;

/// The suites of the files, or why the files do not parse or hold a malformed attribute
/// (`file:line: error: …`). `observe`, if set, sees the parser's diagnostics.
core::Result<TestSources> discover_suites(const std::vector<std::string>& paths,
                                          const DiagnosticsObserver& observe = {});

/// The attributes on the lines just above `line` (1-based) of `text`: pragma lines
/// `{attribute 'mock' := 'A => B'}` and `{attribute 'network' := 'file.yaml'}`, with blank and
/// comment lines between them; other pragmas are left alone. The error names the line.
core::Result<SuiteAttributes> suite_attributes(std::string_view text, std::uint32_t line);

} // namespace eposp::plctest
