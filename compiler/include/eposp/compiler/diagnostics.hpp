#pragma once

#include "eposp/compiler/source_location.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace eposp::compiler {

class SourceManager;

enum class Severity { Note, Warning, Error };

/// Additional information attached to a diagnostic, possibly pointing elsewhere.
struct DiagnosticNote {
    SourceRange range;
    std::string message;
};

/// One problem found in the source, as data: rendering happens in one place (render()).
struct Diagnostic {
    Severity severity = Severity::Error;
    SourceRange range;
    std::string message;
    std::vector<DiagnosticNote> notes;
};

/// Collects the diagnostics of a compilation. After `error_limit` errors further errors are
/// dropped and one final error says so, like a C compiler's -ferror-limit.
class Diagnostics {
public:
    static constexpr std::size_t kDefaultErrorLimit = 50;

    explicit Diagnostics(std::size_t error_limit = kDefaultErrorLimit);

    void report(Diagnostic diagnostic);
    void error(const SourceRange& range, std::string message);
    void warning(const SourceRange& range, std::string message);

    const std::vector<Diagnostic>& all() const { return diagnostics_; }
    std::size_t error_count() const { return error_count_; }
    bool has_errors() const { return error_count_ > 0; }

private:
    std::size_t error_limit_;
    std::size_t error_count_ = 0;
    std::vector<Diagnostic> diagnostics_;
};

/// `file:line:col: error: message`, the source line and a caret under the range (tildes under
/// the rest of it on the same line), then each note the same way.
std::string render(const Diagnostic& diagnostic, const SourceManager& sources);
/// Every diagnostic rendered, in the order reported.
std::string render(const Diagnostics& diagnostics, const SourceManager& sources);

} // namespace eposp::compiler
