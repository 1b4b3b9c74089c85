"""List the CUDA fat-binary entries of a shared library, or keep only one architecture's.

    python tools/gpu/fatbin.py LIB                  # entries per (kind, sm) and their bytes
    python tools/gpu/fatbin.py LIB OUT 90 [elf]     # OUT: LIB with every entry but sm_90's
                                                    # (only its machine code with "elf")
                                                    # zeroed in place

Used to carry cufinufft to a GPU machine within a size limit (docs/performance.md,
section 4): the wheel holds machine code and PTX for 15 architectures; the zeroed entries
keep their headers and sizes (the library's layout is unchanged) and compress to nothing.
The CUDA driver loads the entry of the device's architecture and never reads the others.

The layout read here (a fat binary header, magic 0xBA55ED50, then entries of kind
1 = PTX or 2 = ELF, each with its header size, padded payload size and sm version) is
that of NVIDIA's fatbin format as written by nvcc and read by the tools of the CUDA
toolkit (``cuobjdump``); it is not an official interface.
"""

from __future__ import annotations

import struct
import sys
from collections import Counter

MAGIC = struct.pack("<I", 0xBA55ED50)


def entries(buf: bytes):
    """Yield each entry of each fat binary in ``buf``: dict(entry, kind, header,
    padded, payload, sm)."""
    pos = 0
    while True:
        i = buf.find(MAGIC, pos)
        if i < 0:
            return
        _, header_size, fat_size = struct.unpack_from("<HHQ", buf, i + 4)
        if header_size != 16 or fat_size == 0 or i + 16 + fat_size > len(buf):
            pos = i + 4
            continue
        p, end = i + 16, i + 16 + fat_size
        while p < end:
            kind, _, eh, padded = struct.unpack_from("<HHII", buf, p)
            (payload,) = struct.unpack_from("<I", buf, p + 16)
            (sm,) = struct.unpack_from("<I", buf, p + 28)
            yield {"entry": p, "kind": kind, "header": eh, "padded": padded,
                   "payload": payload, "sm": sm}
            if eh == 0:
                break
            p += eh + padded
        pos = end


def main() -> None:
    buf = bytearray(open(sys.argv[1], "rb").read())
    count, size = Counter(), Counter()
    for e in entries(buf):
        key = ({1: "ptx", 2: "elf"}.get(e["kind"], str(e["kind"])), e["sm"])
        count[key] += 1
        size[key] += e["padded"]
    for key in sorted(count, key=str):
        print(key, count[key], "entries,", size[key], "bytes")
    if len(sys.argv) > 3:
        sm = int(sys.argv[3])
        elf_only = len(sys.argv) > 4 and sys.argv[4] == "elf"
        blanked = 0
        for e in entries(buf):
            if not (e["sm"] == sm and (not elf_only or e["kind"] == 2)):
                a = e["entry"] + e["header"]
                buf[a:a + e["padded"]] = bytes(e["padded"])
                blanked += 1
        open(sys.argv[2], "wb").write(buf)
        print("zeroed", blanked, "entries")


if __name__ == "__main__":
    main()
