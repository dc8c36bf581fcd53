#!/usr/bin/python3
"""Two python-can `socketcand` clients exchange frames through a socketcand server.

Usage: python_can_clients.py HOST PORT [CHANNEL]

Connects two python-can buses to the server (e.g. `eposp bus --socketcand HOST:PORT`), sends
standard and extended frames of every length 0..8 each way and checks that every frame arrives
at the other client intact, and only there. Exit status: 0 when all arrived, 1 when not,
77 (skipped) when python-can is not installed.
"""

import sys
import time

try:
    import can
except ImportError:
    print("python-can is not installed (Debian: python3-can)", file=sys.stderr)
    sys.exit(77)

DEADLINE_S = 10.0
# python-can before 4.2 writes extended identifiers without leading zeros, so the server can
# only tell them from standard ones by their value: keep extended identifiers above 0x7FF.
EXTENDED_BASE = 0x1ABC000


def frames(direction):
    """Standard and extended frames with 0..8 bytes, including bytes below 0x10, 0x00 and 0xFF."""
    result = []
    for length in range(9):
        data = bytes((direction * 0x40 + length * 0x1D + i * 0x0B) & 0xFF for i in range(length))
        result.append(can.Message(arbitration_id=0x100 * direction + length, data=data,
                                  is_extended_id=False))
        result.append(can.Message(arbitration_id=EXTENDED_BASE + 0x100 * direction + length,
                                  data=data[::-1], is_extended_id=True))
    result.append(can.Message(arbitration_id=0x7FF, data=b"\xff" * 8, is_extended_id=False))
    result.append(can.Message(arbitration_id=0x1FFFFFFF - direction, data=b"\x00",
                              is_extended_id=True))
    return result


def key(message):
    return (message.arbitration_id, bytes(message.data))


def receive(bus, count, deadline):
    received = []
    while len(received) < count and time.monotonic() < deadline:
        message = bus.recv(timeout=max(0.0, deadline - time.monotonic()))
        if message is not None:
            received.append(message)
    return received


def check(name, sent, received):
    """Compares as multisets: the bus arbitrates queued frames by identifier."""
    problems = []
    expected = sorted(key(m) for m in sent)
    got = sorted(key(m) for m in received)
    if got != expected:
        missing = [f"{i:X}#{d.hex()}" for i, d in expected if (i, d) not in got]
        extra = [f"{i:X}#{d.hex()}" for i, d in got if (i, d) not in expected]
        problems.append(f"{name}: {len(got)} of {len(expected)} frames; "
                        f"missing {missing}, unexpected {extra}")
    now = time.time()
    for message in received:
        if abs(message.timestamp - now) > 3600:
            problems.append(f"{name}: timestamp {message.timestamp} is not wall-clock time")
            break
    return problems


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 1
    host, port = argv[1], int(argv[2])
    channel = argv[3] if len(argv) == 4 else "can0"

    try:
        bus_a = can.Bus(interface="socketcand", channel=channel, host=host, port=port)
        bus_b = can.Bus(interface="socketcand", channel=channel, host=host, port=port)
    except (can.CanError, OSError) as error:
        print(f"cannot join bus {channel} at {host}:{port}: {error}", file=sys.stderr)
        return 1
    try:
        a_sends, b_sends = frames(1), frames(2)
        for message in a_sends:
            bus_a.send(message)
        for message in b_sends:
            bus_b.send(message)
        deadline = time.monotonic() + DEADLINE_S
        b_received = receive(bus_b, len(a_sends), deadline)
        a_received = receive(bus_a, len(b_sends), deadline)
        # Anything more would be a frame echoed back to its sender.
        a_received += receive(bus_a, 1, time.monotonic() + 0.2)
        b_received += receive(bus_b, 1, time.monotonic() + 0.2)
    finally:
        bus_a.shutdown()
        bus_b.shutdown()

    problems = check("a -> b", a_sends, b_received) + check("b -> a", b_sends, a_received)
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        return 1
    print(f"ok: {len(a_sends)} frames a -> b and {len(b_sends)} frames b -> a arrived intact")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
