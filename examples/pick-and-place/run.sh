#!/usr/bin/env bash
# A two-axis pick-and-place cell with the PLCopen motion blocks: the EPOS P boots its network
# (the internal EPOS2 as axis 0, an EPOS2 on the CAN bus as axis 1; the network file of
# examples/two-axis), then pick-and-place.st powers and homes both axes and runs three cycles of
# moves with MC_MoveAbsolute, for 10 s of virtual time. It prints the cell's step and cycle
# count, the axes every 250 ms from the trace, and leaves the trace and its plot in build/demo/.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/pick-and-place/pick-and-place.st examples/pick-and-place/tests/*.st --network examples/two-axis/network.yaml
#
# Usage: examples/pick-and-place/run.sh [path/to/eposp]
. "$(dirname "${BASH_SOURCE[0]}")/../demo-common.sh"

section "A pick-and-place cell with MC_Power, MC_Home and MC_MoveAbsolute (examples/pick-and-place)"
"$eposp" run "$here/pick-and-place.st" --network "$here/../two-axis/network.yaml" --for 10s \
    --trace "$out/pick-and-place.csv" --watch Main.Cycles --watch Main.Step --watch Main.Failed

section "The carriage (axis 0) and the lift (axis 1) every 250 ms, from $out/pick-and-place.csv"
awk -F, 'NR > 1 && $1 * 1000 % 250 == 0 && $1 >= 0.5 && $1 <= 7 {
        if ($2 == 0) { t = $1; p0 = $7; v0 = $9 } else { printf "%6.2f s   carriage %7d qc %6d rpm   lift %7d qc %6d rpm\n", t, p0, v0, $7, $9 } }' \
    "$out/pick-and-place.csv"
"$eposp" plot "$out/pick-and-place.csv" -o "$out/pick-and-place.svg"
