// The checking stage on its own: the language rules it owns are reported from the typed
// program, without code generation (compiler/src/checks/, issue 17).
#include "checks/checks.hpp"
#include "eposp/compiler/types/front_end.hpp"

#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler {
namespace {

struct Checked {
    SourceManager sources;
    Diagnostics front_end_diagnostics;
    Diagnostics diagnostics; // the checks' alone
};

// Types `program` (and `library`, linked after it, when given) and runs the checks only.
std::vector<std::string> check(Checked& checked, const std::string& program,
                               const std::string& library = "",
                               const CompileOptions& options = {}) {
    std::vector<FileId> files{checked.sources.add("main.st", program)};
    if (!library.empty()) {
        files.push_back(checked.sources.add("library.st", library));
    }
    auto front_end = types::analyse(checked.sources, files, checked.front_end_diagnostics);
    EXPECT_NE(front_end->program, nullptr)
        << render(checked.front_end_diagnostics, checked.sources);
    std::vector<std::string> codes;
    if (front_end->program == nullptr) {
        return codes;
    }
    checks::check_program(*front_end->program, front_end->units, library.empty() ? 0 : 1, options,
                          checked.diagnostics);
    for (const Diagnostic& diagnostic : checked.diagnostics.all()) {
        codes.emplace_back(describe(diagnostic.code).name);
    }
    return codes;
}

using Codes = std::vector<std::string>;

TEST(ChecksStage, FindsRecursionThroughAnotherPou) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
FUNCTION Ping : INT
VAR_INPUT n : INT; END_VAR
Ping := Pong(n);
END_FUNCTION
FUNCTION Pong : INT
VAR_INPUT n : INT; END_VAR
Pong := Ping(n);
END_FUNCTION
PROGRAM Main
VAR x : INT; END_VAR
x := Ping(1);
END_PROGRAM
)st"),
              Codes{"E0407"});
}

TEST(ChecksStage, ReportsTheWarningsOfABody) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
FUNCTION Sign : INT
VAR_INPUT x : INT; END_VAR
VAR spare : INT; END_VAR
x := 0;
IF x > 0 THEN
    Sign := 1;
END_IF;
RETURN;
x := 1;
END_FUNCTION
PROGRAM Main
VAR n : INT; END_VAR
n := Sign(5);
END_PROGRAM
)st"),
              (Codes{"W0404", "W0405", "W0405", "W0401", "W0403"}));
}

TEST(ChecksStage, ChecksALibraryPouOnlyWhenTheProgramCallsIt) {
    const std::string library = R"st(
FUNCTION Called : INT
VAR unused_in_called : INT; END_VAR
Called := 1;
END_FUNCTION
FUNCTION NotCalled : INT
VAR unused_in_other : INT; END_VAR
NotCalled := 1;
END_FUNCTION
)st";
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
PROGRAM Main
VAR n : INT; END_VAR
n := Called();
END_PROGRAM
)st",
                    library),
              Codes{"W0401"});
    EXPECT_NE(render(checked.diagnostics, checked.sources).find("unused_in_called"),
              std::string::npos);
}

TEST(ChecksStage, RefusesConstantsOutsideTheBoundsAndWarnsOfCutStrings) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
TYPE Percent : INT (0..100); END_TYPE
FUNCTION Scale : INT
VAR_INPUT p : Percent; END_VAR
Scale := p;
END_FUNCTION
PROGRAM Main
VAR
    a : ARRAY[1..10] OF INT;
    p : Percent := 150;
    s : STRING[3];
    n : INT;
END_VAR
a[11] := 1;
p := 50 * 3;
n := Scale(-1);
s := 'abcdef';
END_PROGRAM
)st"),
              (Codes{"E0409", "E0410", "E0410", "E0410", "W0406"}));
}

TEST(ChecksStage, RefusesLoopExitsOutsideALoopAndConstantZeroDivisors) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
PROGRAM Main
VAR x, y : DINT := 7; END_VAR
WHILE x > 0 DO
    x := x - 1;
    EXIT;
END_WHILE;
x := y / (3 - 3) + y MOD 0 + DIV(y, 0) + y / 2;
CONTINUE;
END_PROGRAM
)st"),
              (Codes{"E0405", "E0408", "E0408", "E0408"}));
}

TEST(ChecksStage, RefusesCaseLabelsThatShareAValue) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
PROGRAM Main
VAR n : ULINT; x : INT; END_VAR
CASE n OF
    1..10: x := 1;
    5, 16#FFFF_FFFF_FFFF_FFFF: x := 2;
    11..20: x := 3;
    18446744073709551615: x := 4;
END_CASE;
END_PROGRAM
)st"),
              (Codes{"E0406", "E0406"}));
}

TEST(ChecksStage, RefusesWritingAForVariableAndStepsThatCannotEnd) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
PROGRAM Main
VAR i, j : INT; END_VAR
FOR i := 1 TO 10 DO
    FOR j := 1 TO 10 BY 0 DO
        i := 5;
    END_FOR;
    j := i;
    i := 2;
END_FOR;
END_PROGRAM
)st"),
              (Codes{"E0404", "E0402"}));
}

TEST(ChecksStage, RefusesTasksTheControllerCannotRun) {
    Checked checked;
    CompileOptions options;
    options.task_event_check = [](std::string_view event) -> std::optional<std::string> {
        if (event == "sync") {
            return std::nullopt;
        }
        return "not an event of this host";
    };
    EXPECT_EQ(check(checked, R"st(
CONFIGURATION Cell
VAR_GLOBAL count : INT; go : BOOL; END_VAR
RESOURCE Station ON PLC
    TASK Fast (INTERVAL := T#100us, PRIORITY := 1);
    TASK Once (SINGLE := count, PRIORITY := -1);
    {attribute 'event' := 'sync'}
    {attribute 'event' := 'sync'}
    TASK Synced (PRIORITY := 3);
    {attribute 'event' := 'sync'}
    TASK Both (INTERVAL := T#10ms, PRIORITY := 7);
    {attribute 'event' := 'tick'}
    TASK Refused (PRIORITY := 4);
    {attribute 'event' := ''}
    TASK Unnamed (PRIORITY := 5);
    TASK Triggered (SINGLE := go, PRIORITY := 6);
    PROGRAM Inst WITH Fast : Main;
END_RESOURCE
END_CONFIGURATION
PROGRAM Main
VAR x : INT; END_VAR
x := x + 1;
END_PROGRAM
)st",
                    "", options),
              (Codes{"E0421", "E0421", "E0421", "E0424", "E0424", "E0424", "E0424"}));
}

TEST(ChecksStage, RefusesAnyParametersAndWholeInstancesAssigned) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
FUNCTION Describe : INT
VAR_INPUT v : ANY; END_VAR
END_FUNCTION
FUNCTION_BLOCK Counter
VAR_OUTPUT n : INT; END_VAR
n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a, b : Counter; END_VAR
a();
a := b;
END_PROGRAM
)st"),
              (Codes{"W0403", "E0416", "E0412"}));
}

TEST(ChecksStage, RefusesProgramConnectionsToWhatCannotBeConnected) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
CONFIGURATION Cell
VAR_GLOBAL g : INT; END_VAR
RESOURCE Station ON PLC
    TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM A WITH Cyclic : Source (out => g);
    PROGRAM B WITH Cyclic : Sink (in := g + 1, total => 5);
    PROGRAM C WITH Cyclic : Sink (in := A.out, total => g);
END_RESOURCE
END_CONFIGURATION
PROGRAM Source
VAR_OUTPUT out : INT; END_VAR
out := 1;
END_PROGRAM
PROGRAM Sink
VAR_INPUT in : INT; END_VAR
VAR_OUTPUT total : INT; END_VAR
total := in;
END_PROGRAM
)st"),
              (Codes{"E0423", "E0423"}));
}

TEST(ChecksStage, RefusesTheSizeOfAConformantArray) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
FUNCTION Bytes : UDINT
VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
Bytes := SIZEOF(a) + SIZEOF(a[LOWER_BOUND(a, 1)]);
END_FUNCTION
PROGRAM Main
VAR values : ARRAY[1..4] OF INT; n : UDINT; END_VAR
n := Bytes(values);
END_PROGRAM
)st"),
              Codes{"E0417"});
}

TEST(ChecksStage, RefusesAForVariableThatIsNoLocalInteger) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
FUNCTION_BLOCK Walker
VAR_IN_OUT r : INT; END_VAR
VAR_OUTPUT n : INT; END_VAR
VAR i : INT; x : REAL; END_VAR
VAR CONSTANT c : INT := 3; END_VAR
FOR r := 1 TO 3 DO n := n + 1; END_FOR;
FOR x := 1.0 TO 3.0 DO n := n + 1; END_FOR;
FOR c := 1 TO 3 DO n := n + 1; END_FOR;
FOR i := 1 TO 3 DO n := n + i; END_FOR;
END_FUNCTION_BLOCK
)st"),
              (Codes{"E0403", "E0403", "E0403", "W0407"}));
}

TEST(ChecksStage, RefusesWritingWhatCannotBeWritten) {
    Checked checked;
    EXPECT_EQ(check(checked, R"st(
CONFIGURATION Cell
VAR_GLOBAL CONSTANT top : INT := 5; END_VAR
VAR_GLOBAL g : INT; END_VAR
VAR_ACCESS
    TopPath : top : INT READ_WRITE;
    TopRead : top : INT;
    GPath : g : INT READ_WRITE;
    InPath : %IW2 : WORD READ_WRITE;
    MainPath : M.x : INT READ_WRITE;
END_VAR
RESOURCE Station ON PLC
    TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM M WITH Cyclic : Main (total => top);
END_RESOURCE
END_CONFIGURATION
FUNCTION_BLOCK Counter
VAR_OUTPUT n : INT; END_VAR
n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR CONSTANT limit : INT := 10; END_VAR
VAR_EXTERNAL CONSTANT top : INT; END_VAR
VAR_EXTERNAL g : INT; END_VAR
VAR_OUTPUT total : INT; END_VAR
VAR c : Counter; w : WORD; ok : BOOL; x : INT; a : ARRAY[1..2] OF INT; END_VAR
c();
limit := 20;
top := 1;
g := top;
c.n := 1;
%IX0.0 := TRUE;
%QX0.0 := TRUE;
w.3 := TRUE;
a[1] := limit;
x := ABS(IN := x, ENO => ok);
total := x;
END_PROGRAM
)st"),
              (Codes{"E0401", "E0401", "E0401", "E0401", "E0401", "E0401", "E0401"}));
    ASSERT_EQ(checked.diagnostics.all().size(), 7U);
    // The note shows the declaration that forbids the write.
    EXPECT_EQ(checked.diagnostics.all()[0].notes.size(), 1U);
    EXPECT_EQ(checked.diagnostics.all()[0].notes[0].message, "'limit' is declared CONSTANT here");
}

TEST(ChecksStage, RefusesCallsOfTheWrongForm) {
    Checked checked;
    EXPECT_EQ(
        check(checked, R"st(
FUNCTION_BLOCK Accumulate
VAR_IN_OUT total : DINT; END_VAR
VAR_INPUT step : DINT; END_VAR
total := total + step;
END_FUNCTION_BLOCK
FUNCTION AddTo : BOOL
VAR_IN_OUT total : DINT; END_VAR
VAR_INPUT step : DINT; END_VAR
total := total + step;
AddTo := TRUE;
END_FUNCTION
PROGRAM Main
VAR acc : Accumulate; t : TON; sum : DINT; x : INT; ok : BOOL; END_VAR
acc(step := 1);
acc(total := sum, step := 1);
ok := AddTo(step := 2);
ok := AddTo(sum, 2);
ok := AddTo(total := sum, step := 1, step := 2);
x := LIMIT(MN := 0, IN := x, IN := 5, MX := 100);
x := LIMIT(0, IN := x, MX := 100);
t(TRUE, T#1s);
t(IN := TRUE, PT := T#1s, EN => ok);
x := ABS(x, EN := ok);
x := ABS(IN := x, ENO => ok);
END_PROGRAM
)st"),
        (Codes{"E0415", "E0415", "E0415", "E0415", "E0415", "E0413", "E0413", "E0414", "E0414"}));
}

} // namespace
} // namespace eposp::compiler
