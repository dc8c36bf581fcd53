#include "checksum_functions.hpp"

namespace eposp::differential {

std::vector<std::string> checksum_functions() {
    // Rotate and xor, then multiply by an odd constant (a bijection) so that a difference in
    // any bit reaches all of them. Reals are folded by value in three integer parts (none can
    // overflow DINT) rather than by their bits, which ST cannot read without pointers.
    return {
        "FUNCTION Mix : ULINT\n"
        "VAR_INPUT ck : ULINT; v : ULINT; END_VAR\n"
        "Mix := LWORD_TO_ULINT(ROL(ULINT_TO_LWORD(ck), 7) XOR ULINT_TO_LWORD(v)) * "
        "1099511628211;\n"
        "END_FUNCTION",
        "FUNCTION MixR : ULINT\n"
        "VAR_INPUT ck : ULINT; r : LREAL; END_VAR\n"
        "VAR c : LREAL; high : DINT; low : DINT; END_VAR\n"
        "c := LIMIT(-2.0E15, r, 2.0E15);\n"
        "high := TRUNC(c / 1.0E6);\n"
        "c := (c - DINT_TO_LREAL(high) * 1.0E6) * 1.0E3;\n"
        "low := TRUNC(c);\n"
        "MixR := Mix(Mix(Mix(ck, LINT_TO_ULINT(DINT_TO_LINT(high))), "
        "LINT_TO_ULINT(DINT_TO_LINT(low))), "
        "LINT_TO_ULINT(DINT_TO_LINT(TRUNC((c - DINT_TO_LREAL(low)) * 1.0E9))));\n"
        "END_FUNCTION",
        std::string("FUNCTION MixS : ULINT\n"
                    "VAR_INPUT ck : ULINT; s : STRING; END_VAR\n"
                    "VAR i : INT; END_VAR\n"
                    "MixS := Mix(ck, INT_TO_ULINT(LEN(s)));\n"
                    "FOR i := 1 TO LEN(s) DO\n"
                    "  MixS := Mix(MixS, INT_TO_ULINT(FIND('") +
            kStringAlphabet +
            "', MID(s, 1, i))));\n"
            "END_FOR;\n"
            "END_FUNCTION",
    };
}

} // namespace eposp::differential
