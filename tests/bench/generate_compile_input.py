#!/usr/bin/env python3
"""Writes Structured Text inputs for measuring compile time and memory (docs/performance.md).

  generate_compile_input.py variables N   one PROGRAM with N variables, each read and written
  generate_compile_input.py large LINES   about LINES lines of machine-like code: enumerations,
                                          structs, function blocks with timers, CASE state
                                          machines, FOR loops over arrays, functions, strings

The text goes to standard output and is the same on every run (no randomness), so that two
compilers are timed on the same file. Both compile without diagnostics.
"""

import sys

TYPES = ["DINT", "INT", "REAL", "BOOL", "UDINT", "LREAL", "WORD", "TIME"]


def update(name, type_name):
    """A statement that reads and writes `name` (so that no variable is unused)."""
    if type_name == "BOOL":
        return f"{name} := NOT {name};"
    if type_name in ("REAL", "LREAL"):
        return f"{name} := {name} * 0.5 + 1.0;"
    if type_name == "WORD":
        return f"{name} := {name} XOR 16#00FF;"
    if type_name == "TIME":
        return f"{name} := {name} + T#1ms;"
    return f"{name} := {name} + 1;"


def many_variables(count):
    out = ["PROGRAM Main", "  VAR CONSTANT"]
    constants = max(1, count // 10)
    out += [f"    k{i} : DINT := {i};" for i in range(constants)]
    out.append("  END_VAR")
    out.append("  VAR")
    out += [f"    v{i} : {TYPES[i % len(TYPES)]};" for i in range(count)]
    out.append("  END_VAR")
    for i in range(count):
        out.append("  " + update(f"v{i}", TYPES[i % len(TYPES)]))
        if TYPES[i % len(TYPES)] == "DINT":
            out.append(f"  v{i} := v{i} + k{i % constants};")
    out.append("END_PROGRAM")
    out += configuration(["Main"])
    return out


def configuration(programs):
    out = ["CONFIGURATION Cell", "  RESOURCE Cpu ON PLC",
           "    TASK Cyclic(INTERVAL := T#10ms, PRIORITY := 1);"]
    out += [f"    PROGRAM P{i} WITH Cyclic : {name};" for i, name in enumerate(programs)]
    out += ["  END_RESOURCE", "END_CONFIGURATION"]
    return out


def module(m):
    """About 190 lines: one station of a machine, with its types, blocks and program."""
    return f"""TYPE
  State{m} : (Idle{m}, Loading{m}, Moving{m}, Unloading{m}, Faulted{m});
  Item{m} : STRUCT
    state : State{m};
    pos : DINT;
    target : DINT;
    weight : INT;
    done : UDINT;
    label : STRING[20];
  END_STRUCT;
END_TYPE

FUNCTION Scale{m} : LREAL
  VAR_INPUT raw : DINT; gain : LREAL; offset : LREAL; END_VAR
  VAR clipped : DINT; END_VAR
  clipped := LIMIT(-10000, raw, 10000);
  Scale{m} := DINT_TO_LREAL(clipped) * gain + offset;
END_FUNCTION

FUNCTION Checksum{m} : DWORD
  VAR_INPUT a : DINT; b : DINT; c : DINT; END_VAR
  VAR acc : DWORD; i : INT; END_VAR
  acc := DINT_TO_DWORD(a);
  FOR i := 1 TO 8 DO
    acc := ROL(acc, 3) XOR DINT_TO_DWORD(b + INT_TO_DINT(i));
    IF (acc AND 16#1) <> 0 THEN
      acc := acc XOR DINT_TO_DWORD(c);
    END_IF;
  END_FOR;
  Checksum{m} := acc;
END_FUNCTION

FUNCTION_BLOCK Axis{m}
  VAR_INPUT enable : BOOL; target : DINT; speed : DINT := 10; END_VAR
  VAR_OUTPUT position : DINT; busy : BOOL; done : BOOL; error : BOOL; END_VAR
  VAR settle : TON; edge : R_TRIG; moves : UDINT; END_VAR
  edge(CLK := enable);
  IF edge.Q THEN
    moves := moves + 1;
  END_IF;
  IF NOT enable THEN
    busy := FALSE;
    done := FALSE;
  ELSIF position < target - speed THEN
    position := position + speed;
    busy := TRUE;
  ELSIF position > target + speed THEN
    position := position - speed;
    busy := TRUE;
  ELSE
    position := target;
    busy := FALSE;
  END_IF;
  settle(IN := enable AND NOT busy, PT := T#20ms);
  done := settle.Q;
  error := ABS(position) > 1000000;
END_FUNCTION_BLOCK

FUNCTION_BLOCK Station{m}
  VAR_INPUT tick : DINT; run : BOOL; END_VAR
  VAR_OUTPUT moved : DINT; finished : UDINT; alarm : BOOL; message : STRING[40]; END_VAR
  VAR
    items : ARRAY[0..31] OF Item{m};
    axis : Axis{m};
    blink : TON;
    count : CTU;
    i : INT;
    total : LREAL;
    code : DWORD;
  END_VAR
  moved := 0;
  FOR i := 0 TO 31 DO
    CASE items[i].state OF
      Idle{m}:
        IF run AND ((tick + INT_TO_DINT(i)) MOD 5) = 0 THEN
          items[i].state := Loading{m};
          items[i].weight := (i * 7) MOD 97;
          items[i].label := CONCAT('item ', INT_TO_STRING(i));
        END_IF;
      Loading{m}:
        items[i].target := items[i].pos + 10 + INT_TO_DINT(items[i].weight MOD 13);
        items[i].state := Moving{m};
      Moving{m}:
        IF items[i].pos < items[i].target THEN
          items[i].pos := items[i].pos + 1;
          moved := moved + 1;
        ELSE
          items[i].state := Unloading{m};
        END_IF;
      Unloading{m}:
        IF items[i].weight > 90 THEN
          items[i].state := Faulted{m};
        ELSE
          items[i].done := items[i].done + 1;
          items[i].state := Idle{m};
        END_IF;
      Faulted{m}:
        IF ((tick + INT_TO_DINT(i)) MOD 50) = 0 THEN
          items[i].state := Idle{m};
          items[i].weight := 0;
        END_IF;
    END_CASE;
  END_FOR;
  finished := 0;
  total := 0.0;
  FOR i := 0 TO 31 DO
    finished := finished + items[i].done;
    total := total + Scale{m}(raw := items[i].pos, gain := 0.25, offset := 1.5);
  END_FOR;
  axis(enable := run, target := tick MOD 1000, speed := 5);
  blink(IN := NOT blink.Q, PT := T#500ms);
  count(CU := blink.Q, R := NOT run, PV := 100);
  code := Checksum{m}(a := tick, b := moved, c := axis.position);
  alarm := axis.error OR count.Q OR total > 1.0E9;
  IF alarm THEN
    message := CONCAT('station {m}: ', DINT_TO_STRING(axis.position));
  ELSE
    message := '';
  END_IF;
END_FUNCTION_BLOCK

PROGRAM Line{m}
  VAR_EXTERNAL cycles : DINT; produced : UDINT; alarms : DINT; END_VAR
  VAR
    station : Station{m};
    ramp : LREAL;
    step : INT;
    history : ARRAY[1..8] OF DINT;
    k : INT;
  END_VAR
  station(tick := cycles, run := (cycles MOD 1000) < 900);
  produced := produced + station.finished;
  IF station.alarm THEN
    alarms := alarms + 1;
  END_IF;
  CASE step OF
    0: ramp := 0.0; step := 1;
    1: ramp := ramp + 0.1;
       IF ramp >= 10.0 THEN step := 2; END_IF;
    2: ramp := ramp - 0.1;
       IF ramp <= 0.0 THEN step := 0; END_IF;
  ELSE
    step := 0;
  END_CASE;
  FOR k := 8 TO 2 BY -1 DO
    history[k] := history[k - 1];
  END_FOR;
  history[1] := station.moved;
END_PROGRAM
""".splitlines()


def large(lines):
    per_module = len(module(0))
    out = []
    m = 0
    while len(out) + per_module + 12 < lines:
        out += module(m)
        out.append("")
        m += 1
    main = ["PROGRAM Main", "  VAR_EXTERNAL cycles : DINT; END_VAR", "  cycles := cycles + 1;",
            "END_PROGRAM"]
    out += main
    out += ["CONFIGURATION Cell",
            "  VAR_GLOBAL cycles : DINT; produced : UDINT; alarms : DINT; END_VAR",
            "  RESOURCE Cpu ON PLC",
            "    TASK Cyclic(INTERVAL := T#10ms, PRIORITY := 1);",
            "    PROGRAM Counter WITH Cyclic : Main;"]
    out += [f"    PROGRAM L{i} WITH Cyclic : Line{i};" for i in range(m)]
    out += ["  END_RESOURCE", "END_CONFIGURATION"]
    return out


def main(argv):
    if len(argv) != 3 or argv[1] not in ("variables", "large"):
        sys.exit(__doc__)
    count = int(argv[2])
    lines = many_variables(count) if argv[1] == "variables" else large(count)
    sys.stdout.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv)
