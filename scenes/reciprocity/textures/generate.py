#!/usr/bin/env python3
"""Writes the textures of scenes/reciprocity/bump-and-normal-maps.json: 64 x 64 8-bit RGB PNGs,
read by the scene as linear.

- bumps.png: the egg-crate height 1/2 + 1/2 sin(4 x 2 pi x) sin(4 x 2 pi y) in [0, 1] (grey);
- ripples.png: the tangent-space normal map (colour = (n + 1) / 2) of the height
  0.02 sin(6 x 2 pi x) sin(3 x 2 pi y), n = normalize(-dh/dx, -dh/dy, 1) with x, y in [0, 1).

Run with python3 from this directory; the standard library is enough (zlib, struct).
"""
import math
import struct
import zlib

SIZE = 64


def png(path, pixel):
    rows = b""
    for j in range(SIZE):
        rows += b"\0" + bytes(c for i in range(SIZE) for c in pixel(i, j))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)  # 8-bit RGB
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def byte(v):
    return max(0, min(255, round(255 * v)))


def bumps(i, j):
    x, y = (i + 0.5) / SIZE, (j + 0.5) / SIZE
    h = 0.5 + 0.5 * math.sin(8 * math.pi * x) * math.sin(8 * math.pi * y)
    return (byte(h),) * 3


def ripples(i, j):
    # Row j = 0 is the top of the image, where v = 1: the y slope is taken along v.
    x, y = (i + 0.5) / SIZE, 1 - (j + 0.5) / SIZE
    a = 0.02
    dx = a * 12 * math.pi * math.cos(12 * math.pi * x) * math.sin(6 * math.pi * y)
    dy = a * 6 * math.pi * math.sin(12 * math.pi * x) * math.cos(6 * math.pi * y)
    length = math.sqrt(dx * dx + dy * dy + 1)
    n = (-dx / length, -dy / length, 1 / length)
    return tuple(byte(0.5 * (c + 1)) for c in n)


png("bumps.png", bumps)
png("ripples.png", ripples)
