"""The geometry of lamina's shapes as polygon meshes, in plain Python (no bpy), for
benchmarks/peers/cycles.py: Cycles has no analytic spheres or disks, and the participating-media
translation (cycles_media.py) needs the shapes' extents and closed domain meshes before Blender
sees them. tests/python/test_peers.py checks these functions without Blender.

A mesh is (positions, faces): positions a list of (x, y, z), faces lists of indices,
counter-clockwise seen from the front (the side the face's normal points to). A transform is a
4x4 matrix as nested lists (rows; column vectors: p' = M p), lamina's transform list applied in
order (the first operation first).
"""

import math
import os


class Unsupported(Exception):
    """A lamina feature this comparison does not translate: the message says which."""


# ---------------------------------------------------------------------------------------------
# Transforms.


def identity():
    return [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def rotation(axis, degrees):
    """Rotation by `degrees` about `axis`, counter-clockwise looking down the axis (right-handed,
    Rodrigues' formula: Blender's Matrix.Rotation and lamina's `rotate`)."""
    n = math.sqrt(sum(a * a for a in axis))
    if n == 0:
        raise Unsupported(f"rotation about a zero axis {axis!r}")
    x, y, z = (a / n for a in axis)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1.0 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0.0],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0.0],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0.0],
            [0.0, 0.0, 0.0, 1.0]]


def transform_matrix(ops, what):
    m = identity()
    for op in ops or []:
        if "translate" in op:
            step = identity()
            for i in range(3):
                step[i][3] = float(op["translate"][i])
        elif "scale" in op:
            s = op["scale"]
            s = [s] * 3 if isinstance(s, (int, float)) else s
            step = identity()
            for i in range(3):
                step[i][i] = float(s[i])
        elif "rotate" in op:
            step = rotation(op["rotate"]["axis"], op["rotate"]["angle"])
        elif "matrix" in op:
            v = op["matrix"]
            step = [list(map(float, v[4 * i:4 * i + 4])) for i in range(4)]
        else:
            raise Unsupported(f"{what}: transform operation {op!r}")
        m = matmul(step, m)
    return m


def apply(m, p):
    return tuple(sum(m[i][k] * p[k] for k in range(3)) + m[i][3] for i in range(3))


# ---------------------------------------------------------------------------------------------
# Tessellations.


def rectangle():
    """lamina's rectangle: [-1, 1]^2 at z = 0, its front facing +z."""
    return [(-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)], [[0, 1, 2, 3]]


def uv_sphere(center, radius, u_segments=256, v_segments=128):
    """A UV sphere (Blender's create_uvsphere layout: u_segments around, v_segments pole to
    pole), faces outwards. Its polygons lie inside the sphere; at 256 x 128 the surface is within
    7.5e-5 radii of it, below anything the benchmark resolves."""
    cx, cy, cz = center
    positions = [(cx, cy, cz + radius), (cx, cy, cz - radius)]  # north and south pole
    for j in range(1, v_segments):
        theta = math.pi * j / v_segments
        for i in range(u_segments):
            phi = 2.0 * math.pi * i / u_segments
            positions.append((cx + radius * math.sin(theta) * math.cos(phi),
                              cy + radius * math.sin(theta) * math.sin(phi),
                              cz + radius * math.cos(theta)))

    def ring(j, i):  # vertex i of ring j (1 .. v_segments - 1)
        return 2 + (j - 1) * u_segments + i % u_segments

    faces = []
    for i in range(u_segments):
        faces.append([0, ring(1, i), ring(1, i + 1)])
        for j in range(1, v_segments - 1):
            faces.append([ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i + 1)])
        faces.append([1, ring(v_segments - 1, i + 1), ring(v_segments - 1, i)])
    return positions, faces


def disk(center, normal, radius, segments=256):
    """lamina's disk as a fan of triangles, its front facing `normal`. The polygon's radius is
    stretched so that its area is the disk's, pi r^2 (an inscribed regular N-gon has
    (N / 2) r^2 sin(2 pi / N)): an emitting disk then emits the disk's power exactly."""
    n = math.sqrt(sum(a * a for a in normal))
    if n == 0 or radius <= 0:
        raise Unsupported(f"disk: normal {normal!r}, radius {radius!r}")
    w = [a / n for a in normal]
    # Any orthonormal u, v with u x v = w.
    helper = (1.0, 0.0, 0.0) if abs(w[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = cross(helper, w)
    lu = math.sqrt(sum(a * a for a in u))
    u = [a / lu for a in u]
    v = cross(w, u)
    r = radius * math.sqrt(2.0 * math.pi / (segments * math.sin(2.0 * math.pi / segments)))
    positions = [tuple(center)]
    for i in range(segments):
        phi = 2.0 * math.pi * i / segments
        c, s = math.cos(phi), math.sin(phi)
        positions.append(tuple(center[k] + r * (c * u[k] + s * v[k]) for k in range(3)))
    faces = [[0, 1 + i, 1 + (i + 1) % segments] for i in range(segments)]
    return positions, faces


def box(lo, hi):
    """An axis-aligned box, faces outwards."""
    positions = [(x, y, z) for z in (lo[2], hi[2]) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])]
    # Vertex index: x bit 1, y bit 2, z bit 4.
    faces = [[0, 2, 3, 1], [4, 5, 7, 6],  # z = lo (normal -z), z = hi (+z)
             [0, 1, 5, 4], [2, 6, 7, 3],  # y = lo, y = hi
             [0, 4, 6, 2], [1, 3, 7, 5]]  # x = lo, x = hi
    return positions, faces


def read_obj(path):
    """Positions and faces of a Wavefront OBJ file (`v` and `f` lines; v, v/vt, v//vn, v/vt/vn
    references, negative ones counted from the end), and whether it has vertex normals."""
    positions, faces, normals = [], [], False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                positions.append(tuple(float(a) for a in fields[1:4]))
            elif fields[0] == "vn":
                normals = True
            elif fields[0] == "f":
                face = []
                for ref in fields[1:]:
                    k = int(ref.split("/")[0])
                    face.append(k - 1 if k > 0 else len(positions) + k)
                if len(face) < 3 or not all(0 <= k < len(positions) for k in face):
                    raise Unsupported(f"{path}:{number}: a face needs 3 vertices read before it")
                faces.append(face)
    return positions, faces, normals


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def flipped(faces):
    """The same faces wound the other way (their normals reversed)."""
    return [list(reversed(face)) for face in faces]


# ---------------------------------------------------------------------------------------------
# A lamina shape as a mesh.


def shape_mesh(shape, scene_dir, what, ignore_normals=False):
    """(positions, faces, matrix) of a lamina shape: its own tessellation and its transform. An OBJ
    file's vertex normals are refused unless ignore_normals (a black surface does not shade, and
    a room's extent needs positions only)."""
    kind = shape.get("type")
    if "normals" in shape or "uvs" in shape:
        raise Unsupported(f"{what}: vertex normals and uvs")
    if kind == "mesh":
        positions, faces = [tuple(p) for p in shape["positions"]], shape["faces"]
    elif kind == "rectangle":
        positions, faces = rectangle()
    elif kind == "sphere":
        positions, faces = uv_sphere(shape.get("center", [0, 0, 0]), float(shape.get("radius", 1.0)))
    elif kind == "disk":
        positions, faces = disk(shape.get("center", [0, 0, 0]), shape.get("normal", [0, 0, 1]),
                                float(shape.get("radius", 1.0)))
    elif kind == "obj":
        positions, faces, normals = read_obj(os.path.join(scene_dir, shape["file"]))
        if normals and not ignore_normals:
            raise Unsupported(f"{what}: vertex normals (of {shape['file']})")
    else:
        raise Unsupported(f"{what}: shape type {kind!r}")
    return positions, faces, transform_matrix(shape.get("transform"), what)


def world_positions(positions, matrix):
    return [apply(matrix, p) for p in positions]


def bounds(points):
    return ([min(p[i] for p in points) for i in range(3)],
            [max(p[i] for p in points) for i in range(3)])


def polygon_area(points):
    """Area of a planar polygon (half the norm of its vector area)."""
    s = [0.0, 0.0, 0.0]
    for a, b in zip(points, points[1:] + points[:1]):
        c = cross(a, b)
        s = [s[i] + c[i] for i in range(3)]
    return 0.5 * math.sqrt(sum(a * a for a in s))


# ---------------------------------------------------------------------------------------------
# Checks of closed meshes.


def is_closed(faces):
    """True when every edge is used once in each direction: a closed surface, its faces wound
    consistently (so an inside and an outside exist and the normals agree on them)."""
    directed = {}
    for face in faces:
        for a, b in zip(face, face[1:] + face[:1]):
            if (a, b) in directed:
                return False
            directed[(a, b)] = True
    return all((b, a) in directed for (a, b) in directed)


def signed_volume(positions, faces):
    """The enclosed volume, positive when the faces point outwards (divergence theorem over a
    fan of triangles per face)."""
    v = 0.0
    for face in faces:
        p0 = positions[face[0]]
        for a, b in zip(face[1:-1], face[2:]):
            p1, p2 = positions[a], positions[b]
            v += (p0[0] * (p1[1] * p2[2] - p1[2] * p2[1]) - p0[1] * (p1[0] * p2[2] - p1[2] * p2[0])
                  + p0[2] * (p1[0] * p2[1] - p1[1] * p2[0])) / 6.0
    return v
