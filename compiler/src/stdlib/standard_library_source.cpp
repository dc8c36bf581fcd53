#include "standard_library_source.hpp"

#include "eposp/vm/stdlib/manifest.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace eposp::compiler::stdlib {

namespace {

// The FBs' bodies: their VAR_INPUT and VAR_OUTPUT sections are those of their rows in the
// manifest (vm/stdlib/manifest.hpp), which with_interfaces() writes after each FUNCTION_BLOCK
// line. @CLOCK is the manifest's clock native (clock_binding), a FUNCTION without statements.
// Counters count on rising edges (table 45); timers follow the timing diagrams of table 46: a
// timer's ET is measured against PT at every call, so changing PT while the timer runs takes effect
// at once, as in CODESYS.
constexpr std::string_view kSource = R"ST(
FUNCTION @CLOCK : TIME
END_FUNCTION

FUNCTION_BLOCK SR
  Q1 := S1 OR (NOT R AND Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK RS
  Q1 := NOT R1 AND (S OR Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK R_TRIG
  VAR M : BOOL; END_VAR
  Q := CLK AND NOT M;
  M := CLK;
END_FUNCTION_BLOCK

FUNCTION_BLOCK F_TRIG
  VAR M : BOOL := TRUE; END_VAR (* no falling edge on the first call *)
  Q := NOT CLK AND NOT M;
  M := NOT CLK;
END_FUNCTION_BLOCK

@COUNTERS(CTU, CTD, CTUD, 32767, -32768)
@COUNTERS(CTU_DINT, CTD_DINT, CTUD_DINT, 2147483647, -2147483648)
@COUNTERS(CTU_LINT, CTD_LINT, CTUD_LINT, 9223372036854775807, -9223372036854775808)
@COUNTERS(CTU_UDINT, CTD_UDINT, CTUD_UDINT, 4294967295, 0)
@COUNTERS(CTU_ULINT, CTD_ULINT, CTUD_ULINT, 18446744073709551615, 0)

FUNCTION_BLOCK TP
  VAR start : TIME; M : BOOL; END_VAR
  IF NOT Q AND IN AND NOT M THEN
    start := @CLOCK();
    Q := TRUE;
  END_IF;
  IF Q THEN
    ET := @CLOCK() - start;
    IF ET >= PT THEN ET := PT; Q := FALSE; END_IF;
  END_IF;
  (* ET holds PT after the pulse only while IN stays TRUE, also in the call ending the pulse *)
  IF NOT Q AND NOT IN THEN ET := T#0s; END_IF;
  M := IN;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TON
  VAR start : TIME; running : BOOL; END_VAR
  IF IN THEN
    IF NOT running THEN start := @CLOCK(); running := TRUE; END_IF;
    ET := @CLOCK() - start;
    IF ET >= PT THEN ET := PT; Q := TRUE; ELSE Q := FALSE; END_IF;
  ELSE
    Q := FALSE; ET := T#0s; running := FALSE;
  END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TOF
  VAR start : TIME; running : BOOL; END_VAR
  IF IN THEN
    Q := TRUE; ET := T#0s; running := FALSE;
  ELSIF Q THEN
    IF NOT running THEN start := @CLOCK(); running := TRUE; END_IF;
    ET := @CLOCK() - start;
    IF ET >= PT THEN ET := PT; Q := FALSE; running := FALSE; END_IF;
  END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK RTC
  VAR start : TIME; M : BOOL; END_VAR
  IF IN AND NOT M THEN start := @CLOCK(); CDT := PDT; END_IF;
  IF IN THEN CDT := PDT + (@CLOCK() - start); END_IF;
  Q := IN;
  M := IN;
END_FUNCTION_BLOCK
)ST";

constexpr std::string_view kCounters = R"ST(
FUNCTION_BLOCK @CTU
  VAR M : BOOL; END_VAR
  IF R THEN CV := 0;
  ELSIF CU AND NOT M AND CV < @MAX THEN CV := CV + 1;
  END_IF;
  M := CU;
  Q := CV >= PV;
END_FUNCTION_BLOCK

FUNCTION_BLOCK @CTD
  VAR M : BOOL; END_VAR
  IF LD THEN CV := PV;
  ELSIF CD AND NOT M AND CV > @MIN THEN CV := CV - 1;
  END_IF;
  M := CD;
  Q := CV <= 0;
END_FUNCTION_BLOCK

FUNCTION_BLOCK @CTUD
  VAR MU, MD : BOOL; END_VAR
  IF R THEN CV := 0;
  ELSIF LD THEN CV := PV;
  ELSIF NOT (CU AND NOT MU AND CD AND NOT MD) THEN
    IF CU AND NOT MU AND CV < @MAX THEN CV := CV + 1;
    ELSIF CD AND NOT MD AND CV > @MIN THEN CV := CV - 1;
    END_IF;
  END_IF;
  MU := CU;
  MD := CD;
  QU := CV >= PV;
  QD := CV <= 0;
END_FUNCTION_BLOCK
)ST";

void replace_all(std::string& text, std::string_view from, std::string_view to) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
}

/// The VAR_INPUT and VAR_OUTPUT sections of the standard FB `name` from its row of the manifest,
/// neighbouring parameters of one type in one declaration (`S1, R : BOOL;`).
std::string interface_of(std::string_view name) {
    const auto variants = vm::stdlib::standard_block_variants();
    const auto variant = std::find_if(variants.begin(), variants.end(), [&](const auto& candidate) {
        return candidate.name == name;
    });
    if (variant == variants.end()) {
        throw std::logic_error("no manifest row for the standard FB " + std::string(name));
    }
    std::string result;
    for (const bool output : {false, true}) {
        result += output ? "  VAR_OUTPUT" : "  VAR_INPUT";
        std::string_view type;
        for (const vm::stdlib::StandardParameter& parameter : variant->block->parameters) {
            if (parameter.name.empty() || parameter.output != output) {
                continue;
            }
            if (!type.empty() && variant->type_of(parameter) != type) {
                result.append(" : ").append(type).append(";");
                type = {};
            }
            result.append(type.empty() ? " " : ", ").append(parameter.name);
            type = variant->type_of(parameter);
        }
        result.append(" : ").append(type).append("; END_VAR\n");
    }
    return result;
}

/// The source with each `@COUNTERS(up, down, updown, max, min)` line expanded.
std::string expand() {
    std::string result;
    std::string_view rest = kSource;
    while (!rest.empty()) {
        const auto line_end = rest.find('\n');
        std::string_view line = rest.substr(0, line_end);
        rest = line_end == std::string_view::npos ? std::string_view{} : rest.substr(line_end + 1);
        if (!line.starts_with("@COUNTERS(")) {
            result.append(line).append("\n");
            continue;
        }
        line.remove_prefix(10);
        line.remove_suffix(1);
        std::string fields[5];
        for (auto& field : fields) {
            const auto comma = line.find(',');
            field = std::string(line.substr(0, comma));
            line = comma == std::string_view::npos ? std::string_view{} : line.substr(comma + 2);
        }
        std::string block(kCounters);
        replace_all(block, "@CTUD", fields[2]);
        replace_all(block, "@CTU", fields[0]);
        replace_all(block, "@CTD", fields[1]);
        replace_all(block, "@MAX", fields[3]);
        replace_all(block, "@MIN", fields[4]);
        result += block;
    }
    return result;
}

/// `source` with the interface of each FUNCTION_BLOCK after its first line.
std::string with_interfaces(std::string_view source) {
    static constexpr std::string_view kBlock = "FUNCTION_BLOCK ";
    std::string result;
    while (!source.empty()) {
        const auto line_end = source.find('\n');
        const std::string_view line = source.substr(0, line_end);
        source =
            line_end == std::string_view::npos ? std::string_view{} : source.substr(line_end + 1);
        result.append(line).append("\n");
        if (line.starts_with(kBlock)) {
            result += interface_of(line.substr(kBlock.size()));
        }
    }
    return result;
}

} // namespace

std::string_view standard_library_source() {
    static const std::string source = [] { // immutable once built
        std::string text = with_interfaces(expand());
        replace_all(text, "@CLOCK", vm::stdlib::clock_binding().name);
        return text;
    }();
    return source;
}

} // namespace eposp::compiler::stdlib
