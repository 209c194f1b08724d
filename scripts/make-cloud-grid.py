#!/usr/bin/env python3
"""Writes the density grid of scenes/media/chromatic-cloud.json: a small procedural cloud.

A union of soft spheres (a cumulus-like heap: a wide base and smaller puffs on top) eroded by
three octaves of smooth value noise, on a 32^3 grid (128 KiB), in the lamina grid file format
of docs/media.md ("Grid media"): one JSON header line, then the densities as little-endian
float32, x fastest, then y, then z, at the centres of the cells of the medium's box. The result
is deterministic (a fixed seed), so the file in the repository is what this script writes.

    python3 scripts/make-cloud-grid.py scenes/media/cloud.lgrid
"""
import array
import json
import math
import random
import sys

SIZE = 32
SEED = 7


def smooth(t):
    return t * t * (3 - 2 * t)


class ValueNoise:
    """Smooth value noise in [0, 1] on a lattice of `cells`^3 over the unit cube."""

    def __init__(self, rng, cells):
        self.cells = cells
        n = cells + 1
        self.lattice = [rng.random() for _ in range(n * n * n)]

    def __call__(self, p):
        n = self.cells + 1
        i, f = [], []
        for v in p:
            s = v * self.cells
            k = min(int(s), self.cells - 1)
            i.append(k)
            f.append(smooth(s - k))
        out = 0.0
        for dx in (0, 1):
            for dy in (0, 1):
                for dz in (0, 1):
                    w = ((f[0] if dx else 1 - f[0]) * (f[1] if dy else 1 - f[1]) *
                         (f[2] if dz else 1 - f[2]))
                    out += w * self.lattice[((i[2] + dz) * n + i[1] + dy) * n + i[0] + dx]
        return out


# Puffs: centre (x, y, z) in the unit box, radius.
PUFFS = [((0.5, 0.35, 0.5), 0.3), ((0.3, 0.4, 0.45), 0.2), ((0.7, 0.4, 0.55), 0.22),
         ((0.45, 0.6, 0.5), 0.2), ((0.62, 0.62, 0.42), 0.14)]


def cloud():
    rng = random.Random(SEED)
    octaves = [ValueNoise(rng, cells) for cells in (4, 8, 16)]
    values = array.array("f")
    for z in range(SIZE):
        for y in range(SIZE):
            for x in range(SIZE):  # x fastest
                p = ((x + 0.5) / SIZE, (y + 0.5) / SIZE, (z + 0.5) / SIZE)
                shape = 0.0
                for centre, radius in PUFFS:
                    r2 = sum((a - b) ** 2 for a, b in zip(p, centre)) / radius**2
                    shape = max(shape, min(max(1 - r2, 0.0), 1.0))
                noise = sum(o(p) / 2**k for k, o in enumerate(octaves))
                density = max(shape * 1.6 - 0.45 * noise, 0.0)
                # A flat-ish base, as cumulus have.
                density *= min(max((p[1] - 0.08) / 0.1, 0.0), 1.0)
                values.append(density)
    if sys.byteorder != "little":
        values.byteswap()
    return values


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make-cloud-grid.py OUTPUT.lgrid")
    header = json.dumps({"lamina_grid": 1, "size": [SIZE, SIZE, SIZE]}) + "\n"
    with open(sys.argv[1], "wb") as out:
        out.write(header.encode())
        values = cloud()
        out.write(values.tobytes())


if __name__ == "__main__":
    main()
