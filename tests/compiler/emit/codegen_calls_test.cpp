// Calls compiled and run: functions (formal, positional, default inputs, outputs, VAR_IN_OUT,
// nested calls), FB instances (also in arrays), programs in a configuration.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(FunctionCall, FormalPositionalDefaultsOutputsAndInOut) {
    StProgram run(R"(
FUNCTION Scale : DINT
  VAR_INPUT v : DINT; k : DINT := 10; END_VAR
  VAR_OUTPUT twice : DINT; END_VAR
  VAR_IN_OUT acc : DINT; END_VAR
  VAR tmp : DINT := 1; END_VAR
  tmp := tmp + 1;
  acc := acc + v;
  twice := 2 * v;
  Scale := v * k + tmp;
END_FUNCTION

FUNCTION Add3 : INT
  VAR_INPUT a, b, c : INT; END_VAR
  Add3 := a + b + c;
END_FUNCTION

PROGRAM Main
VAR a, b, c, d, acc, t : DINT; n : INT; END_VAR
a := Scale(v := 3, acc := acc);
b := Scale(v := 3, k := 2, acc := acc, twice => t);
c := Scale(Scale(v := 1, acc := acc), 1, acc);
n := Add3(1, Add3(2, 3, 4), 5);
d := acc;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.a"), 32); // 3 * 10 + 2: tmp starts at 1 every call
    EXPECT_EQ(run.get<std::int32_t>("Main.b"), 8);
    EXPECT_EQ(run.get<std::int32_t>("Main.t"), 6);
    EXPECT_EQ(run.get<std::int32_t>("Main.c"), 14); // Scale(12, 1) = 12 + 2
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 15);
    EXPECT_EQ(run.get<std::int32_t>("Main.d"), 3 + 3 + 1 + 12);
}

TEST(FunctionBlockCall, InstancesKeepTheirStateAndOutputs) {
    StProgram run(R"(
FUNCTION_BLOCK Counter
  VAR_INPUT step : INT := 1; END_VAR
  VAR_OUTPUT value : INT; END_VAR
  VAR_IN_OUT total : DINT; END_VAR
  value := value + step;
  total := total + step;
END_FUNCTION_BLOCK

PROGRAM Main
VAR c1, c2 : Counter; arr : ARRAY[1..3] OF Counter; i : INT; v1, v2, s : INT; total : DINT; END_VAR
c1(total := total);
c2(step := 5, total := total, value => v2);
v1 := c1.value;
FOR i := 1 TO 3 DO arr[i](step := i, total := total); END_FOR;
s := arr[1].value + arr[2].value + arr[3].value;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.v1"), 3);
    EXPECT_EQ(run.get<std::int16_t>("Main.v2"), 15);
    EXPECT_EQ(run.get<std::int16_t>("Main.s"), 18);
    EXPECT_EQ(run.get<std::int32_t>("Main.total"), 3 * (1 + 5 + 6));
    EXPECT_EQ(run.get<std::int16_t>("Main.arr[2].value"), 6);
}

TEST(Configuration, ProgramConnectionsCopyInputsBeforeAndOutputsAfter) {
    StProgram run(R"(
PROGRAM Doubler
  VAR_INPUT v : DINT; k : DINT; END_VAR
  VAR_OUTPUT twice : DINT; END_VAR
  twice := v * 2 + k;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL source : DINT := 21; sink : DINT; END_VAR
  RESOURCE Cpu ON PLC
    TASK T(INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM D WITH T : Doubler (v := source, k := 100, twice => sink);
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Cell.sink"), 142);
}

TEST(Configuration, GlobalsTasksAndInstancesByPath) {
    StProgram run(R"(
PROGRAM Prog
  VAR_EXTERNAL g : DINT; END_VAR
  VAR count : DINT := 100; END_VAR
  count := count + 1;
  g := g + count;
END_PROGRAM

CONFIGURATION Cell
  VAR_GLOBAL g : DINT := 5; END_VAR
  RESOURCE Cpu ON PLC
    TASK Fast(INTERVAL := T#2ms, PRIORITY := 1);
    PROGRAM P1 WITH Fast : Prog;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(2)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("P1.count"), 102);
    EXPECT_EQ(run.get<std::int32_t>("Cell.g"), 5 + 101 + 102);
}

} // namespace
} // namespace eposp::compiler::test

namespace eposp::compiler::test {
namespace {

TEST(FunctionBlockCall, VarTempStartsFromItsInitialValueAtEachCall) {
    StProgram run(R"(
FUNCTION_BLOCK Acc
  VAR_OUTPUT kept, fresh : INT; END_VAR
  VAR_TEMP t : INT := 10; END_VAR
  t := t + 1;
  fresh := t;
  kept := kept + t;
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; END_VAR
a();
a();
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.a.fresh"), 11);
    EXPECT_EQ(run.get<std::int16_t>("Main.a.kept"), 22);
}

TEST(EnableInputs, EnFalseSkipsTheCallAndEnoTellsWhetherItRan) {
    StProgram run(R"(
FUNCTION Inc : DINT
  VAR_INPUT v : DINT; END_VAR
  Inc := v + 1;
END_FUNCTION
FUNCTION_BLOCK Count
  VAR_OUTPUT n : INT; END_VAR
  n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : Count; off : BOOL; eno1, eno2, eno3 : BOOL := TRUE; x : DINT; y : DINT := 5; END_VAR
c(EN := off, ENO => eno1);
c(EN := NOT off, ENO => eno2);
x := Inc(v := 41, EN := TRUE);
y := Inc(EN := off, v := 1, ENO => eno3);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.c.n"), 1);
    EXPECT_FALSE(run.get<bool>("Main.eno1"));
    EXPECT_TRUE(run.get<bool>("Main.eno2"));
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 42);
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 5); // a skipped call leaves its target as it was
    EXPECT_FALSE(run.get<bool>("Main.eno3"));
}

TEST(NestedData, StructsArraysReferencesAndInOutArrays) {
    StProgram run(R"(
TYPE
  Inner : STRUCT a : INT; b : ARRAY[1..3] OF DINT; END_STRUCT;
  Outer : STRUCT name : STRING[10] := 'xy'; inner : Inner; list : ARRAY[0..1] OF Inner; END_STRUCT;
  Level : INT (Low := 1, High := 5);
END_TYPE
FUNCTION MakeInner : Inner
  VAR_INPUT v : INT; END_VAR
  MakeInner.a := v;
  MakeInner.b[2] := v * 2;
END_FUNCTION
FUNCTION_BLOCK Summer
  VAR_IN_OUT data : ARRAY[1..3] OF DINT; END_VAR
  VAR_OUTPUT total : DINT; END_VAR
  VAR i : INT; END_VAR
  total := 0;
  FOR i := 1 TO 3 DO total := total + data[i]; END_FOR;
  IF total > 100 THEN RETURN; END_IF;
  data[1] := data[1] + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  o : Outer; p : REF_TO Outer; lv : Level := High; names : ARRAY[1..2] OF STRING[4];
  s : Summer; tot, k : DINT; u : UINT; w : WSTRING := "wide"; n, got : INT;
END_VAR
o.inner := MakeInner(7);
o.list[1] := MakeInner(3);
p := REF(o);
p^.inner.b[1] := 5;
p^.list[1].b[3] := 9;
names[2] := 'abcdefg';
s(data := o.inner.b, total => tot);
FOR u := 10 TO 12 DO k := k + UINT_TO_DINT(u); END_FOR;
CASE lv OF Low: got := 1; High: got := 5; END_CASE;
n := LEN(w);
REPEAT k := k + 1; IF k > 40 THEN EXIT; END_IF; UNTIL FALSE END_REPEAT;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.o.inner.a"), 7);
    EXPECT_EQ(run.get<std::int32_t>("Main.o.inner.b[1]"), 6);
    EXPECT_EQ(run.get<std::int32_t>("Main.o.inner.b[2]"), 14);
    EXPECT_EQ(run.get<std::int16_t>("Main.o.list[1].a"), 3);
    EXPECT_EQ(run.get<std::int32_t>("Main.o.list[1].b[3]"), 9);
    EXPECT_EQ(run.get<std::int32_t>("Main.tot"), 19);
    EXPECT_EQ(run.get<std::int32_t>("Main.k"), 41);
    EXPECT_EQ(run.get<std::int16_t>("Main.got"), 5);
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 4);
    EXPECT_EQ(run.get_string("Main.names[2]"), "abcd");
    EXPECT_EQ(run.get_string("Main.o.name"), "xy");
}

} // namespace
} // namespace eposp::compiler::test
