#!/usr/bin/python3
"""A service tool on the EPOS P's CAN bus over socketcand (python-can): reads the EPOS P's device
type 0x1000 by SDO from node NODE and checks that SYNCs and the axes' PDOs pass by.

Usage: epos_p_service_tool.py HOST PORT NODE, against `eposp serve --socketcand HOST:PORT` with
examples/two-axis. Exit status: 0 when all was seen, 1 when not, 77 without python-can.
"""
import sys
import time

try:
    import can
except ImportError:
    print("python-can is not installed (Debian: python3-can)", file=sys.stderr)
    sys.exit(77)

host, port, node = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
bus = can.Bus(interface="socketcand", host=host, port=port, channel="external")
seen = set()
device_type = None
bus.send(can.Message(arbitration_id=0x600 + node, data=[0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0],
                     is_extended_id=False))
deadline = time.monotonic() + 5.0
while time.monotonic() < deadline and (device_type is None or len(seen) < 2):
    message = bus.recv(timeout=0.5)
    if message is None:
        continue
    if message.arbitration_id == 0x580 + node and bytes(message.data[1:4]) == b"\x00\x10\x00":
        device_type = int.from_bytes(message.data[4:8], "little")
    if message.arbitration_id in (0x080, 0x182):
        seen.add(message.arbitration_id)
bus.shutdown()
print(f"device type: {device_type:#010x}" if device_type is not None else "no SDO answer")
print("seen:", " ".join(f"{i:#05x}" for i in sorted(seen)))
sys.exit(0 if device_type == 0x195 and seen == {0x080, 0x182} else 1)
