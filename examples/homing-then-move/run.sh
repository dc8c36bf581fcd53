#!/usr/bin/env bash
# Homing, then moves, on one axis with the PLCopen motion blocks: the EPOS P boots an EPOS2 on
# its CAN bus as axis 1 (network.yaml; its machine with a home switch in machine.yaml), then
# homing-then-move.st powers the axis, writes its homing speeds, homes it on the switch
# (MC_Home, method 23) and visits three positions, for 6 s of virtual time. It prints the
# program's end state and the axis every 250 ms, and leaves the trace and its plot in
# build/demo/.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/homing-then-move/homing-then-move.st examples/homing-then-move/tests/*.st --network examples/homing-then-move/network.yaml
#
# Usage: examples/homing-then-move/run.sh [path/to/eposp]
. "$(dirname "${BASH_SOURCE[0]}")/../demo-common.sh"

section "Homing, then moves, on axis 1 (examples/homing-then-move)"
"$eposp" run "$here/homing-then-move.st" --network "$here/network.yaml" --for 6s \
    --trace "$out/homing-then-move.csv" --watch Main.Step --watch Main.Visited \
    --watch Main.Failed --watch Main.Position.Position

section "Axis 1 every 250 ms from $out/homing-then-move.csv (qc, rpm, PLCopen state)"
awk -F, 'NR > 1 && $2 == 1 && $1 * 1000 % 250 == 0 && $1 >= 0.5 {
        printf "%6.2f s   %7d qc %6d rpm   %s\n", $1, $7, $9, $11 }' "$out/homing-then-move.csv"
"$eposp" plot "$out/homing-then-move.csv" -o "$out/homing-then-move.svg"
