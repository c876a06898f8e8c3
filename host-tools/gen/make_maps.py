#!/usr/bin/env python3
"""make_maps.py: writes the image maps the scenes use (8-bit RGB PNG, no
gamma chunk: the values are linear, as the renderer reads them).
Run: python3 host-tools/gen/make_maps.py [DIR] (default scenes/maps, where
the maps are kept: the scenes name them relative to their own folder).
write_png is also the PNG writer of host-tools/gen/make_normal_tex.py."""
import math
import os
import struct
import sys
import zlib


def write_png(path, width, height, pixel):
    rows = b""
    for y in range(height):
        rows += b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(width))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 9)))
        f.write(chunk(b"IEND", b""))


def checker(x, y):
    # 8x8 squares of 8 texels: edges stay sharp under bilinear filtering
    light = ((x // 8) + (y // 8)) % 2 == 0
    return (230, 220, 190) if light else (120, 30, 30)


def dimples(x, y):
    # a grid of round dimples, one per 16 texels, as a height field
    h = 0.5 + 0.5 * math.cos(2 * math.pi * x / 16) * math.cos(2 * math.pi * y / 16)
    g = int(round(255 * h))
    return (g, g, g)


def bricks(x, y):
    row = y // 8
    shift = 8 if row % 2 else 0
    mortar = y % 8 == 0 or (x + shift) % 16 == 0
    return (200, 200, 190) if mortar else (150 + (row * 37) % 40, 60, 40)


def rivets(x, y):
    # a normal map (the usual encoding: channel c = 255 (n + 1) / 2, x along
    # the tangent T, y along B = N x T, z along N): a dome of radius 5
    # texels in each 16-texel cell, flat (128 128 255) between them
    dx, dy = (x % 16) - 7.5, (y % 16) - 7.5
    r = 5.0
    d2 = dx * dx + dy * dy
    if d2 >= r * r:
        n = (0.0, 0.0, 1.0)
    else:
        n = (dx / r, dy / r, math.sqrt(1 - d2 / (r * r)))
    return tuple(min(255, max(0, int(round(127.5 * (c + 1))))) for c in n)


def stripes(x, y):
    # an attribute map (grey level / 255): diagonal stripes of 1 (8 texels
    # wide) and 0.15 between them, 16 texels apart
    g = 255 if (x + y) % 16 < 8 else 38
    return (g, g, g)


def spots(x, y):
    # an attribute map: round spots of 0.1 in a field of 1, one per 32 texels
    dx, dy = (x % 32) - 15.5, (y % 32) - 15.5
    g = 26 if dx * dx + dy * dy < 64 else 255
    return (g, g, g)


# The maps: file name, width, height, texel function.
MAPS = [("checker.png", 64, 64, checker), ("dimples.png", 64, 64, dimples),
        ("bricks.png", 64, 64, bricks), ("rivets.png", 64, 64, rivets),
        ("stripes.png", 64, 64, stripes), ("spots.png", 64, 64, spots)]


def main():
    if len(sys.argv) > 2:
        sys.exit("usage: make_maps.py [DIR]")
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    out = sys.argv[1] if len(sys.argv) == 2 else os.path.join(root, "scenes", "maps")
    for name, width, height, pixel in MAPS:
        write_png(os.path.join(out, name), width, height, pixel)


if __name__ == "__main__":
    main()
