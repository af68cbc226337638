#!/usr/bin/env python3
"""Writes a candump log as a pcap file of SocketCAN frames (LINKTYPE_CAN_SOCKETCAN, 227).

    candump2pcap.py LOG PCAP

Reads the line forms of `powerkey decode` that the sample logs use: `(time) iface ID#DATA` and a
bare `ID#DATA`; blank lines and lines starting with '#' or '//' are skipped. A 3-digit ID is an
11-bit frame, an 8-digit one a 29-bit frame (CAN_EFF_FLAG set). Frames without a timestamp get
0.001 s steps. Exits with status 1 on a line it cannot read, naming it.
"""
import struct
import sys

LINKTYPE_CAN_SOCKETCAN = 227
CAN_EFF_FLAG = 0x80000000


def frames(path):
    with open(path, encoding="ascii") as log:
        for number, text in enumerate(log, 1):
            line = text.strip()
            if not line or line.startswith("#") or line.startswith("//"):
                continue
            parts = line.split()
            when = None
            if parts[0].startswith("(") and parts[0].endswith(")"):
                when = float(parts[0][1:-1])
            ident, sep, data = parts[-1].partition("#")
            if not sep or len(ident) not in (3, 8) or len(data) % 2 or len(data) > 16:
                sys.exit(f"candump2pcap: {path}:{number}: not an ID#DATA frame: {line}")
            try:
                can_id = int(ident, 16)
                payload = bytes.fromhex(data)
            except ValueError:
                sys.exit(f"candump2pcap: {path}:{number}: not hex: {line}")
            if len(ident) == 8:
                can_id |= CAN_EFF_FLAG
            yield when, can_id, payload


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: candump2pcap.py LOG PCAP")
    with open(sys.argv[2], "wb") as out:
        # pcap global header: magic, version 2.4, zone 0, sigfigs 0, snaplen, link type.
        out.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, LINKTYPE_CAN_SOCKETCAN))
        for n, (when, can_id, payload) in enumerate(frames(sys.argv[1])):
            if when is None:
                when = n / 1000
            seconds = int(when)
            micros = int(round((when - seconds) * 1e6))
            # SocketCAN header: can_id in network byte order, length, 3 reserved bytes; then data.
            record = struct.pack(">IB3x", can_id, len(payload)) + payload
            out.write(struct.pack("<IIII", seconds, micros, len(record), len(record)))
            out.write(record)


if __name__ == "__main__":
    main()
