#pragma once

// Random, well-defined Structured Text programs for differential testing: from a seeded
// generator, a PROGRAM Main (with user FUNCTIONs, FUNCTION_BLOCKs and STRUCTs around it) whose
// every computed value is folded into `Main.checksum`, a ULINT, so that one number per scan says
// whether two executors agree. Well-defined by construction, not by rejection: no signed
// overflow (signed operands are reduced with MOD first), no division or MOD by zero (divisors
// are built non-zero), no index out of range (indices are reduced with MOD and offset), no NaN
// or infinity (reals are bounded with LIMIT), string positions inside their string, and loops
// that end.

#include "eposp/differential/program_tree.hpp"

#include <random>
#include <string>

namespace eposp::differential {

/// The generator's knobs: how big, and which features (all on by default).
struct GeneratorOptions {
    int functions = 2; ///< user FUNCTIONs (each may call the ones before it)
    int function_blocks = 1;
    int statements = 14; ///< statements of Main's body, before folding
    int expression_depth = 3;
    int max_inputs = 7;  ///< inputs of one user FUNCTION
    bool reals = true;   ///< REAL and LREAL values and arithmetic
    bool strings = true; ///< STRING values, string functions and STRING arguments
    bool arrays = true;
    bool structs = true;
    bool loops = true; ///< FOR, WHILE, REPEAT (with EXIT and CONTINUE)
    bool case_statements = true;
    bool in_out = true; ///< VAR_IN_OUT parameters
    /// TIME, TOD and DT arithmetic (table 30), each taken back to a duration in LINT nanoseconds.
    bool times = true;
    /// CASE on ULINT with labels above 2^63 - 1.
    bool huge_case_labels = true;
    /// MAX, MIN and LIMIT on STRING (SEL and MUX take strings whenever `strings` is on).
    bool string_max_min_limit = true;
    /// Real-to-integer conversions of values that may lie halfway between two integers.
    bool real_ties = false;
    /// Main's VAR CONSTANTs, whose initial values are operator expressions over literals and
    /// the constants before them: the compiler folds them, the reference evaluates them.
    bool constants = true;
};

/// One program; its source is render(block). Main's checksum is `Main.checksum`.
struct GeneratedProgram {
    Block block;
};

GeneratedProgram generate_program(std::mt19937_64& random, const GeneratorOptions& options = {});

/// The checksum variable every generated program folds into.
inline constexpr const char* kChecksumPath = "Main.checksum";

} // namespace eposp::differential
