#include "eposp/compiler/diagnostics_json.hpp"

#include "eposp/compiler/source_manager.hpp"

#include <nlohmann/json.hpp>

namespace eposp::compiler {
namespace {

// Fields in the order of the schema (docs/diagnostics.md), not sorted.
using json = nlohmann::ordered_json;

json position(const SourcePosition& at) {
    return {{"line", at.line}, {"column", at.column}};
}

// The file by its path (null for a diagnostic about the compilation as a whole, such as a
// compile option), and the range with both ends included, 1-based.
void locate(json& out, const SourceRange& range, const SourceManager& sources) {
    const bool in_a_file = range.file < sources.file_count();
    out["file"] = in_a_file ? json(sources.path(range.file)) : json(nullptr);
    out["range"] = in_a_file && range.begin.line > 0
                       ? json{{"start", position(range.begin)}, {"end", position(range.end)}}
                       : json(nullptr);
}

json to_json(const Diagnostic& diagnostic, const SourceManager& sources) {
    json out;
    out["code"] = describe(diagnostic.code).name;
    out["severity"] = severity_name(diagnostic.severity);
    out["title"] = describe(diagnostic.code).title;
    out["message"] = diagnostic.message;
    locate(out, diagnostic.range, sources);
    out["notes"] = json::array();
    for (const DiagnosticNote& note : diagnostic.notes) {
        json entry{{"message", note.message}};
        locate(entry, note.range, sources);
        out["notes"].push_back(std::move(entry));
    }
    out["fix_it"] = nullptr;
    if (diagnostic.fix_it) {
        json fix{{"replacement", diagnostic.fix_it->replacement}};
        locate(fix, diagnostic.fix_it->range, sources);
        out["fix_it"] = std::move(fix);
    }
    return out;
}

} // namespace

std::string render_json(const Diagnostics& diagnostics, const SourceManager& sources) {
    std::string out;
    for (const Diagnostic& diagnostic : diagnostics.all()) {
        // Invalid UTF-8 in a message (a quoted name from a Windows-1252 file) is replaced, not
        // thrown on.
        out += to_json(diagnostic, sources).dump(-1, ' ', false, json::error_handler_t::replace);
        out += '\n';
    }
    return out;
}

} // namespace eposp::compiler
