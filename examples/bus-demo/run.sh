#!/usr/bin/env bash
# The demo of what exists so far: a simulated CAN bus exchanging frames.
#   1. A CANopen network's start-up (candump log) replayed onto a 1 Mbit/s bus in virtual time.
#   2. The same kind of bus in real time, joined over socketcand by two python-can clients that
#      exchange frames, as any outside CAN tool would.
# Each run prints the bus statistics and leaves a candump log and a pcap in build/demo/.
#
# Usage: examples/bus-demo/run.sh [path/to/eposp]
set -euo pipefail
eposp=$(realpath "${1:-build/device/eposp}")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${EPOSP_DEMO_DIR:-build/demo}
mkdir -p "$out"

section() { printf '\n\033[1m%s\033[0m\n' "$*"; }

section "1. Replaying a CANopen network's start-up onto a virtual 1 Mbit/s bus"
"$eposp" bus --virtual --replay "$here/canopen-network.log" --for 1s \
    --log "$out/replay.log" --pcap "$out/replay.pcap"
if command -v tshark >/dev/null; then
    echo "The first frames as Wireshark's CANopen dissector reads them:"
    tshark -r "$out/replay.pcap" -d can.subdissector=canopen 2>/dev/null | head -n 12
fi

section "2. A real-time bus joined by two python-can clients over socketcand"
: >"$out/socketcand.out" # no address of an earlier run may be read before the bus writes its own
"$eposp" bus --socketcand 127.0.0.1:0 --for 20s --log "$out/socketcand.log" \
    --pcap "$out/socketcand.pcap" >"$out/socketcand.out" &
bus_pid=$!
trap 'kill "$bus_pid" 2>/dev/null || true' EXIT
address=
for _ in $(seq 100); do # the bus prints its address once it listens
    address=$(sed -n 's/^socketcand: listening on \([^ ]*\).*/\1/p' "$out/socketcand.out")
    [ -n "$address" ] && break
    sleep 0.1
done
[ -n "$address" ] || { echo "the bus did not start:"; cat "$out/socketcand.out"; exit 1; }
/usr/bin/python3 "$here/python_can_clients.py" "${address%:*}" "${address##*:}"
kill -INT "$bus_pid"
wait "$bus_pid"
trap - EXIT
cat "$out/socketcand.out"
