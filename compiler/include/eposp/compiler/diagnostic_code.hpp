#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace eposp::compiler {

enum class Severity { Note, Warning, Error };

/// The stage whose rule a diagnostic states (the hundreds digit of its code), not the file that
/// reports it today: a type error keeps its code when it moves from code generation to typing.
enum class DiagnosticStage { Driver, Syntax, Names, Types, Checks, Limits };

/// Every diagnostic the compiler reports, by its stable code: `E` errors, `W` warnings, then the
/// stage (0 driver, 1 syntax, 2 names, 3 types, 4 checks, 5 limits) and a number within it.
/// Generated from the catalogue (diagnostic_catalogue.def), so a code that is not in it does not
/// compile.
enum class DiagnosticCode : std::uint16_t {
#define EPOSP_DIAGNOSTIC(code, severity, stage, title, explanation, wrong, right) code,
#include "eposp/compiler/diagnostic_catalogue.def"
#undef EPOSP_DIAGNOSTIC
};

/// One entry of the catalogue: what `eposp explain CODE` prints. `wrong` is ST that produces
/// the diagnostic, `right` the same program fixed (it compiles without diagnostics). A line
/// `(* in a linked library: *)` starts the part of an example compiled as a linked library
/// (native POUs); codes that ST alone cannot produce have no examples.
struct DiagnosticInfo {
    DiagnosticCode code;
    std::string_view name; // "E0201"
    Severity severity;
    DiagnosticStage stage;
    std::string_view title;
    std::string_view explanation;
    std::string_view wrong;
    std::string_view right;
};

/// Every code, in the order of the catalogue.
std::span<const DiagnosticInfo> diagnostic_catalogue();
const DiagnosticInfo& describe(DiagnosticCode code);
/// The code named `name` ("E0201", any case); nullopt when there is none.
std::optional<DiagnosticCode> find_diagnostic_code(std::string_view name);
std::string_view stage_name(DiagnosticStage stage);
/// "note", "warning", "error": as rendered and in JSON.
std::string_view severity_name(Severity severity);

} // namespace eposp::compiler
