#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""make_ico.py OUT.ico IMAGE.png...: one Windows icon of PNG images (square, at most 256 px).

Windows Vista and later read PNG entries in an .ico, so the PNGs go in as they are: the format
is a 6-byte header, a 16-byte entry per image, then the images.
"""
import struct
import sys


def png_size(data, name):
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        sys.exit(f"make_ico.py: {name}: not a PNG")
    width, height = struct.unpack(">II", data[16:24])
    if width != height or not 1 <= width <= 256:
        sys.exit(f"make_ico.py: {name}: {width}x{height}, not square up to 256 px")
    return width


def main(out, pngs):
    images = []
    for name in pngs:
        with open(name, "rb") as f:
            data = f.read()
        images.append((png_size(data, name), data))
    header = struct.pack("<HHH", 0, 1, len(images))
    offset = len(header) + 16 * len(images)
    entries, blobs = b"", b""
    for size, data in images:
        side = 0 if size == 256 else size  # 0 means 256 in an icon entry
        entries += struct.pack("<BBBBHHII", side, side, 0, 0, 1, 32, len(data), offset)
        blobs += data
        offset += len(data)
    with open(out, "wb") as f:
        f.write(header + entries + blobs)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: make_ico.py OUT.ico IMAGE.png...")
    main(sys.argv[1], sys.argv[2:])
