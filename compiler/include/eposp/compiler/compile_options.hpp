#pragma once

#include "eposp/compiler/source_location.hpp"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler {

/// How one compilation departs from the program as written: what `eposp test` needs to build a
/// test harness around the user's files (docs/testing-plc-code.md).
struct CompileOptions {
    /// Files whose CONFIGURATION declarations are dropped before name resolution, with their
    /// access paths, tasks and program instances (the harness brings its own); their VAR_GLOBALs
    /// stay as global variable lists (the POUs refer to them). Their POUs, types and global
    /// variable lists stay. A file not compiled is an error.
    std::vector<FileId> ignored_configurations{};
    /// FUNCTION_BLOCK name → the FUNCTION_BLOCK that stands in for it (a test double): every
    /// use of the first as a type (variable declarations anywhere, ARRAY OF, REF_TO, structure
    /// members, EXTENDS) names the second instead, and the first is not generated. Either may
    /// be a standard FB (TON) or a native block of a linked library. Names compare
    /// case-insensitively; a name that is not a FUNCTION_BLOCK is an error.
    std::map<std::string, std::string> substitutions{};
    /// Simple IFs (one assignment to one variable in each branch) become branch-free selects.
    /// Coverage compiles turn it off, so that every IF has a branch whose outcomes are counted;
    /// the program's results are the same either way.
    bool if_conversion = true;
    /// Whether the host releases event tasks on the event a TASK's `{attribute 'event' :=
    /// '…'}` names: nothing if it does, else why not (reported at the attribute). Unset: every
    /// text is kept in the image for the host to judge when it loads the program.
    std::function<std::optional<std::string>(std::string_view)> task_event_check{};
};

} // namespace eposp::compiler
