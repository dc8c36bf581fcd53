#include "eposp/compiler/diagnostics.hpp"

#include "eposp/compiler/source_manager.hpp"
#include "utf8.hpp"

namespace eposp::compiler {

Diagnostics::Diagnostics(std::size_t error_limit) : error_limit_(error_limit) {}

void Diagnostics::report(Diagnostic diagnostic) {
    if (diagnostic.severity == Severity::Error) {
        if (error_count_ > error_limit_) {
            return;
        }
        if (error_count_ == error_limit_) {
            diagnostic.message = "too many errors; stopping after " + std::to_string(error_limit_);
            diagnostic.notes.clear();
        }
        ++error_count_;
    }
    diagnostics_.push_back(std::move(diagnostic));
}

void Diagnostics::error(const SourceRange& range, std::string message) {
    report({Severity::Error, range, std::move(message), {}});
}

void Diagnostics::warning(const SourceRange& range, std::string message) {
    report({Severity::Warning, range, std::move(message), {}});
}

namespace {

std::string_view severity_name(Severity severity) {
    switch (severity) {
    case Severity::Note:
        return "note";
    case Severity::Warning:
        return "warning";
    case Severity::Error:
        return "error";
    }
    return "error";
}

// The quoted line, then a caret under the first character of the range and tildes under the
// rest of it on that line. Tabs are copied so that the caret lines up in any tab width.
void render_excerpt(std::string& out, const SourceRange& range, const SourceManager& sources) {
    const std::string_view line = sources.line(range.file, range.begin.line);
    if (range.begin.line == 0 || (line.empty() && range.begin.column <= 1)) {
        return;
    }
    out.append(line).append("\n");
    const std::size_t caret_offset = utf8::offset_of_column(line, range.begin.column);
    for (std::size_t i = 0; i < caret_offset && i < line.size(); ++i) {
        if (line[i] == '\t') {
            out += '\t';
        } else if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) {
            out += ' '; // one column per code point, not per byte
        }
    }
    out += '^';
    if (range.end.line == range.begin.line && range.end.column > range.begin.column) {
        out.append(range.end.column - range.begin.column, '~');
    }
    out += '\n';
}

void render_one(std::string& out, Severity severity, const SourceRange& range,
                const std::string& message, const SourceManager& sources) {
    if (range.file < sources.file_count()) {
        out.append(sources.path(range.file)).append(":");
        if (range.begin.line > 0) {
            out.append(std::to_string(range.begin.line))
                .append(":")
                .append(std::to_string(range.begin.column))
                .append(":");
        }
        out += ' ';
    }
    out.append(severity_name(severity)).append(": ").append(message).append("\n");
    if (range.file < sources.file_count()) {
        render_excerpt(out, range, sources);
    }
}

} // namespace

std::string render(const Diagnostic& diagnostic, const SourceManager& sources) {
    std::string out;
    render_one(out, diagnostic.severity, diagnostic.range, diagnostic.message, sources);
    for (const DiagnosticNote& note : diagnostic.notes) {
        render_one(out, Severity::Note, note.range, note.message, sources);
    }
    return out;
}

std::string render(const Diagnostics& diagnostics, const SourceManager& sources) {
    std::string out;
    for (const Diagnostic& diagnostic : diagnostics.all()) {
        out += render(diagnostic, sources);
    }
    return out;
}

} // namespace eposp::compiler
