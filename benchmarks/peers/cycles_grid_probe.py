#!/usr/bin/env python3
"""Where Cycles 3.4 reads a density grid's values: the check behind cycles_media.py's placement of
the .vdb it writes (vdb_index_to_world), and of lamina's grid media against the same numbers.

A benchmark-side check, not a test (it needs Blender 3.4 and python3-openvdb). It writes a probe
scene: an 8^3 grid of an absorbing medium (sigma_a 0.1; the values rise along x, y and z inside,
the outermost cells 0) in the box [-1, 1]^3, inside an interface sphere, in front of an emitter of
radiance 1, seen along z. Each pixel is the transmittance exp(-sigma_a * integral of the density)
along its camera ray, which this script integrates (4000 midpoint steps) from lamina's definition
of the density: values at the cell centres lo + (i + 1/2) h, trilinear between them, the nearest
value beyond the outermost centres, 0 outside the box (docs/media.md). It renders the scene with
lamina and with Cycles (through cycles.py) and prints each image's RMS difference from that
integral with the values put at the centres (shift 0) and half a cell off on every axis (shift
+1/2: a value read half a cell above its centre, -1/2: below): the renderer reads the values where
its row is smallest. With the .vdb as cycles_media.py writes it, both renderers are at shift 0
(lamina within its noise, Cycles within its ray-marching and pixel-area differences).

  python3 benchmarks/peers/cycles_grid_probe.py --lamina build/app/lamina --work /tmp/probe
"""

import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_efficiency  # noqa: E402

N = 8
SIGMA_A = 0.1
FOV = 25.0
EYE_Z = -6.0
RESOLUTION = 64


def probe_values():
    """The grid, x fastest: rising along each axis inside, 0 on the outermost cells."""
    values = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                inside = all(0 < a < N - 1 for a in (i, j, k))
                values.append(float(i + 2 * j + 0.5 * k) if inside else 0.0)
    return values


def probe_scene():
    return {
        "camera": {"position": [0, 0, EYE_Z], "look_at": [0, 0, 0], "fov": FOV},
        "film": {"resolution": [RESOLUTION, RESOLUTION]},
        "integrator": {"max_depth": 4},
        "media": {"probe": {"type": "grid", "sigma_a": SIGMA_A,
                            "density": {"size": [N, N, N], "values": probe_values()},
                            "bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}}},
        "materials": {"black": {"type": "lambert", "reflectance": 0}},
        "shapes": [
            {"type": "sphere", "radius": 1.9, "material": "interface", "interior": "probe"},
            {"type": "rectangle", "material": "black", "emission": {"radiance": 1},
             "transform": [{"scale": 5}, {"rotate": {"axis": [0, 1, 0], "angle": 180}},
                           {"translate": [0, 0, 4]}]},
        ],
    }


def lamina_density(points, shift):
    """lamina's density at points (..., 3), the values moved by `shift` cells on every axis."""
    grid = np.array(probe_values()).reshape(N, N, N)  # [z][y][x]
    h = 2.0 / N
    u = np.clip((points + 1.0) / h - 0.5 - shift, 0.0, N - 1.0)
    i0 = np.minimum(np.floor(u).astype(int), N - 2)
    f = u - i0
    out = np.zeros(points.shape[:-1])
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                w = ((f[..., 0] if dx else 1 - f[..., 0]) * (f[..., 1] if dy else 1 - f[..., 1])
                     * (f[..., 2] if dz else 1 - f[..., 2]))
                out += w * grid[i0[..., 2] + dz, i0[..., 1] + dy, i0[..., 0] + dx]
    return np.where(np.all(np.abs(points) <= 1.0, axis=-1), out, 0.0)


def transmittance(shift):
    """The exact image: exp(-sigma_a * optical depth) through each pixel's centre."""
    t = math.tan(math.radians(FOV) / 2)
    ys, xs = np.mgrid[0:RESOLUTION, 0:RESOLUTION]
    # Looking along +z with +y up, image right is -x (a right-handed frame).
    d = np.stack([-(2 * (xs + 0.5) / RESOLUTION - 1) * t, (1 - 2 * (ys + 0.5) / RESOLUTION) * t,
                  np.ones(xs.shape)], axis=-1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    edges = np.linspace(-EYE_Z - 2.5, -EYE_Z + 2.5, 4001)
    depth = np.zeros(xs.shape)
    for a, b in zip(edges[:-1], edges[1:]):
        depth += lamina_density(np.array([0, 0, EYE_Z]) + d * (0.5 * (a + b)), shift) * (b - a)
    return np.exp(-SIGMA_A * depth)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--lamina", default="build/app/lamina")
    p.add_argument("--blender", default="blender")
    p.add_argument("--python", default="build/python", help="lamina's Python module (read_image)")
    p.add_argument("--lamina-spp", type=int, default=4096)
    p.add_argument("--work", required=True)
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    scene = os.path.join(args.work, "probe.json")
    with open(scene, "w") as f:
        json.dump(probe_scene(), f)
    images = {"lamina": os.path.join(args.work, "lamina.exr"),
              "Cycles": os.path.join(args.work, "cycles.exr")}
    peer_efficiency.run_lamina(args.lamina, scene, images["lamina"], spp=args.lamina_spp)
    # Absorption only: Cycles' samples differ only by the pixel position and its step offset;
    # a step rate of 0.1 makes its ray marching's error small beside a half-cell shift.
    env = dict(os.environ, LAMINA_PEER_VOLUME_STEP_RATE="0.1")
    subprocess.run([args.blender, "-b", "--factory-startup", "-t", "2", "-P",
                    os.path.join(os.path.dirname(os.path.abspath(__file__)), "cycles.py"), "--",
                    "--inside-blender", scene, "16", "1", images["Cycles"]],
                   check=True, capture_output=True, env=env)
    exact = {shift: transmittance(shift) for shift in (-0.5, 0.0, 0.5)}
    print("| renderer | RMS against shift -1/2 | shift 0 | shift +1/2 |")
    print("|---|---|---|---|")
    for name, path in images.items():
        image = peer_efficiency.read_rgb(path, args.python)[..., 0]
        rms = [float(np.sqrt(((image - exact[s]) ** 2).mean())) for s in (-0.5, 0.0, 0.5)]
        print(f"| {name} | {rms[0]:.4f} | {rms[1]:.4f} | {rms[2]:.4f} |")


if __name__ == "__main__":
    main()
