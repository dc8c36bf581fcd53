#pragma once

#include "eposp/compiler/diagnostics.hpp"

#include <string>

namespace eposp::compiler {

/// Each diagnostic as one line of JSON (JSON Lines, as rustc's --error-format=json), for
/// editors and CI; the schema is in docs/diagnostics.md:
/// {"code":"E0201","severity":"error","title":"undeclared identifier","message":"...",
///  "file":"main.st","range":{"start":{"line":3,"column":1},"end":{"line":3,"column":4}},
///  "notes":[{"message":"...","file":...,"range":...}],"fix_it":null}
std::string render_json(const Diagnostics& diagnostics, const SourceManager& sources);

} // namespace eposp::compiler
