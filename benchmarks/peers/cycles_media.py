"""lamina's participating media in Cycles 3.4, for benchmarks/peers/cycles.py.

The translation is planned in plain Python (plan(); tested without Blender by
tests/python/test_peers.py) and built with bpy inside Blender (build()).

**Coefficients.** Cycles' Volume Scatter node adds a scattering coefficient Color x Density and
its Volume Absorption node an absorption coefficient (1 - Color) x Density, both to the
extinction (intern/cycles/kernel/svm/closure.h, svm_node_closure_volume, 3.4; the Blender manual
calls them the scatter and absorption "density"; EEVEE's node_volume_scatter and
node_volume_absorption compute the same), per RGB channel, in scene units. A lamina medium's
sigma_s (times `scale`) is therefore a Volume Scatter of Density max(sigma_s) and Color
sigma_s / max(sigma_s), its sigma_a a Volume Absorption of Density max(sigma_a) and Color
1 - sigma_a / max(sigma_a) (colours in [0, 1], exact up to float rounding), the two added by an
Add Shader; the scatter node's Anisotropy is lamina's Henyey-Greenstein g (Cycles' phase function
is Henyey-Greenstein with the same sign convention: g > 0 forward). Cycles' Principled Volume is
not used: its absorption is (1 - Color)(1 - sqrt(Absorption Color)) x Density, tied to the
scatter colour.

**Where the media are.** Cycles has no medium per side of a surface: a mesh whose material has
a Volume output is a domain, a path is in it between crossing its boundary inwards (against the
geometric normal) and outwards, and surfaces without a volume change nothing. Two of lamina's
arrangements translate exactly, anything else is refused:

  - *A homogeneous medium around the camera filling a closed box room* (the camera's `medium`;
    walls that name no media): a closed domain mesh, a box just outside the room's walls (which
    must tile the six faces of the scene's bounding box: then no path leaves the room, and the
    fog outside the walls is never reached). Cycles finds the camera inside it (its volume stack
    is initialised by a ray from the camera, which works when the domain is closed). A
    `dielectric` sphere whose `exterior` is that medium and whose inside is vacuum (lamina's
    clear glass ball in fog) becomes a cavity of the same domain object: the sphere's faces wound
    inwards, so that entering the ball leaves the domain and leaving it enters again, with a
    sharp Glass BSDF of IOR 1 / ior (Cycles takes the IOR as is on the front side of a face and
    its inverse on the back: with the faces turned, a ray from outside sees ior and one from
    inside 1 / ior, as on the ball itself). The whole domain has that one material, box faces
    included (no path reaches them: the walls are inside), because Cycles' volume stack keys an
    entry by object and shader id (which includes the face's smooth-shading flag): entered through
    a face of one id (the camera's stack is initialised through the box) and left through a face
    of another, the medium stays on the stack, and a path coming out of the ball enters it a
    second time, doubling the fog. So every face is smooth-shaded too. With a volume-only box
    material and a glass cavity material the floor's caustic came out 40% dark, with one material
    but flat box faces still 35%.
  - *A grid medium inside an `interface` sphere* (camera outside, vacuum around) that contains
    the grid's box: a Volume object read from an OpenVDB file of the same density values (written
    here with pyopenvdb, Debian's python3-openvdb) and the same coefficients times its `density`
    attribute. lamina puts the values at the centres of the box's cells and interpolates
    trilinearly; the .vdb puts voxel (i, j, k) at min + (i + 1/2) h (h the cell size), where
    Cycles' linear interpolation centres its values too. OpenVDB's background is 0, lamina's
    density beyond the outermost cell centres is the nearest value (`clamp`) or fades to 0
    (`zero`) and is 0 outside the box: the two agree everywhere exactly when the outermost layer
    of cells is 0, which is required. Cycles 3.4 ray-marches such a volume (steps of the voxel
    size times the step rate, biased by the step; lamina tracks it exactly): the benchmark's
    --volume-step-rate sets the step, and the cross-check of the two renderers' images says
    whether its bias shows.

Not translated (refused in one line): emitting media (`Le`), a medium's `transform`, colour grids
(`channels`, `sigma_a_grid`, `sigma_s_grid`), grid files other than lamina's own, media on both
sides of a shape, nested media, a camera in a grid medium.
"""

import array
import json
import os
import sys

from cycles_geometry import (Unsupported, box, bounds, flipped, polygon_area, shape_mesh,
                             uv_sphere, world_positions)

MEDIUM_KEYS = {"type", "sigma_a", "sigma_s", "scale", "g", "density", "bounds", "edges"}


def rgb3(value, what):
    if isinstance(value, (int, float)):
        value = [value] * 3
    if not (isinstance(value, list) and len(value) == 3
            and all(isinstance(v, (int, float)) and v >= 0 for v in value)):
        raise Unsupported(f"{what}: expected a number >= 0 or [r, g, b], got {value!r}")
    return tuple(float(v) for v in value)


def coefficients(name, medium):
    """(sigma_a, sigma_s, g) of a lamina medium, `scale` applied."""
    what = f"media.{name}"
    extra = set(medium) - MEDIUM_KEYS
    if extra:
        raise Unsupported(f"{what}: {', '.join(sorted(extra))} (the Cycles comparison translates "
                          f"{', '.join(sorted(MEDIUM_KEYS))})")
    if medium.get("type") not in ("homogeneous", "grid"):
        raise Unsupported(f"{what}.type: {medium.get('type')!r}")
    scale = float(medium.get("scale", 1.0))
    sigma_a = tuple(scale * v for v in rgb3(medium.get("sigma_a", 0), f"{what}.sigma_a"))
    sigma_s = tuple(scale * v for v in rgb3(medium.get("sigma_s", 0), f"{what}.sigma_s"))
    g = float(medium.get("g", 0.0))
    if not -1 < g < 1:
        raise Unsupported(f"{what}.g: {g}")
    return sigma_a, sigma_s, g


def scatter_node(sigma_s):
    """(Color, Density) of the Volume Scatter node whose Color x Density is sigma_s, or None."""
    density = max(sigma_s)
    return None if density == 0 else (tuple(v / density for v in sigma_s), density)


def absorption_node(sigma_a):
    """(Color, Density) of the Volume Absorption node whose (1 - Color) x Density is sigma_a,
    or None."""
    density = max(sigma_a)
    return None if density == 0 else (tuple(1.0 - v / density for v in sigma_a), density)


def cycles_coefficients(scatter, absorption):
    """What Cycles makes of the two nodes (svm_node_closure_volume): (sigma_a, sigma_s)."""
    sigma_s = tuple(c * scatter[1] for c in scatter[0]) if scatter else (0.0,) * 3
    sigma_a = tuple((1.0 - c) * absorption[1] for c in absorption[0]) if absorption else (0.0,) * 3
    return sigma_a, sigma_s


# ---------------------------------------------------------------------------------------------
# Density grids.


def read_lgrid(path):
    """(size, values) of a lamina grid file (docs/media.md: one JSON line, then nx ny nz
    little-endian float32, x fastest)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"\n")
    if end < 0:
        raise Unsupported(f"{path}: not a lamina grid file (the Cycles comparison reads those only)")
    try:
        header = json.loads(data[:end])
    except ValueError:
        header = None
    if not isinstance(header, dict) or header.get("lamina_grid") != 1:
        raise Unsupported(f"{path}: not a lamina grid file (the Cycles comparison reads those only)")
    size = [int(n) for n in header["size"]]
    values = array.array("f")
    values.frombytes(data[end + 1:])
    if sys.byteorder != "little":
        values.byteswap()
    if len(values) != size[0] * size[1] * size[2]:
        raise Unsupported(f"{path}: {len(values)} values for a grid of {size}")
    return size, list(values)


def read_density(name, medium, scene_dir):
    what = f"media.{name}.density"
    density = medium.get("density")
    if isinstance(density, str):
        return read_lgrid(os.path.join(scene_dir, density))
    if isinstance(density, dict) and set(density) <= {"size", "values"}:
        size = [int(n) for n in density["size"]]
        values = [float(v) for v in density["values"]]
        if len(values) != size[0] * size[1] * size[2]:
            raise Unsupported(f"{what}: {len(values)} values for a grid of {size}")
        return size, values
    raise Unsupported(f"{what}: a lamina grid file or {{\"size\", \"values\"}} of one channel")


def outer_cells_zero(size, values):
    """True when every cell on the grid's six faces holds 0."""
    nx, ny, nz = size
    for z in range(nz):
        for y in range(ny):
            for x in range(nx):
                if (x in (0, nx - 1) or y in (0, ny - 1) or z in (0, nz - 1)) and \
                        values[(z * ny + y) * nx + x] != 0:
                    return False
    return True


def grid_box(name, medium):
    b = medium.get("bounds", {"min": [0, 0, 0], "max": [1, 1, 1]})
    lo, hi = [float(v) for v in b["min"]], [float(v) for v in b["max"]]
    if not all(h > l for l, h in zip(lo, hi)):
        raise Unsupported(f"media.{name}.bounds: {b!r}")
    return lo, hi


def vdb_index_to_world(size, lo, hi):
    """OpenVDB's linear transform (a 4x4 matrix for row vectors: [i j k 1] M = world) under which
    Cycles 3.4 finds voxel (i, j, k)'s value at lamina's cell centre lo + (i + 1/2) h: index
    coordinates (i, j, k) go to the cell's lower corner lo + i h, since Cycles reads a voxel's
    value at the centre of its index cell, index i + 1/2 (module docstring)."""
    h = [(hi[a] - lo[a]) / size[a] for a in range(3)]
    return [[h[0], 0.0, 0.0, 0.0], [0.0, h[1], 0.0, 0.0], [0.0, 0.0, h[2], 0.0],
            [lo[0], lo[1], lo[2], 1.0]]


def write_vdb(path, size, values, lo, hi):
    """The density as an OpenVDB float grid named `density` (a fog volume, background 0; cells of
    value 0 inactive)."""
    import numpy as np
    import pyopenvdb as vdb

    nx, ny, nz = size
    dense = np.asarray(values, dtype=np.float32).reshape(nz, ny, nx).transpose(2, 1, 0).copy()
    grid = vdb.FloatGrid(0.0)
    grid.copyFromArray(dense, ijk=(0, 0, 0), tolerance=0.0)
    grid.transform = vdb.createLinearTransform(vdb_index_to_world(size, lo, hi))
    grid.name = "density"
    grid.gridClass = vdb.GridClass.FOG_VOLUME
    vdb.write(path, grids=[grid])


# ---------------------------------------------------------------------------------------------
# The plan.


class Plan:
    """What build() makes: `handled` the shape indices it builds itself (cavities, interfaces);
    `room` None or (medium, positions, faces, glass_ior) of the domain around the camera
    (glass_ior the IOR of the Glass BSDF on every face, 1 / the cavities' ior, or None without
    cavities: then the domain's faces have no surface, transparent to Cycles); `grids`
    (medium, size, values, lo, hi) for each grid medium; `camera_medium` the medium around the
    camera or None."""

    def __init__(self):
        self.handled, self.room, self.grids, self.camera_medium = set(), None, [], None


def side(shape, key):
    value = shape.get(key)
    return None if value in (None, "vacuum") else value


def clear_glass(desc, what):
    """The index of a smooth dielectric of one real index, or Unsupported."""
    if not isinstance(desc, dict) or desc.get("type") != "dielectric" or \
            set(desc) - {"type", "ior", "roughness"} or desc.get("roughness", 0) != 0 or \
            not isinstance(desc.get("ior", 1.5), (int, float)) or desc.get("ior", 1.5) <= 0:
        raise Unsupported(f"{what}: a boundary of the room's medium must be a smooth dielectric of "
                          f"one numeric ior")
    return float(desc.get("ior", 1.5))


def closed_room(scene, scene_dir, skip):
    """The bounds of every shape, checked to be a room: the faces of the shapes that lie on each of
    the box's six faces cover it (their areas sum to its area)."""
    meshes = []
    for i, shape in enumerate(scene.get("shapes", [])):
        positions, faces, matrix = shape_mesh(shape, scene_dir, f"shapes[{i}]", ignore_normals=True)
        meshes.append((i, world_positions(positions, matrix), faces))
    lo, hi = bounds([p for _, points, _ in meshes for p in points])
    extent = max(h - l for l, h in zip(lo, hi))
    tolerance = 1e-6 * extent
    for axis in range(3):
        u, v = [a for a in range(3) if a != axis]
        face_area = (hi[u] - lo[u]) * (hi[v] - lo[v])
        for plane in (lo[axis], hi[axis]):
            covered = sum(polygon_area([points[k] for k in face])
                          for i, points, faces in meshes if i not in skip for face in faces
                          if all(abs(points[k][axis] - plane) <= tolerance for k in face))
            if abs(covered - face_area) > 1e-6 * face_area:
                raise Unsupported(f"camera.medium: a medium around the camera must fill a closed "
                                  f"box room (the walls on the plane {'xyz'[axis]} = {plane:g} "
                                  f"cover {covered:.6g} of its {face_area:.6g})")
    return lo, hi


def plan(scene, scene_dir):
    media = scene.get("media", {})
    result = Plan()
    for name, medium in media.items():
        coefficients(name, medium)
        if medium.get("type") == "grid":
            size, values = read_density(name, medium, scene_dir)
            if not outer_cells_zero(size, values):
                raise Unsupported(f"media.{name}.density: the outermost cells must be 0 (OpenVDB's "
                                  f"background 0 then gives lamina's density everywhere)")
    fog = side(scene.get("camera", {}), "medium")
    if fog is not None:
        if media.get(fog, {}).get("type") != "homogeneous":
            raise Unsupported(f"camera.medium: {fog!r} must be a homogeneous medium of `media`")
        result.camera_medium = fog
    materials = scene.get("materials", {})
    cavities = []
    for i, shape in enumerate(scene.get("shapes", [])):
        what = f"shapes[{i}]"
        inside, outside = side(shape, "interior"), side(shape, "exterior")
        if inside is None and outside is None:
            if shape.get("material") == "interface":
                raise Unsupported(f"{what}: an interface with no medium")
            continue
        if fog is not None and outside == fog and inside is None:
            if shape.get("type") != "sphere" or "transform" in shape:
                raise Unsupported(f"{what}: a boundary of the room's medium must be a sphere")
            ior = clear_glass(materials.get(shape.get("material")), what)
            cavities.append((shape, ior))
        elif inside is not None and outside is None and shape.get("material") == "interface" and \
                media.get(inside, {}).get("type") == "grid" and inside != fog:
            if shape.get("type") != "sphere" or "transform" in shape:
                raise Unsupported(f"{what}: a grid medium's boundary must be a sphere")
            medium = media[inside]
            lo, hi = grid_box(inside, medium)
            center, radius = shape.get("center", [0, 0, 0]), float(shape.get("radius", 1.0))
            corners = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
            if any(sum((c[a] - center[a]) ** 2 for a in range(3)) >= radius ** 2 for c in corners):
                raise Unsupported(f"{what}: the sphere must contain media.{inside}'s box")
            if any(g[0] == inside for g in result.grids):
                raise Unsupported(f"{what}: media.{inside} has one boundary only")
            size, values = read_density(inside, medium, scene_dir)
            result.grids.append((inside, size, values, lo, hi))
        else:
            raise Unsupported(f"{what}: interior {inside!r}, exterior {outside!r} (the Cycles "
                              f"comparison translates clear dielectric spheres in the camera's "
                              f"medium and grid media in interface spheres)")
        result.handled.add(i)
    if fog is not None:
        lo, hi = closed_room(scene, scene_dir, result.handled)
        margin = 1e-3 * max(h - l for l, h in zip(lo, hi))
        positions, faces = box([l - margin for l in lo], [h + margin for h in hi])
        for shape, _ in cavities:
            sphere, sphere_faces = uv_sphere(shape.get("center", [0, 0, 0]),
                                             float(shape.get("radius", 1.0)))
            offset = len(positions)
            positions = positions + sphere
            faces = faces + [[offset + j for j in face] for face in flipped(sphere_faces)]
        iors = {ior for _, ior in cavities}
        if len(iors) > 1:
            raise Unsupported(f"media.{fog}: its glass spheres must share one ior (the domain has "
                              f"one material)")
        result.room = (fog, positions, faces, 1.0 / iors.pop() if iors else None)
    return result


# ---------------------------------------------------------------------------------------------
# Inside Blender.


def volume_shader(nodes, links, coeffs, density=None):
    """The Volume socket of Scatter + Absorption for (sigma_a, sigma_s, g); `density` an output
    socket that multiplies both (a grid's density attribute) or None."""
    sigma_a, sigma_s, g = coeffs
    outputs = []
    for kind, values in (("ShaderNodeVolumeScatter", scatter_node(sigma_s)),
                         ("ShaderNodeVolumeAbsorption", absorption_node(sigma_a))):
        if values is None:
            continue
        node = nodes.new(kind)
        node.inputs["Color"].default_value = values[0] + (1.0,)
        if density is None:
            node.inputs["Density"].default_value = values[1]
        else:
            times = nodes.new("ShaderNodeMath")
            times.operation = "MULTIPLY"
            times.inputs[1].default_value = values[1]
            links.new(density, times.inputs[0])
            links.new(times.outputs["Value"], node.inputs["Density"])
        if kind == "ShaderNodeVolumeScatter":
            node.inputs["Anisotropy"].default_value = g
        outputs.append(node.outputs["Volume"])
    if len(outputs) == 2:
        add = nodes.new("ShaderNodeAddShader")
        links.new(outputs[0], add.inputs[0])
        links.new(outputs[1], add.inputs[1])
        return add.outputs["Shader"]
    return outputs[0] if outputs else None


def volume_material(bpy, name, coeffs, glass_ior=None, grid=False):
    """A material with the medium's Volume output; with glass_ior, a sharp Glass BSDF surface of
    that IOR, else no surface (Cycles' boundary of a volume-only material is transparent)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    density = None
    if grid:
        attribute = nodes.new("ShaderNodeAttribute")
        attribute.attribute_name = "density"
        density = attribute.outputs["Fac"]
    volume = volume_shader(nodes, links, coeffs, density)
    if volume is not None:
        links.new(volume, out.inputs["Volume"])
    if glass_ior is not None:
        glass = nodes.new("ShaderNodeBsdfGlass")
        glass.distribution = "SHARP"
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glass.inputs["IOR"].default_value = glass_ior
        links.new(glass.outputs["BSDF"], out.inputs["Surface"])
    return mat


def build(bpy, scene, media_plan, work_dir, tag):
    media = scene.get("media", {})
    collection = bpy.context.scene.collection
    if media_plan.room is not None:
        fog, positions, faces, glass_ior = media_plan.room
        mesh = bpy.data.meshes.new(f"{fog} domain")
        mesh.from_pydata(positions, [], faces)
        mesh.materials.append(volume_material(bpy, f"{fog} domain", coefficients(fog, media[fog]),
                                              glass_ior=glass_ior))
        # All smooth, the box too (never shaded): Cycles' shader id carries the smooth flag, and
        # the volume stack compares ids.
        for polygon in mesh.polygons:
            polygon.use_smooth = True
        mesh.update()
        collection.objects.link(bpy.data.objects.new(mesh.name, mesh))
    for name, size, values, lo, hi in media_plan.grids:
        path = os.path.join(work_dir, f"{tag}-{name}.vdb")
        write_vdb(path, size, values, lo, hi)
        volume = bpy.data.volumes.new(name)
        volume.filepath = path
        volume.render.precision = "FULL"  # the default, HALF, rounds the densities
        volume.render.clipping = 0.0  # the default drops densities below 0.001
        volume.render.step_size = 0.0  # the voxel size, times the step rates
        volume.materials.append(volume_material(bpy, f"{name} volume",
                                                coefficients(name, media[name]), grid=True))
        collection.objects.link(bpy.data.objects.new(name, volume))
