#!/usr/bin/env bash
# A conveyor in velocity mode started by a drive's digital input: the EPOS P boots its internal
# EPOS2 (axis 0, the belt) and an EPOS2 on its CAN bus (axis 1, the pusher, whose part sensor is
# its drive's home switch input; network.yaml, pusher.yaml). conveyor.st pushes parts onto the
# belt, and each time the sensor sees a part it runs the belt with MC_MoveVelocity for 1.2 s and
# stops it with MC_Halt, for 8 s of virtual time. It prints the count of parts and both axes
# every 250 ms, and leaves the trace and its plot in build/demo/.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/conveyor/conveyor.st examples/conveyor/tests/*.st --network examples/conveyor/network.yaml
#
# Usage: examples/conveyor/run.sh [path/to/eposp]
. "$(dirname "${BASH_SOURCE[0]}")/../demo-common.sh"

section "A conveyor started by a drive's digital input (examples/conveyor)"
"$eposp" run "$here/conveyor.st" --network "$here/network.yaml" --for 8s \
    --trace "$out/conveyor.csv" --watch Main.Parts --watch Main.Failed

section "The belt (axis 0) and the pusher (axis 1) every 250 ms from $out/conveyor.csv"
awk -F, 'NR > 1 && $1 * 1000 % 250 == 0 && $1 >= 0.5 {
        if ($2 == 0) { t = $1; p0 = $7; v0 = $9; s0 = $11 } else {
        printf "%6.2f s   belt %7d qc %5d rpm %-16s   pusher %6d qc %5d rpm\n", t, p0, v0, s0, $7, $9 } }' \
    "$out/conveyor.csv"
"$eposp" plot "$out/conveyor.csv" -o "$out/conveyor.svg"
