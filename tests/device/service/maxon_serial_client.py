#!/usr/bin/python3
"""An independent client of maxon's serial protocols, written from the protocol description of
issue 14 alone (no eposp code): v1 (RS-232: handshakes, Len-1) and v2 (USB: 0x90 0x02 frames with
byte stuffing), ReadObject, WriteObject and segmented read and write.

Usage:
  maxon_serial_client.py selftest          the issue's byte vectors, no device needed
  maxon_serial_client.py PORT v1|v2 IMAGE  against a device on serial PORT: reads 0x1000,
                                           writes and reads back 0x5005, reads 0x1008 by
                                           segmented read, writes IMAGE (an .epx) to 0x1F50 sub 1
                                           by segmented write and reads it back
Exit status: 0 when every check passed, 1 when not, 77 without pyserial.
"""
import struct
import sys

READ_OBJECT = 0x10
WRITE_OBJECT = 0x11
INITIATE_SEGMENTED_READ = 0x12
INITIATE_SEGMENTED_WRITE = 0x13
SEGMENT_READ = 0x14
SEGMENT_WRITE = 0x15
DLE, STX = 0x90, 0x02
READY, NOT_READY = ord("O"), ord("F")


def crc(words):
    """CRC-CCITT, polynomial 0x1021, initial 0, MSB first, over 16-bit words plus one 0x0000."""
    value = 0
    for word in list(words) + [0]:
        for bit in range(15, -1, -1):
            carry = value & 0x8000
            value = ((value << 1) | ((word >> bit) & 1)) & 0xFFFF
            if carry:
                value ^= 0x1021
    return value


def words_of(data):
    """Little-endian 16-bit words of an even-length byte string."""
    return [data[i] | data[i + 1] << 8 for i in range(0, len(data), 2)]


def pad(data):
    return data + b"\x00" if len(data) % 2 else data


# --- v1 (RS-232) ---------------------------------------------------------------------------


def v1_frame_rest(opcode, data):
    """What follows the opcode once the device said 'O': Len-1, the words, the CRC."""
    data = pad(data)
    length = len(data) // 2 - 1
    check = crc([opcode << 8 | length] + words_of(data))
    return bytes([length]) + data + struct.pack("<H", check)


def v1_answer_check(length, data):
    return crc([0x00 << 8 | length] + words_of(data))


# --- v2 (USB) ------------------------------------------------------------------------------


def v2_encode(opcode, data):
    data = pad(data)
    length = len(data) // 2
    check = crc([length << 8 | opcode] + words_of(data))
    body = bytes([opcode, length]) + data + struct.pack("<H", check)
    return bytes([DLE, STX]) + body.replace(bytes([DLE]), bytes([DLE, DLE]))


class V2Decoder:
    """Finds frames in bytes: 0x90 0x90 is a data byte 0x90, 0x90 0x02 starts a new frame."""

    def __init__(self):
        self.frames = []
        self.body = None
        self.escaped = False

    def feed(self, data):
        for byte in data:
            if self.escaped:
                self.escaped = False
                if byte == STX:
                    self.body = bytearray()
                    continue
                if byte != DLE or self.body is None:
                    self.body = None  # a stuffing error: wait for the next frame
                    continue
            elif byte == DLE:
                self.escaped = True
                continue
            if self.body is None:
                continue
            self.body.append(byte)
            if len(self.body) >= 2 and len(self.body) == 2 + 2 * self.body[1] + 2:
                opcode, length = self.body[0], self.body[1]
                data = bytes(self.body[2:-2])
                (check,) = struct.unpack("<H", self.body[-2:])
                if check == crc([length << 8 | opcode] + words_of(data)):
                    self.frames.append((opcode, data))
                self.body = None


# --- commands ------------------------------------------------------------------------------


def object_parameters(index, sub, node):
    return struct.pack("<HBB", index, sub, node)


class Client:
    def __init__(self, port, protocol):
        self.port = port
        self.protocol = protocol
        self.decoder = V2Decoder()

    def read(self, count):
        data = self.port.read(count)
        if len(data) != count:
            raise IOError(f"timeout: {len(data)} of {count} bytes")
        return data

    def expect_ready(self, stage):
        reply = self.read(1)[0]
        if reply != READY:
            raise IOError(f"device answered {reply:#04x} to the {stage}")

    def request(self, opcode, data):
        """Sends a frame and returns (error code, answer data after the error code)."""
        if self.protocol == "v1":
            self.port.write(bytes([opcode]))
            self.expect_ready("opcode")
            self.port.write(v1_frame_rest(opcode, data))
            self.expect_ready("frame")
            if self.read(1)[0] != 0x00:
                raise IOError("the answer does not begin with opcode 0x00")
            self.port.write(bytes([READY]))
            length = self.read(1)[0]
            answer = self.read(2 * (length + 1))
            (check,) = struct.unpack("<H", self.read(2))
            if check != v1_answer_check(length, answer):
                self.port.write(bytes([NOT_READY]))
                raise IOError("answer CRC wrong")
            self.port.write(bytes([READY]))
        else:
            self.port.write(v2_encode(opcode, data))
            while not self.decoder.frames:
                chunk = self.port.read(1)
                if not chunk:
                    raise IOError("timeout waiting for a v2 answer")
                self.decoder.feed(chunk + self.port.read(self.port.in_waiting))
            opcode_back, answer = self.decoder.frames.pop(0)
            if opcode_back != 0x00:
                raise IOError(f"answer opcode {opcode_back:#04x}")
        (error,) = struct.unpack("<I", answer[:4])
        return error, answer[4:]

    def read_object(self, index, sub, node=0):
        error, data = self.request(READ_OBJECT, object_parameters(index, sub, node))
        return error, data[:4]

    def write_object(self, index, sub, value, node=0):
        parameters = object_parameters(index, sub, node) + struct.pack("<I", value)
        return self.request(WRITE_OBJECT, parameters)[0]

    def write_segmented(self, index, sub, value, node=0):
        parameters = object_parameters(index, sub, node) + struct.pack("<I", len(value))
        error, _ = self.request(INITIATE_SEGMENTED_WRITE, parameters)
        toggle, position = 0, 0
        while error == 0:
            segment = value[position:position + 63]
            more = position + len(segment) < len(value)
            control = len(segment) | toggle << 6 | more << 7
            error, _ = self.request(SEGMENT_WRITE, bytes([control]) + segment)
            position += len(segment)
            toggle ^= 1
            if not more:
                break
        return error

    def read_segmented(self, index, sub, node=0):
        error, _ = self.request(INITIATE_SEGMENTED_READ, object_parameters(index, sub, node))
        value, toggle = b"", 0
        while error == 0:
            error, answer = self.request(SEGMENT_READ, bytes([toggle << 6]))
            if error:
                break
            control = answer[0]
            if (control >> 6 & 1) != toggle:
                raise IOError("segment with a wrong toggle")
            value += answer[1:1 + (control & 0x3F)]
            toggle ^= 1
            if not control & 0x80:
                break
        return error, value


# --- checks --------------------------------------------------------------------------------


def selftest():
    failures = []

    def check(name, got, expected):
        if got != expected:
            failures.append(f"{name}: {got.hex(' ')} != {expected.hex(' ')}")

    # v1: ReadObject 0x6041/0 node 0, and the answer err 0, value 0x00000637.
    check("v1 ReadObject", bytes([READ_OBJECT]) + v1_frame_rest(READ_OBJECT,
                                                                object_parameters(0x6041, 0, 0)),
          bytes.fromhex("10 01 41 60 00 00 9A C3"))
    answer = struct.pack("<II", 0, 0x637)
    check("v1 answer", bytes([0x00, 3]) + answer + struct.pack("<H", v1_answer_check(3, answer)),
          bytes.fromhex("00 03 00 00 00 00 37 06 00 00 E8 4A"))
    # v2: ReadObject node 1, WriteObject 0x607A = 0x90 (stuffed), and the answer.
    check("v2 ReadObject", v2_encode(READ_OBJECT, object_parameters(0x6041, 0, 1)),
          bytes.fromhex("90 02 10 02 41 60 00 01 64 CF"))
    write = v2_encode(WRITE_OBJECT, object_parameters(0x607A, 0, 1) + struct.pack("<I", 0x90))
    check("v2 WriteObject", write, bytes.fromhex("90 02 11 04 7A 60 00 01 90 90 00 00 00 E6 D2"))
    encoded_answer = bytes.fromhex("90 02 00 04 00 00 00 00 37 06 00 00 99 CA")
    check("v2 answer", v2_encode(0x00, answer), encoded_answer)
    decoder = V2Decoder()
    decoder.feed(b"\x55" + write[:5] + encoded_answer)  # noise, a frame cut short, a whole one
    if decoder.frames != [(0x00, answer)]:
        failures.append(f"v2 decoder: {decoder.frames}")
    decoder.feed(write)
    if decoder.frames[-1] != (WRITE_OBJECT, object_parameters(0x607A, 0, 1) + b"\x90\0\0\0"):
        failures.append(f"v2 decoder unstuffing: {decoder.frames}")
    for failure in failures:
        print("FAIL", failure)
    print("selftest:", "ok" if not failures else f"{len(failures)} failures")
    return 0 if not failures else 1


def against_device(path, protocol, image_path):
    try:
        import serial
    except ImportError:
        print("pyserial is not installed (Debian: python3-serial)", file=sys.stderr)
        return 77
    port = serial.Serial(path, 115200, timeout=3)
    client = Client(port, protocol)
    failures = []

    def check(name, got, expected):
        print(f"{name}: {got!r}")
        if got != expected:
            failures.append(f"{name}: {got!r} != {expected!r}")

    error, data = client.read_object(0x1000, 0)
    check("device type", (error, struct.unpack("<I", data)[0]), (0, 0x195))
    check("write 0x5005", client.write_object(0x5005, 0, 600), 0)
    error, data = client.read_object(0x5005, 0)
    check("read 0x5005", (error, struct.unpack("<I", data)[0] & 0xFFFF), (0, 600))
    check("missing object", client.read_object(0x1234, 0)[0], 0x06020000)
    check("device name", client.read_segmented(0x1008, 0), (0, b"EPOS P"))
    with open(image_path, "rb") as image_file:
        image = image_file.read()
    check("download", client.write_segmented(0x1F50, 1, image), 0)
    error, stored = client.read_segmented(0x1F50, 1)
    check("image read back", (error, len(stored), stored == image), (0, len(image), True))
    port.close()
    print(f"{protocol}:", "ok" if not failures else "; ".join(failures))
    return 0 if not failures else 1


if __name__ == "__main__":
    if sys.argv[1:] == ["selftest"]:
        sys.exit(selftest())
    if len(sys.argv) != 4 or sys.argv[2] not in ("v1", "v2"):
        sys.exit(__doc__)
    sys.exit(against_device(*sys.argv[1:]))
