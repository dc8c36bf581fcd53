// Time and date arithmetic (IEC 61131-3 ed. 3, table 30) on the VM: every row in its three
// forms, the operator, the overloaded ADD, SUB, MUL or DIV and the named function, stored into a
// variable of the row's result type, so that a result typed narrower or wider than the standard
// says (TIME - LTIME is an LTIME) would not compile. A short operand beside a long one widens
// first (figure 11: TIME to LTIME, DATE to LDATE, TOD to LTOD, DT to LDT); a time of day wraps
// around midnight at either width.
#include "codegen_harness.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;
constexpr std::int64_t kDay = 86'400 * kSecond;
constexpr std::int64_t kJanuary31 = 19'753 * kDay; // D#2024-01-31
constexpr std::int64_t kNoon = 12 * 3'600 * kSecond;

/// The inputs every row computes on.
constexpr const char* kInputs = R"(
    t : TIME := T#1s; lt : LTIME := LTIME#2us; d : DATE := D#2024-01-31;
    ld : LDATE := LDATE#2024-01-01; tod1 : TOD := TOD#23:59:59; ltod1 : LTOD := LTOD#00:00:01;
    dt1 : DT := DT#2024-01-31-12:00:00; ldt1 : LDT := LDT#2024-01-31-11:00:00;
    n : INT := 3; r : LREAL := 2.5;)";

struct Row {
    const char* type;       ///< the result type of table 30
    const char* operation;  ///< the operator form (null: the function has no symbol)
    const char* overloaded; ///< ADD, SUB, MUL or DIV (null: none)
    const char* named;      ///< the named function of table 30
    std::int64_t expected;
};

const Row kRows[] = {
    {"TIME", "t + t", "ADD(t, t)", "ADD_TIME(t, t)", 2 * kSecond},
    {"LTIME", "lt + lt", "ADD(lt, lt)", "ADD_LTIME(lt, lt)", 4'000},
    {"TOD", "tod1 + t", "ADD(tod1, t)", "ADD_TOD_TIME(tod1, t)", 0},
    {"LTOD", "ltod1 + lt", "ADD(ltod1, lt)", "ADD_LTOD_LTIME(ltod1, lt)", kSecond + 2'000},
    {"DT", "dt1 + t", "ADD(dt1, t)", "ADD_DT_TIME(dt1, t)", kJanuary31 + kNoon + kSecond},
    {"LDT", "ldt1 + lt", "ADD(ldt1, lt)", "ADD_LDT_LTIME(ldt1, lt)",
     kJanuary31 + kNoon - 3'600 * kSecond + 2'000},
    {"TIME", "t - T#250ms", "SUB(t, T#250ms)", "SUB_TIME(t, T#250ms)", 750'000'000},
    {"LTIME", "lt - LTIME#500ns", "SUB(lt, LTIME#500ns)", "SUB_LTIME(lt, LTIME#500ns)", 1'500},
    {"TIME", "d - D#2024-01-01", "SUB(d, D#2024-01-01)", "SUB_DATE_DATE(d, D#2024-01-01)",
     30 * kDay},
    {"LTIME", "ld - LDATE#2023-12-31", "SUB(ld, LDATE#2023-12-31)",
     "SUB_LDATE_LDATE(ld, LDATE#2023-12-31)", kDay},
    {"TOD", "TOD#00:00:00.5 - t", "SUB(TOD#00:00:00.5, t)", "SUB_TOD_TIME(TOD#00:00:00.5, t)",
     kDay - kSecond / 2},
    {"LTOD", "ltod1 - LTIME#2s", "SUB(ltod1, LTIME#2s)", "SUB_LTOD_LTIME(ltod1, LTIME#2s)",
     kDay - kSecond},
    {"TIME", "tod1 - TOD#12:00:00", "SUB(tod1, TOD#12:00:00)", "SUB_TOD_TOD(tod1, TOD#12:00:00)",
     kNoon - kSecond},
    {"LTIME", "ltod1 - LTOD#00:00:00.5", "SUB(ltod1, LTOD#00:00:00.5)",
     "SUB_LTOD_LTOD(ltod1, LTOD#00:00:00.5)", kSecond / 2},
    {"DT", "dt1 - t", "SUB(dt1, t)", "SUB_DT_TIME(dt1, t)", kJanuary31 + kNoon - kSecond},
    {"LDT", "ldt1 - lt", "SUB(ldt1, lt)", "SUB_LDT_LTIME(ldt1, lt)",
     kJanuary31 + kNoon - 3'600 * kSecond - 2'000},
    {"TIME", "dt1 - DT#2024-01-31-11:00:00", "SUB(dt1, DT#2024-01-31-11:00:00)",
     "SUB_DT_DT(dt1, DT#2024-01-31-11:00:00)", 3'600 * kSecond},
    {"LTIME", "ldt1 - LDT#2024-01-31-10:59:59", "SUB(ldt1, LDT#2024-01-31-10:59:59)",
     "SUB_LDT_LDT(ldt1, LDT#2024-01-31-10:59:59)", kSecond},
    {"TIME", "t * n", "MUL(t, n)", "MUL_TIME(t, n)", 3 * kSecond},
    {"LTIME", "lt * n", "MUL(lt, n)", "MUL_LTIME(lt, n)", 6'000},
    {"TIME", "t / n", "DIV(t, n)", "DIV_TIME(t, n)", kSecond / 3},
    {"LTIME", "lt / r", "DIV(lt, r)", "DIV_LTIME(lt, r)", 800},
    {"DT", nullptr, nullptr, "CONCAT_DATE_TOD(d, tod1)", kJanuary31 + kDay - kSecond},
    {"LDT", nullptr, nullptr, "CONCAT_DATE_LTOD(d, ltod1)", kJanuary31 + kSecond},
    // The short operand widens to the long row (figure 11).
    {"LTIME", "t + lt", "ADD(t, lt)", "ADD_LTIME(t, lt)", kSecond + 2'000},
    {"LTIME", "t - lt", "SUB(t, lt)", "SUB_LTIME(t, lt)", kSecond - 2'000},
    {"LTOD", "tod1 + lt", "ADD(tod1, lt)", "ADD_LTOD_LTIME(tod1, lt)", kDay - kSecond + 2'000},
    {"LTOD", "ltod1 - t", "SUB(ltod1, t)", "SUB_LTOD_LTIME(ltod1, t)", 0},
    {"LDT", "dt1 + lt", "ADD(dt1, lt)", "ADD_LDT_LTIME(dt1, lt)", kJanuary31 + kNoon + 2'000},
    {"LTIME", "dt1 - ldt1", "SUB(dt1, ldt1)", "SUB_LDT_LDT(dt1, ldt1)", 3'600 * kSecond},
    {"LTIME", "d - ld", "SUB(d, ld)", "SUB_LDATE_LDATE(d, ld)", 30 * kDay},
    {"LTIME", "tod1 - ltod1", "SUB(tod1, ltod1)", "SUB_LTOD_LTOD(tod1, ltod1)", kDay - 2 * kSecond},
    {"LDT", nullptr, nullptr, "CONCAT_DATE_LTOD(d, tod1)", kJanuary31 + kDay - kSecond},
};

TEST(TimeArithmetic, EveryRowOfTable30InEachFormComputesItsValueAtItsType) {
    std::string variables;
    std::string body;
    for (std::size_t i = 0; i < std::size(kRows); ++i) {
        const Row& row = kRows[i];
        variables += fmt::format("    named{0}, operator{0}, overloaded{0} : {1};\n", i, row.type);
        body += fmt::format("named{} := {};\n", i, row.named);
        if (row.operation != nullptr) {
            body += fmt::format("operator{} := {};\noverloaded{} := {};\n", i, row.operation, i,
                                row.overloaded);
        }
    }
    StProgram run(
        fmt::format("PROGRAM Main\nVAR{}\n{}END_VAR\n{}END_PROGRAM\n", kInputs, variables, body));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    for (std::size_t i = 0; i < std::size(kRows); ++i) {
        const Row& row = kRows[i];
        SCOPED_TRACE(row.named);
        EXPECT_EQ(run.get<std::int64_t>(fmt::format("Main.named{}", i)), row.expected);
        if (row.operation != nullptr) {
            EXPECT_EQ(run.get<std::int64_t>(fmt::format("Main.operator{}", i)), row.expected);
            EXPECT_EQ(run.get<std::int64_t>(fmt::format("Main.overloaded{}", i)), row.expected);
        }
    }
}

// ADD and MUL are extensible (table 24): on times each step from left to right is a row of
// table 30, on variables as on constants (folded: a CONSTANT's initial value must be one).
TEST(TimeArithmetic, ExtensibleAddAndMulStepThroughTable30FromLeftToRight) {
    struct Extended {
        const char* type;
        const char* variables; ///< on the inputs
        const char* constants; ///< the same on literals
        std::int64_t expected;
    };
    const Extended kExtended[] = {
        {"TIME", "ADD(t, t, T#250ms)", "ADD(T#1s, T#1s, T#250ms)", 2 * kSecond + kSecond / 4},
        {"TOD", "ADD(tod1, t, t)", "ADD(TOD#23:59:59, T#1s, T#1s)", kSecond}, // past midnight
        {"LTOD", "ADD(tod1, lt, t)", "ADD(TOD#23:59:59, LTIME#2us, T#1s)", 2'000},
        {"LTIME", "ADD(t, lt, t, lt)", "ADD(T#1s, LTIME#2us, T#1s, LTIME#2us)",
         2 * kSecond + 4'000},
        {"DT", "ADD(dt1, t, T#1h)", "ADD(DT#2024-01-31-12:00:00, T#1s, T#1h)",
         kJanuary31 + kNoon + 3'601 * kSecond},
        {"TIME", "MUL(t, n, r)", "MUL(T#1s, 3, 2.5)", 7 * kSecond + kSecond / 2},
        {"LTIME", "MUL(lt, n, n, 2)", "MUL(LTIME#2us, 3, 3, 2)", 36'000},
    };
    // Each on variables into `variables<i>`; on literals into the CONSTANT `constants<i>`, which
    // `copy<i>` holds in the image.
    std::string variables;
    std::string constants;
    std::string body;
    for (std::size_t i = 0; i < std::size(kExtended); ++i) {
        const Extended& row = kExtended[i];
        variables += fmt::format("    variables{0}, copy{0} : {1};\n", i, row.type);
        constants += fmt::format("    constants{} : {} := {};\n", i, row.type, row.constants);
        body += fmt::format("variables{0} := {1};\ncopy{0} := constants{0};\n", i, row.variables);
    }
    StProgram run(fmt::format("PROGRAM Main\nVAR{}\n{}END_VAR\nVAR CONSTANT\n{}END_VAR\n{}"
                              "END_PROGRAM\n",
                              kInputs, variables, constants, body));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    for (std::size_t i = 0; i < std::size(kExtended); ++i) {
        SCOPED_TRACE(kExtended[i].variables);
        EXPECT_EQ(run.get<std::int64_t>(fmt::format("Main.variables{}", i)), kExtended[i].expected);
        EXPECT_EQ(run.get<std::int64_t>(fmt::format("Main.copy{}", i)), kExtended[i].expected);
    }
}

} // namespace
} // namespace eposp::compiler::test
