#!/usr/bin/env python3
"""Loading big meshes: lamina against Blender 3.4's importers and Cycles' scene sync.

A benchmark, not a test (never run in CI; Blender 3.4 from Debian: `apt-get install -y
blender`). It writes a scene of --triangles triangles (default 10 million) split over --meshes
height-field meshes, once as binary PLY files and once as OBJ files (positions and normals,
the way exporters write them), and for each format measures

  lamina   `lamina info` (reads every file: the read time) and `lamina render --spp 1` at
           32x32 (read, BVH build and one sample per pixel: the seconds to the first pixel),
           each as its own process;
  Blender  the importer (OBJ: the C++ `wm.obj_import`; PLY: 3.4's `import_mesh.ply`) and then
           one Cycles sample at 32x32 (scene sync, BVH and the sample), in one process.

and prints per renderer the read throughput (MB of files / read seconds), the seconds to the
first pixel (lamina: the whole `render` process; Blender: import plus render, without Blender's
start-up) and the peak memory per triangle (the process's peak resident set, getrusage, over
the triangle count, less the peak of the same process on an empty scene: what the meshes cost,
BVH included). Ratios are Blender / lamina (above 1: lamina is ahead). Times are wall seconds;
run on a quiet machine and compare only ratios from one run.

Run from the repository root:
  python3 benchmarks/peers/mesh_loading.py --lamina build/app/lamina --work /tmp/meshes
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def grid_size(triangles_per_mesh):
    """n for an n x n grid of quads, 2 n^2 triangles, nearest to the count asked."""
    return max(1, int(round((triangles_per_mesh / 2) ** 0.5)))


def height_field(n, offset):
    """Positions, normals and triangles of a wavy n x n quad grid of side 1 at x = offset."""
    s = np.linspace(0.0, 1.0, n + 1, dtype=np.float64)
    u, v = np.meshgrid(s, s, indexing="xy")
    k = 6.0 * np.pi
    h = 0.05 * np.sin(k * u) * np.cos(k * v)
    dhdu = 0.05 * k * np.cos(k * u) * np.cos(k * v)
    dhdv = -0.05 * k * np.sin(k * u) * np.sin(k * v)
    positions = np.stack([u + offset, h, v], axis=-1).reshape(-1, 3)
    normals = np.stack([-dhdu, np.ones_like(h), -dhdv], axis=-1).reshape(-1, 3)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    i = np.arange(n)
    a = (i[None, :] + (n + 1) * i[:, None]).ravel()  # lower-left corner of each quad
    b, c, d = a + 1, a + n + 2, a + n + 1
    # Counter-clockwise seen from +y (the side the normals face).
    tris = np.concatenate([np.stack([a, d, c], 1), np.stack([a, c, b], 1)]).astype(np.int32)
    return positions.astype(np.float32), normals.astype(np.float32), tris


def write_ply(path, positions, normals, tris):
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(positions)}\n"
        "property float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\n"
        f"element face {len(tris)}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    faces = np.empty(len(tris), dtype=[("n", "u1"), ("v", "<i4", 3)])
    faces["n"] = 3
    faces["v"] = tris
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(np.concatenate([positions, normals], axis=1).astype("<f4").tobytes())
        f.write(faces.tobytes())


def write_obj(path, positions, normals, tris):
    with open(path, "w") as f:
        np.savetxt(f, positions, fmt="v %.6f %.6f %.6f")
        np.savetxt(f, normals, fmt="vn %.6f %.6f %.6f")
        t = tris + 1
        np.savetxt(f, np.repeat(t, 2, axis=1), fmt="f %d//%d %d//%d %d//%d")


def make_meshes(work, fmt, triangles, meshes):
    """The files of one format (written once per work directory and size) and their total."""
    n = grid_size(triangles / meshes)
    paths = []
    for m in range(meshes):
        path = os.path.join(work, f"mesh{m:02d}_{n}.{fmt}")
        if not os.path.exists(path):
            part = path + ".part"
            (write_ply if fmt == "ply" else write_obj)(part, *height_field(n, 1.1 * m))
            os.replace(part, path)
        paths.append(path)
    return paths, meshes * 2 * n * n


def lamina_scene(work, fmt, paths, meshes):
    """A scene of the meshes under a quad light, seen from above (every mesh in view)."""
    width = 1.1 * meshes
    scene = {
        "camera": {"position": [width / 2, 3.0 * meshes, 0.5], "look_at": [width / 2, 0, 0.5],
                   "up": [0, 0, 1], "fov": 40},
        "film": {"resolution": [32, 32]},
        "sampler": {"spp": 1},
        "materials": {"grey": {"type": "lambert", "reflectance": 0.5}},
        "shapes": [{"type": fmt, "file": p, "material": "grey"} for p in paths]
        + [{"type": "rectangle", "material": "grey",
            "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}},
                          {"scale": width}, {"translate": [width / 2, 5.0 * meshes, 0.5]}],
            "emission": {"radiance": 1}}],
    }
    path = os.path.join(work, f"scene_{fmt}.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def peak_rss_of(cmd, env=None):
    """Runs cmd in a child and returns (wall seconds, peak RSS bytes, output)."""
    start = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         env=env)
    out = p.stdout.read()
    _, status, usage = os.wait4(p.pid, 0)
    seconds = time.perf_counter() - start
    p.stdout.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"mesh_loading.py: {' '.join(cmd)} failed:\n{out[-2000:]}")
    return seconds, usage.ru_maxrss * 1024, out


BLENDER_SCRIPT = r"""
import bpy, json, sys, time
args = sys.argv[sys.argv.index("--") + 1:]
fmt, out = args[0], args[1]
paths = args[2:]
for o in list(bpy.data.objects):
    bpy.data.objects.remove(o)
for m in list(bpy.data.meshes):  # the start-up cube's mesh
    bpy.data.meshes.remove(m)
start = time.perf_counter()
for p in paths:
    if fmt == "obj":
        bpy.ops.wm.obj_import(filepath=p)
    else:
        bpy.ops.import_mesh.ply(filepath=p)
imported = time.perf_counter() - start
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.cycles.samples = 1
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.render.resolution_x = scene.render.resolution_y = 32
scene.render.resolution_percentage = 100
cam = bpy.data.objects.new("cam", bpy.data.cameras.new("cam"))
scene.collection.objects.link(cam)
scene.camera = cam
cam.location = (len(paths) * 0.55, -0.5, 3.0 * max(len(paths), 1))
scene.render.filepath = out
start = time.perf_counter()
bpy.ops.render.render(write_still=True)
rendered = time.perf_counter() - start
triangles = sum(len(m.polygons) for m in bpy.data.meshes)
print("MESH_LOADING " + json.dumps({"import": imported, "render": rendered,
                                    "triangles": triangles}))
"""


def blender_run(blender, work, fmt, paths):
    script = os.path.join(work, "mesh_loading_blender.py")
    with open(script, "w") as f:
        f.write(BLENDER_SCRIPT)
    cmd = [blender, "-b", "--factory-startup", "-t", "2", "-P", script, "--", fmt,
           os.path.join(work, f"cycles_{fmt}.exr")] + paths
    seconds, rss, out = peak_rss_of(cmd)
    for line in out.splitlines():
        if line.startswith("MESH_LOADING "):
            return json.loads(line[len("MESH_LOADING "):]), rss
    sys.exit(f"mesh_loading.py: Blender printed no result:\n{out[-2000:]}")


def lamina_triangles(info_output):
    """The triangle count `lamina info` prints ("geometry: 3 meshes (12 triangles, ...")."""
    for line in info_output.splitlines():
        if line.startswith("geometry:") and "triangles" in line:
            return int(line.split("(")[1].split(" triangles")[0])
    raise ValueError("no geometry line in lamina info's output")


def measure(args, fmt):
    paths, triangles = make_meshes(args.work, fmt, args.triangles, args.meshes)
    mb = sum(os.path.getsize(p) for p in paths) / 1e6
    scene = lamina_scene(args.work, fmt, paths, args.meshes)
    empty = lamina_scene(args.work, fmt + "_empty", [], args.meshes)
    read_s, _, info = peak_rss_of([args.lamina, "info", scene])
    counted = lamina_triangles(info) - 2  # the light's rectangle
    if counted != triangles:
        sys.exit(f"mesh_loading.py: lamina counted {counted} triangles, the files hold "
                 f"{triangles}")
    image = os.path.join(args.work, f"lamina_{fmt}.exr")
    first_s, rss, _ = peak_rss_of([args.lamina, "render", scene, "-o", image, "--threads", "2"])
    _, rss0, _ = peak_rss_of([args.lamina, "render", empty, "-o", image, "--threads", "2"])
    row = {"format": fmt, "triangles": triangles, "MB": mb,
           "lamina": {"read": read_s, "first_pixel": first_s,
                      "bytes_per_triangle": (rss - rss0) / triangles}}
    if not args.skip_blender:
        b, brss = blender_run(args.blender, args.work, fmt, paths)
        _, brss0 = blender_run(args.blender, args.work, fmt, [])
        if b["triangles"] != triangles:
            sys.exit(f"mesh_loading.py: Blender imported {b['triangles']} triangles, the files "
                     f"hold {triangles}")
        row["blender"] = {"read": b["import"], "first_pixel": b["import"] + b["render"],
                          "bytes_per_triangle": (brss - brss0) / triangles}
    return row


def report(rows):
    lines = ["| format | triangles | MB | renderer | MB/s read | s to first pixel | "
             "bytes per triangle |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        for who in ("lamina", "blender"):
            if who not in r:
                continue
            m = r[who]
            per = m["bytes_per_triangle"]
            # Below the empty scene's peak: too few triangles to show above the process's own.
            per_text = f"{per:.0f}" if per > 0 else "not resolved"
            lines.append(f"| {r['format']} | {r['triangles']:,} | {r['MB']:.0f} | {who} | "
                         f"{r['MB'] / m['read']:.1f} | {m['first_pixel']:.2f} | {per_text} |")
        if "blender" in r:
            a, b = r["lamina"], r["blender"]
            memory = (f"{b['bytes_per_triangle'] / a['bytes_per_triangle']:.2f}x"
                      if a["bytes_per_triangle"] > 0 and b["bytes_per_triangle"] > 0
                      else "not resolved")
            lines.append(f"| {r['format']} | | | Blender / lamina | "
                         f"{b['read'] / a['read']:.2f}x (time) | "
                         f"{b['first_pixel'] / a['first_pixel']:.2f}x | {memory} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--lamina", default="build/app/lamina")
    p.add_argument("--blender", default="blender")
    p.add_argument("--triangles", type=float, default=10e6)
    p.add_argument("--meshes", type=int, default=10)
    p.add_argument("--formats", nargs="+", choices=["ply", "obj"], default=["ply", "obj"])
    p.add_argument("--work", help="directory for the meshes (kept; default: a temporary one)")
    p.add_argument("--skip-blender", action="store_true", help="measure lamina only")
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        args.work = args.work or tmp
        os.makedirs(args.work, exist_ok=True)
        rows = [measure(args, fmt) for fmt in args.formats]
    print(report(rows))


if __name__ == "__main__":
    main()
