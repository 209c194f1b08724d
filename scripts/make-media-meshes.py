#!/usr/bin/env python3
"""Writes the meshes of scenes/media/glass-of-wine.json and scenes/media/volumetric-caustic.json.

The glass of wine: a tumbler (a cylinder with walls 0.04 thick and a base 0.08 thick) filled to a
level with a liquid, as three OBJ files, one per kind of boundary, each with the material and the
media of its two sides in the scene (docs/media.md, "Boundaries"; the exterior is the side the
normals point to):

  tumbler-glass-air.obj    glass against air: the outer wall and base, the rim, and the inner
                           wall above the liquid (normals towards the air)
  tumbler-glass-wine.obj   glass against the liquid: the inner wall below the level and the inner
                           bottom (normals into the liquid; the glass, of index 1.5, inside)
  tumbler-wine-air.obj     the liquid's surface, a disk at the level (normal up, into the air)

Together they close the glass and the liquid without overlapping: every point of space is in
exactly one of air, glass and liquid, and each boundary's index is the ratio of the two sides'.

The spot lamp's barrel (lamp-barrel.obj): an open tube, black inside and out in the scene, that
an emitting disk closes at its top, so that the lamp lights a cone of half-angle about 20 degrees.

Smooth shading normals (vn) on the curved walls. Deterministic: the files in the repository are
what this script writes.

    python3 scripts/make-media-meshes.py scenes/media
"""
import math
import os
import sys

SEGMENTS = 96  # around the tumbler: a chord deviates from the circle by 0.05% of the radius

# The tumbler, in scene units (1 unit = 10 cm: a glass 8 cm across and 10 cm tall).
OUTER_RADIUS = 0.40
INNER_RADIUS = 0.36
BASE = 0.08  # the inner bottom's height
HEIGHT = 1.0  # the rim
LEVEL = 0.65  # the liquid's surface

# The lamp's barrel.
BARREL_SEGMENTS = 24
BARREL_RADIUS = 0.12
BARREL_LENGTH = 0.6


class Obj:
    def __init__(self, comment):
        self.lines = ["# " + line for line in comment] + ["# written by scripts/make-media-meshes.py"]
        self.v = 0
        self.vn = 0

    def vertex(self, p, n):
        self.lines.append("v %.6f %.6f %.6f" % p)
        self.lines.append("vn %.6f %.6f %.6f" % n)
        self.v += 1
        self.vn += 1
        return self.v

    def face(self, indices):
        self.lines.append("f " + " ".join("%d//%d" % (i, i) for i in indices))

    def write(self, path):
        with open(path, "w") as f:
            f.write("\n".join(self.lines) + "\n")


def angle(i, segments):
    return 2 * math.pi * i / segments


def wall(obj, radius, y0, y1, inward, segments=SEGMENTS):
    """A cylinder's side from y0 to y1, normals away from the axis (or towards it)."""
    s = -1.0 if inward else 1.0
    ring = []
    for i in range(segments):
        a = angle(i, segments)
        c, d = math.cos(a), math.sin(a)
        n = (s * c, 0.0, s * d)
        ring.append((obj.vertex((radius * c, y0, radius * d), n),
                     obj.vertex((radius * c, y1, radius * d), n)))
    for i in range(segments):
        (b0, t0), (b1, t1) = ring[i], ring[(i + 1) % segments]
        # Counter-clockwise seen from the side the normals point to.
        obj.face([b0, t0, t1, b1] if not inward else [b0, b1, t1, t0])


def disk(obj, radius, y, up):
    """A disk at height y as a fan of triangles, facing up or down."""
    n = (0.0, 1.0 if up else -1.0, 0.0)
    centre = obj.vertex((0.0, y, 0.0), n)
    rim = [obj.vertex((radius * math.cos(angle(i, SEGMENTS)), y,
                       radius * math.sin(angle(i, SEGMENTS))), n) for i in range(SEGMENTS)]
    for i in range(SEGMENTS):
        a, b = rim[i], rim[(i + 1) % SEGMENTS]
        obj.face([centre, b, a] if up else [centre, a, b])


def annulus(obj, inner, outer, y):
    """The rim: a flat ring at height y facing up."""
    n = (0.0, 1.0, 0.0)
    ring = []
    for i in range(SEGMENTS):
        a = angle(i, SEGMENTS)
        c, d = math.cos(a), math.sin(a)
        ring.append((obj.vertex((inner * c, y, inner * d), n),
                     obj.vertex((outer * c, y, outer * d), n)))
    for i in range(SEGMENTS):
        (i0, o0), (i1, o1) = ring[i], ring[(i + 1) % SEGMENTS]
        obj.face([i0, i1, o1, o0])


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "."
    glass_air = Obj(["The tumbler's glass against air: outer wall and base, rim, inner wall above",
                     "the liquid. Normals towards the air (the glass inside)."])
    wall(glass_air, OUTER_RADIUS, 0.0, HEIGHT, inward=False)
    disk(glass_air, OUTER_RADIUS, 0.0, up=False)
    annulus(glass_air, INNER_RADIUS, OUTER_RADIUS, HEIGHT)
    wall(glass_air, INNER_RADIUS, LEVEL, HEIGHT, inward=True)
    glass_air.write(os.path.join(directory, "tumbler-glass-air.obj"))

    glass_wine = Obj(["The tumbler's glass against the liquid: inner wall below the level and inner",
                      "bottom. Normals into the liquid (the glass inside)."])
    wall(glass_wine, INNER_RADIUS, BASE, LEVEL, inward=True)
    disk(glass_wine, INNER_RADIUS, BASE, up=True)
    glass_wine.write(os.path.join(directory, "tumbler-glass-wine.obj"))

    wine_air = Obj(["The liquid's surface at its level. Normal up, into the air (the liquid",
                    "inside)."])
    disk(wine_air, INNER_RADIUS, LEVEL, up=True)
    wine_air.write(os.path.join(directory, "tumbler-wine-air.obj"))

    barrel = Obj(["The spot lamp's barrel: an open tube along y from 0 to its length, normals",
                  "outwards (black on both sides in the scene)."])
    wall(barrel, BARREL_RADIUS, 0.0, BARREL_LENGTH, inward=False, segments=BARREL_SEGMENTS)
    barrel.write(os.path.join(directory, "lamp-barrel.obj"))


if __name__ == "__main__":
    main()
