#!/usr/bin/python3
"""Browses a CANopen node's object dictionary over SDO, as a configuration tool would.

Usage: sdo_browse.py EDS NODE_ID HOST PORT [CHANNEL]

Joins the bus at a socketcand server (e.g. `eposp node --socketcand HOST:PORT`) with python-can
and, for every object and sub-index the EDS describes:
  - uploads it (expedited or segmented, as its size requires) and compares the value with the
    EDS DefaultValue ($NODEID taken into account); a write-only entry must refuse the upload
    with abort 0x06010001;
  - downloads the value read back to a read-write entry and uploads it again;
  - downloads to a read-only or constant entry, which must abort with 0x06010002;
and checks that a missing object aborts with 0x06020000 and a missing sub-index of a record with
0x06090011. Prints every problem and a summary. Exit status: 0 when the node behaved as its EDS
says, 1 when not, 77 (skipped) when python-can is not installed.

The SDO client follows CiA 301 7.2.4.3 (python-canopen is not packaged by Debian). Sub-objects
an EDS gives only through CompactSubObj are not browsed (our export_eds writes every one).
"""

import configparser
import re
import struct
import sys
import time

try:
    import can
except ImportError:
    print("python-can is not installed (Debian: python3-can)", file=sys.stderr)
    sys.exit(77)

TIMEOUT_S = 1.0  # CiA 301 leaves the SDO timeout to the client; the node answers in ms

# CiA 301 table 22: SDO abort codes this script expects.
ABORT_WRITE_ONLY = 0x06010001
ABORT_READ_ONLY = 0x06010002
ABORT_NO_OBJECT = 0x06020000
ABORT_NO_SUB_INDEX = 0x06090011

# CiA 301 table 44 (data types): sizes of the fixed-size ones, signedness by type.
FIXED_SIZE = {0x01: 1, 0x02: 1, 0x03: 2, 0x04: 4, 0x05: 1, 0x06: 2, 0x07: 4, 0x08: 4,
              0x0C: 6, 0x0D: 6, 0x10: 3, 0x11: 8, 0x12: 5, 0x13: 6, 0x14: 7, 0x15: 8,
              0x16: 3, 0x18: 5, 0x19: 6, 0x1A: 7, 0x1B: 8}
SIGNED = {0x02, 0x03, 0x04, 0x10, 0x12, 0x13, 0x14, 0x15}
REAL = {0x08: "<f", 0x11: "<d"}
VISIBLE_STRING = 0x09


class SdoAbort(Exception):
    def __init__(self, code):
        super().__init__(f"abort 0x{code:08X}")
        self.code = code


class SdoError(Exception):
    """A protocol violation or a missing answer."""


class SdoClient:
    """An SDO client for one server on the default SDO channel (0x600/0x580 + node-ID)."""

    def __init__(self, bus, node_id):
        self.bus = bus
        self.request_id = 0x600 + node_id
        self.response_id = 0x580 + node_id

    def _exchange(self, index, sub_index, request):
        self.bus.send(can.Message(arbitration_id=self.request_id, data=request,
                                  is_extended_id=False))
        deadline = time.monotonic() + TIMEOUT_S
        while time.monotonic() < deadline:
            message = self.bus.recv(timeout=max(0.0, deadline - time.monotonic()))
            if message is None or message.arbitration_id != self.response_id:
                continue
            data = bytes(message.data)
            if len(data) != 8:
                raise SdoError(f"response of {len(data)} bytes")
            if data[0] == 0x80:
                if int.from_bytes(data[1:3], "little") != index or data[3] != sub_index:
                    raise SdoError(f"abort for another object: {data.hex()}")
                raise SdoAbort(int.from_bytes(data[4:8], "little"))
            return data
        raise SdoError("no response")

    @staticmethod
    def _multiplexer(index, sub_index):
        return index.to_bytes(2, "little") + bytes([sub_index])

    def upload(self, index, sub_index):
        mux = self._multiplexer(index, sub_index)
        reply = self._exchange(index, sub_index, bytes([0x40]) + mux + bytes(4))
        if reply[0] & 0xE0 != 0x40 or reply[1:4] != mux:
            raise SdoError(f"bad initiate upload response {reply.hex()}")
        if reply[0] & 0x02:  # expedited (7.2.4.3.5)
            size = 4 - ((reply[0] >> 2) & 0x03) if reply[0] & 0x01 else 4
            return reply[4:4 + size]
        size = int.from_bytes(reply[4:8], "little") if reply[0] & 0x01 else None
        value = b""
        toggle = 0x00
        while True:  # segments (7.2.4.3.6)
            reply = self._exchange(index, sub_index, bytes([0x60 | toggle]) + bytes(7))
            if reply[0] & 0xE0 != 0x00 or reply[0] & 0x10 != toggle:
                raise SdoError(f"bad upload segment {reply.hex()}")
            value += reply[1:8 - ((reply[0] >> 1) & 0x07)]
            if reply[0] & 0x01:
                break
            toggle ^= 0x10
        if size is not None and size != len(value):
            raise SdoError(f"{len(value)} bytes uploaded, {size} indicated")
        return value

    def download(self, index, sub_index, value):
        mux = self._multiplexer(index, sub_index)
        if 0 < len(value) <= 4:  # expedited, size indicated (7.2.4.3.3)
            command = 0x23 | ((4 - len(value)) << 2)
            reply = self._exchange(index, sub_index,
                                   bytes([command]) + mux + value + bytes(4 - len(value)))
            if reply[0] != 0x60 or reply[1:4] != mux:
                raise SdoError(f"bad initiate download response {reply.hex()}")
            return
        reply = self._exchange(index, sub_index,
                               bytes([0x21]) + mux + len(value).to_bytes(4, "little"))
        if reply[0] != 0x60 or reply[1:4] != mux:
            raise SdoError(f"bad initiate download response {reply.hex()}")
        toggle = 0x00
        offset = 0
        while True:  # segments (7.2.4.3.4)
            chunk = value[offset:offset + 7]
            offset += len(chunk)
            last = offset >= len(value)
            command = toggle | ((7 - len(chunk)) << 1) | (0x01 if last else 0x00)
            reply = self._exchange(index, sub_index,
                                   bytes([command]) + chunk + bytes(7 - len(chunk)))
            if reply[0] != 0x20 | toggle:
                raise SdoError(f"bad download segment response {reply.hex()}")
            if last:
                return
            toggle ^= 0x10


def eds_number(text, node_id):
    """An EDS integer: decimal, 0x-hex or 0-octal, optionally $NODEID+... (CiA 306 4.6.3)."""
    total = 0
    for term in text.replace(" ", "").split("+"):
        if term.upper() == "$NODEID":
            total += node_id
        elif term.lower().startswith("0x"):
            total += int(term, 16)
        elif len(term) > 1 and term.startswith("0") and term.isdigit():
            total += int(term, 8)
        else:
            total += int(term, 10)
    return total


def eds_value(data_type, text, node_id):
    """The bytes of an EDS DefaultValue, little-endian as the SDO carries them."""
    if data_type == VISIBLE_STRING:
        return text.encode("latin-1")
    if data_type in REAL:
        return struct.pack(REAL[data_type], float(text))
    size = FIXED_SIZE.get(data_type)
    if size is None:  # OCTET_STRING, UNICODE_STRING, DOMAIN: hex pairs
        return bytes.fromhex(text.strip())
    number = eds_number(text, node_id) if text.strip() else 0
    return number.to_bytes(size, "little", signed=data_type in SIGNED and number < 0)


class Entry:
    """One sub-object as its EDS section describes it (keys compared without regard to case)."""

    def __init__(self, index, sub_index, section, node_id):
        self.index = index
        self.sub_index = sub_index
        self.name = section.get("parametername", "")
        self.access = section.get("accesstype", "ro").strip().lower()
        self.data_type = eds_number(section["datatype"], node_id)
        self.default = eds_value(self.data_type, section.get("defaultvalue", ""), node_id)

    def label(self):
        return f"0x{self.index:04X} sub {self.sub_index} ({self.name})"


def read_eds(path, node_id):
    """Every entry the EDS describes: [XXXX] of a VAR, [XXXXsubY] of an ARRAY or RECORD."""
    parser = configparser.ConfigParser(interpolation=None, strict=False)
    parser.optionxform = str.lower
    with open(path, encoding="latin-1") as eds:
        parser.read_file(eds)
    entries = []
    records = set()
    for name in parser.sections():
        section = parser[name]
        whole = re.fullmatch(r"([0-9A-F]{4})", name, re.IGNORECASE)
        sub = re.fullmatch(r"([0-9A-F]{4})sub([0-9A-F]{1,2})", name, re.IGNORECASE)
        # CiA 306 4.6.3: a VAR (0x7) or DOMAIN (0x2) object is one value at sub-index 0.
        if whole and eds_number(section.get("objecttype", "0x7"), node_id) in (0x2, 0x7):
            entries.append(Entry(int(whole[1], 16), 0, section, node_id))
        elif sub:
            records.add(int(sub[1], 16))
            entries.append(Entry(int(sub[1], 16), int(sub[2], 16), section, node_id))
    entries.sort(key=lambda e: (e.index, e.sub_index))
    return entries, records


def expect_abort(action, code):
    """None when `action` aborts with `code`, else what it did instead."""
    try:
        action()
    except SdoAbort as abort:
        return None if abort.code == code else f"abort 0x{abort.code:08X}"
    except SdoError as error:
        return str(error)
    return "no abort"


class Browse:
    def __init__(self, sdo):
        self.sdo = sdo
        self.problems = []
        self.counts = {"read": 0, "matched": 0, "written": 0, "refused writes": 0,
                       "write-only": 0}

    def problem(self, text):
        self.problems.append(text)
        print(f"MISMATCH {text}", file=sys.stderr)

    def entry(self, entry):
        if entry.access == "wo":
            if (got := expect_abort(lambda: self.sdo.upload(entry.index, entry.sub_index),
                                    ABORT_WRITE_ONLY)) is not None:
                self.problem(f"{entry.label()}: upload of a write-only entry: {got}")
            self.counts["write-only"] += 1
            return
        try:
            value = self.sdo.upload(entry.index, entry.sub_index)
        except (SdoAbort, SdoError) as error:
            self.problem(f"{entry.label()}: upload failed: {error}")
            return
        self.counts["read"] += 1
        if value == entry.default:
            self.counts["matched"] += 1
        else:
            self.problem(f"{entry.label()}: read {value.hex()}, EDS default "
                         f"{entry.default.hex()}")
        if entry.access in ("ro", "const"):
            if (got := expect_abort(lambda: self.sdo.download(entry.index, entry.sub_index,
                                                              value),
                                    ABORT_READ_ONLY)) is not None:
                self.problem(f"{entry.label()}: download to a read-only entry: {got}")
            self.counts["refused writes"] += 1
        else:
            self.write_back(entry, value)

    def write_back(self, entry, value):
        try:
            self.sdo.download(entry.index, entry.sub_index, value)
            again = self.sdo.upload(entry.index, entry.sub_index)
        except (SdoAbort, SdoError) as error:
            self.problem(f"{entry.label()}: writing back {value.hex()}: {error}")
            return
        if again != value:
            self.problem(f"{entry.label()}: wrote {value.hex()}, read back {again.hex()}")
        self.counts["written"] += 1

    def missing(self, entries, records):
        present = {e.index for e in entries}
        absent = next(i for i in range(0x2000, 0x6000) if i not in present)
        if (got := expect_abort(lambda: self.sdo.upload(absent, 0), ABORT_NO_OBJECT)) is not None:
            self.problem(f"0x{absent:04X}: upload of a missing object: {got}")
        if records:
            record = min(records)
            subs = {e.sub_index for e in entries if e.index == record}
            sub = next(s for s in range(1, 256) if s not in subs)
            if (got := expect_abort(lambda: self.sdo.upload(record, sub),
                                    ABORT_NO_SUB_INDEX)) is not None:
                self.problem(f"0x{record:04X} sub {sub}: upload of a missing sub-index: {got}")


def main(argv):
    if len(argv) not in (5, 6):
        print(__doc__, file=sys.stderr)
        return 1
    eds_path, node_id, host, port = argv[1], int(argv[2], 0), argv[3], int(argv[4])
    channel = argv[5] if len(argv) == 6 else "can0"
    try:
        entries, records = read_eds(eds_path, node_id)
    except (OSError, configparser.Error, KeyError, ValueError) as error:
        print(f"cannot read {eds_path}: {error}", file=sys.stderr)
        return 1
    try:
        bus = can.Bus(interface="socketcand", channel=channel, host=host, port=port)
    except (can.CanError, OSError) as error:
        print(f"cannot join bus {channel} at {host}:{port}: {error}", file=sys.stderr)
        return 1
    browse = Browse(SdoClient(bus, node_id))
    try:
        for entry in entries:
            browse.entry(entry)
        browse.missing(entries, records)
    finally:
        bus.shutdown()

    counts = ", ".join(f"{count} {name}" for name, count in browse.counts.items())
    print(f"browsed node {node_id}: {len(entries)} entries, {counts}, "
          f"{len(browse.problems)} mismatches")
    return 1 if browse.problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
