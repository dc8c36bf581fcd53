#!/usr/bin/env bash
# The main demo: the EPOS P boots a CANopen network of two EPOS2 drives (its internal one and one
# on its CAN bus), then a Structured Text program moves both axes to their targets through their
# controlwords and statuswords, in step with a 1 ms SYNC, for 5 s of virtual time. It prints
# the boot report and the axes' positions from the trace, and leaves the trace (axes.csv), a
# candump log of both buses and a pcap of the CAN bus in build/demo/.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/two-axis/two-axis.st examples/two-axis/tests/*.st --network examples/two-axis/network.yaml
#
# Usage: examples/two-axis/run.sh [path/to/eposp]
. "$(dirname "${BASH_SOURCE[0]}")/../demo-common.sh"

section "An ST program moving two axes on the EPOS P (examples/two-axis)"
"$eposp" run "$here/two-axis.st" --network "$here/network.yaml" --for 5s \
    --trace "$out/axes.csv" --can-log "$out/two-axis.log" --pcap "$out/two-axis.pcap" \
    --watch Cell.axis0.step --watch Cell.axis1.step --watch Cell.both_done

section "The axes every 100 ms once the network is up, from $out/axes.csv (quadcounts, rpm)"
awk -F, 'NR > 1 && $1 * 1000 % 100 == 0 && $1 >= 0.5 && $1 <= 1.5 {
        if ($2 == 0) { t = $1; p0 = $7; v0 = $9 } else { printf "%6.1f s   axis 0 %7d qc %6d rpm   axis 1 %7d qc %6d rpm\n", t, p0, v0, $7, $9 } }' \
    "$out/axes.csv"
echo "   ... both stay at their targets until 5 s."
