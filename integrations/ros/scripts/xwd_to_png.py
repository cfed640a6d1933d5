#!/usr/bin/python3
"""Converts an X window dump (xwd -root of a TrueColor screen, 24 or 32 bits a
pixel, red mask 0xff0000) to a PNG with numpy and zlib only:
xwd_to_png.py IN.xwd OUT.png"""
import struct
import sys
import zlib

import numpy as np


def read_xwd(path):
    with open(path, "rb") as f:
        data = f.read()
    fields = struct.unpack(">25I", data[:100])
    header_size, _, pixmap_format, _, width, height = fields[:6]
    byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
    red_mask, ncolors = fields[14], fields[19]
    if pixmap_format != 2 or bits_per_pixel not in (24, 32) or red_mask != 0xFF0000:
        sys.exit(f"{path}: not a 24/32-bit TrueColor ZPixmap (format {pixmap_format}, "
                 f"{bits_per_pixel} bits a pixel, red mask {red_mask:#x})")
    step = bits_per_pixel // 8
    start = header_size + 12 * ncolors
    rows = np.frombuffer(data, dtype=np.uint8, count=height * bytes_per_line, offset=start)
    pixels = rows.reshape(height, bytes_per_line)[:, :step * width].reshape(height, width, step)
    # LSBFirst: blue, green, red (, pad) in memory; MSBFirst: (pad,) red, green, blue.
    if byte_order == 0:
        return pixels[:, :, [2, 1, 0]]
    return pixels[:, :, step - 3:step]


def write_png(path, rgb):
    height, width, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, payload):
        body = kind + payload
        return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    write_png(sys.argv[2], np.ascontiguousarray(read_xwd(sys.argv[1])))
