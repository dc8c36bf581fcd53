#pragma once

#include "eposp/compiler/diagnostic_code.hpp"
#include "eposp/compiler/source_location.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace eposp::compiler {

class SourceManager;

/// Additional information attached to a diagnostic, possibly pointing elsewhere.
struct DiagnosticNote {
    SourceRange range;
    std::string message;
};

/// A suggested edit that fixes the problem: `replacement` in place of `range` (an empty range,
/// begin after end, inserts before `range.begin`).
struct FixIt {
    SourceRange range;
    std::string replacement;
};

/// One problem found in the source, as data: rendering happens in one place (render()). Its
/// code names the rule (diagnostic_catalogue.def) and gives its severity.
struct Diagnostic {
    Diagnostic(DiagnosticCode code, SourceRange range, std::string message);

    DiagnosticCode code;
    Severity severity;
    SourceRange range;
    std::string message;
    std::vector<DiagnosticNote> notes;
    std::optional<FixIt> fix_it;
};

/// Collects the diagnostics of a compilation. After `error_limit` errors further errors are
/// dropped and one final error says so, like a C compiler's -ferror-limit.
class Diagnostics {
public:
    static constexpr std::size_t kDefaultErrorLimit = 50;

    explicit Diagnostics(std::size_t error_limit = kDefaultErrorLimit);

    void report(Diagnostic diagnostic);
    /// `code` is an error's (a warning's) code: the catalogue says which, and a mismatch is a
    /// programming error (std::logic_error).
    void error(DiagnosticCode code, const SourceRange& range, std::string message);
    void warning(DiagnosticCode code, const SourceRange& range, std::string message);

    const std::vector<Diagnostic>& all() const { return diagnostics_; }
    std::size_t error_count() const { return error_count_; }
    bool has_errors() const { return error_count_ > 0; }

private:
    std::size_t error_limit_;
    std::size_t error_count_ = 0;
    std::vector<Diagnostic> diagnostics_;
};

/// `file:line:col: error: message [E0201]`, the source line and a caret under the range (tildes
/// under the rest of it on the same line), the fix-it's replacement under the caret, then each
/// note the same way (without a code).
std::string render(const Diagnostic& diagnostic, const SourceManager& sources);
/// Every diagnostic rendered, in the order reported.
std::string render(const Diagnostics& diagnostics, const SourceManager& sources);

} // namespace eposp::compiler
