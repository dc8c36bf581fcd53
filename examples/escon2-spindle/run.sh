#!/usr/bin/env bash
# A spindle on a maxon ESCON2 commanded over wires (network.yaml): the program enables the
# ESCON2 and sets its speed as a voltage, then reads its ready output and its speed monitor
# back, for 2 s of virtual time.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/escon2-spindle/spindle.st examples/escon2-spindle/tests/*.st --network examples/escon2-spindle/network.yaml
#
# Usage: examples/escon2-spindle/run.sh [path/to/eposp]
. "$(dirname "${BASH_SOURCE[0]}")/../demo-common.sh"

section "A spindle on an ESCON2, commanded over wires (examples/escon2-spindle)"
"$eposp" run "$here/spindle.st" --network "$here/network.yaml" --for 2s \
    --watch Main.Ready --watch Main.ActualRpm --watch Main.AtSpeed
