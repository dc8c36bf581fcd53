#include "eposp/compiler/diagnostics.hpp"

#include "eposp/compiler/source_manager.hpp"
#include "utf8.hpp"

#include <stdexcept>

namespace eposp::compiler {

Diagnostic::Diagnostic(DiagnosticCode code_, SourceRange range_, std::string message_)
    : code(code_), severity(describe(code_).severity), range(range_), message(std::move(message_)) {
}

Diagnostics::Diagnostics(std::size_t error_limit) : error_limit_(error_limit) {}

void Diagnostics::report(Diagnostic diagnostic) {
    if (diagnostic.severity == Severity::Error) {
        if (error_count_ > error_limit_) {
            return;
        }
        if (error_count_ == error_limit_) {
            diagnostic =
                Diagnostic(DiagnosticCode::E0004, diagnostic.range,
                           "too many errors; stopping after " + std::to_string(error_limit_));
        }
        ++error_count_;
    }
    diagnostics_.push_back(std::move(diagnostic));
}

void Diagnostics::error(DiagnosticCode code, const SourceRange& range, std::string message) {
    if (describe(code).severity != Severity::Error) {
        throw std::logic_error(std::string(describe(code).name) + " is not an error's code");
    }
    report(Diagnostic(code, range, std::move(message)));
}

void Diagnostics::warning(DiagnosticCode code, const SourceRange& range, std::string message) {
    if (describe(code).severity != Severity::Warning) {
        throw std::logic_error(std::string(describe(code).name) + " is not a warning's code");
    }
    report(Diagnostic(code, range, std::move(message)));
}

namespace {

// Blanks up to `column` of `line`. Tabs are copied so that what follows lines up in any tab
// width.
void indent_to(std::string& out, std::string_view line, std::uint32_t column) {
    const std::size_t offset = utf8::offset_of_column(line, column);
    for (std::size_t i = 0; i < offset && i < line.size(); ++i) {
        if (line[i] == '\t') {
            out += '\t';
        } else if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) {
            out += ' '; // one column per code point, not per byte
        }
    }
}

// The quoted line, then a caret under the first character of the range and tildes under the
// rest of it on that line.
void render_excerpt(std::string& out, const SourceRange& range, const SourceManager& sources) {
    const std::string_view line = sources.line(range.file, range.begin.line);
    if (range.begin.line == 0 || (line.empty() && range.begin.column <= 1)) {
        return;
    }
    out.append(line).append("\n");
    indent_to(out, line, range.begin.column);
    out += '^';
    if (range.end.line == range.begin.line && range.end.column > range.begin.column) {
        out.append(range.end.column - range.begin.column, '~');
    }
    out += '\n';
}

// The replacement under the caret, as clang shows a fix-it (the first line of it).
void render_fix_it(std::string& out, const FixIt& fix_it, const SourceManager& sources) {
    indent_to(out, sources.line(fix_it.range.file, fix_it.range.begin.line),
              fix_it.range.begin.column);
    out.append(fix_it.replacement.substr(0, fix_it.replacement.find('\n'))).append("\n");
}

void render_one(std::string& out, Severity severity, std::string_view code,
                const SourceRange& range, const std::string& message,
                const SourceManager& sources) {
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
    out.append(severity_name(severity)).append(": ").append(message);
    if (!code.empty()) {
        out.append(" [").append(code).append("]");
    }
    out += '\n';
    if (range.file < sources.file_count()) {
        render_excerpt(out, range, sources);
    }
}

} // namespace

std::string render(const Diagnostic& diagnostic, const SourceManager& sources) {
    std::string out;
    render_one(out, diagnostic.severity, describe(diagnostic.code).name, diagnostic.range,
               diagnostic.message, sources);
    if (diagnostic.fix_it && diagnostic.fix_it->range.file < sources.file_count() &&
        diagnostic.fix_it->range.begin.line > 0) {
        render_fix_it(out, *diagnostic.fix_it, sources);
    }
    for (const DiagnosticNote& note : diagnostic.notes) {
        render_one(out, Severity::Note, {}, note.range, note.message, sources);
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
