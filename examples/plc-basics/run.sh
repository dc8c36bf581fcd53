#!/usr/bin/env bash
# The PLC part of the demo: a Structured Text program compiled to a program image, the image
# disassembled, and its task run for two seconds of virtual time with two variables watched.
#
# Its unit tests (tests/*_test.st, in virtual time):
#   eposp test examples/plc-basics/blinker.st examples/plc-basics/tests/*.st
#
# Usage: examples/plc-basics/run.sh [path/to/eposp]
set -euo pipefail
eposp=$(realpath "${1:-build/device/eposp}")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${EPOSP_DEMO_DIR:-build/demo}
mkdir -p "$out"

section() { printf '\n\033[1m%s\033[0m\n' "$*"; }

section "The PLC alone: a Structured Text program compiled to a program image"
"$eposp" build "$here/blinker.st" -o "$out/blinker.epx"
"$eposp" dump "$out/blinker.epx" | sed -n '/^tasks:/,/^$/p'

section "Its task run for 2 s of virtual time"
"$eposp" run "$out/blinker.epx" --for 2s --watch Cell.flashes --watch Cell.lamp
