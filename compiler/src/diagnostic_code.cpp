#include "eposp/compiler/diagnostic_code.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace eposp::compiler {
namespace {

constexpr std::array kCatalogue = {
#define EPOSP_DIAGNOSTIC(code, severity, stage, title, explanation, wrong, right)                  \
    DiagnosticInfo{DiagnosticCode::code,                                                           \
                   #code,                                                                          \
                   Severity::severity,                                                             \
                   DiagnosticStage::stage,                                                         \
                   title,                                                                          \
                   explanation,                                                                    \
                   wrong,                                                                          \
                   right},
#include "eposp/compiler/diagnostic_catalogue.def"
#undef EPOSP_DIAGNOSTIC
};

// The enum is generated from the same list, so entry i describes code i; checked once here.
constexpr bool in_enum_order() {
    for (std::size_t i = 0; i < kCatalogue.size(); ++i) {
        if (static_cast<std::size_t>(kCatalogue[i].code) != i) {
            return false;
        }
    }
    return true;
}
static_assert(in_enum_order());

// The letter states the severity: E for errors, W for warnings.
constexpr bool letters_match_severities() {
    return std::all_of(kCatalogue.begin(), kCatalogue.end(), [](const DiagnosticInfo& info) {
        return info.name.size() == 5 &&
               info.name.front() == (info.severity == Severity::Error ? 'E' : 'W');
    });
}
static_assert(letters_match_severities());

} // namespace

std::span<const DiagnosticInfo> diagnostic_catalogue() {
    return kCatalogue;
}

const DiagnosticInfo& describe(DiagnosticCode code) {
    return kCatalogue[static_cast<std::size_t>(code)];
}

std::optional<DiagnosticCode> find_diagnostic_code(std::string_view name) {
    for (const DiagnosticInfo& info : kCatalogue) {
        if (std::equal(
                name.begin(), name.end(), info.name.begin(), info.name.end(),
                [](char a, char b) { return std::toupper(static_cast<unsigned char>(a)) == b; })) {
            return info.code;
        }
    }
    return std::nullopt;
}

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

std::string_view stage_name(DiagnosticStage stage) {
    switch (stage) {
    case DiagnosticStage::Driver:
        return "driver";
    case DiagnosticStage::Syntax:
        return "syntax";
    case DiagnosticStage::Names:
        return "names";
    case DiagnosticStage::Types:
        return "types";
    case DiagnosticStage::Checks:
        return "checks";
    case DiagnosticStage::Limits:
        return "limits";
    }
    return "driver";
}

} // namespace eposp::compiler
