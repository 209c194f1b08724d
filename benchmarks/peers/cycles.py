#!/usr/bin/env python3
"""lamina against Blender Cycles 3.4 at equal wall time, from one scene description.

A benchmark, not a test (never run in CI): it needs Blender 3.4 from Debian
(`apt-get install -y blender`). The lamina scene file is the one description: this script
reads it and builds the same scene in Cycles with bpy (with the settings that make Cycles
unbiased and comparable: cycles_settings), then for each scene

  1. renders two calibration images with each renderer (16 and 64 spp) to learn its fixed
     time (BVH, scene sync) and its time per sample;
  2. renders a long reference with each renderer, as two independent halves (seeds 101 and
     102), so that the reference's own noise can be taken out of the error: for an image x
     and halves h1, h2 of an unbiased renderer, E[(x - h)^2] = MSE(x) + var(h) and
     E[(h1 - h2)^2] = 2 var(h), hence MSE(x) = (MSE(x, h1) + MSE(x, h2)) / 2 - MSE(h1, h2) / 2;
  3. for each time T of --times renders lamina and then Cycles (seed 0, uncorrelated with the
     references) at the sample count that fits T, records the wall time each really took and
     its MSE against its own renderer's reference;
  4. prints the efficiency 1 / (MSE x time) of each and the ratio lamina / Cycles (above 1:
     lamina reaches a lower error in the same time).

Times (--clock wall, the default, for a quiet machine): lamina's is the render time it prints (BVH and sampling, not the process start-up);
Cycles' is measured around bpy.ops.render.render (scene sync, BVH and sampling), not Blender's
start-up or the scene construction in Python. Both use two threads. On a machine shared with
other work use --clock cpu: the CPU seconds of all threads, for lamina of the whole process
(start-up and scene loading included), for Cycles of the Blender process during the render.

Run from the repository root:
  python3 benchmarks/peers/cycles.py scenes/cornell-box.json scenes/glossy-metal-sphere.json \
      --lamina build/app/lamina --times 2 4 8 --reference-spp 1024
  python3 benchmarks/peers/cycles.py scenes/media/volumetric-caustic.json \
      scenes/media/chromatic-cloud.json --lamina build/app/lamina --clock cpu --times 4 8 16 \
      --reference-time 128

--reference-time T gives each renderer's reference (both halves) T seconds by its calibration
instead of the same --reference-spp for both: a renderer that draws samples faster gets more, so
that neither reference is the noisier one for the budgets' images.

Supported lamina features (anything else is refused with a message): the perspective camera
(position, look_at, up, vertical fov), the film resolution, max_depth; materials `lambert`,
`conductor` given by f0 (Schlick) and smooth `dielectric` of one numeric ior (a sharp Glass
BSDF); shapes `mesh`, `rectangle`, `sphere`, `disk` (a polygon of the disk's area) and `obj`
(positions and faces; vertex normals only on a black surface, which does not shade), with
`transform` (cycles_geometry.py); one-sided or two-sided emission with an RGB radiance; a constant
`environment` light; participating media (cycles_media.py, its docstring says how they map): a
homogeneous medium around the camera filling a closed box room, clear glass spheres in it, and
grid media in interface spheres. Cycles always path traces (it has no BDPT or light tracing);
lamina renders with the scene's integrator, `bdpt` for the volumetric caustic: both converge to
the same image, and the efficiency ratio then compares lamina's choice of integrator with
Cycles' only one. Participating media need pyopenvdb for grid media (`apt-get install -y
python3-openvdb`: Blender 3.4 from Debian runs on the system's Python and imports it too).
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_geometry  # noqa: E402  (lamina's shapes as meshes)
import cycles_media  # noqa: E402  (participating media as Cycles volumes)
import peer_efficiency  # noqa: E402  (running lamina, image errors, efficiency arithmetic)
from cycles_geometry import Unsupported  # noqa: E402

# Two calibration renders per renderer: the time of a render is about fixed + spp x per_spp
# (the fixed part is lamina's BVH build, Cycles' scene sync and BVH), and a single short
# render cannot tell the two apart: budgets set from 16 spp alone came out 55-137% of the time
# asked.
CALIBRATION_SPP = (16, 64)


def strip_comments(text):
    """lamina scene files are JSON with // and /* */ comments (nlohmann's ignore_comments)."""
    out, i, n, in_string = [], 0, len(text), False
    while i < n:
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = n if end < 0 else end + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def load_scene(path):
    with open(path, encoding="utf-8") as f:
        return json.loads(strip_comments(f.read()))


def rgb(value, what):
    if isinstance(value, (int, float)):
        return (float(value),) * 3
    if isinstance(value, list) and len(value) == 3 and all(isinstance(v, (int, float)) for v in value):
        return tuple(float(v) for v in value)
    raise Unsupported(f"{what}: expected a number or [r, g, b], got {value!r}")


# ---------------------------------------------------------------------------------------------
# Inside Blender: build the scene with bpy and render it.


def cycles_settings(scene, bpy_scene, spp, seed):
    """The settings that make Cycles an unbiased reference comparable with lamina (its factory
    defaults are biased; they clamp indirect light at 10, for one): CPU, 2 threads, no
    denoising, no adaptive sampling, no clamping, no light threshold, no glossy blur, caustics
    on, every bounce limit from max_depth, a 1 px box filter (lamina's box of radius 0.5)."""
    r = bpy_scene.render
    c = bpy_scene.cycles
    r.engine = "CYCLES"
    c.device = "CPU"
    r.threads_mode = "FIXED"
    r.threads = 2
    width, height = scene.get("film", {}).get("resolution", [512, 512])
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    c.samples = spp
    c.seed = seed
    c.use_animated_seed = False
    c.use_denoising = False
    c.use_adaptive_sampling = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    # lamina's max_depth counts scattering events (1: direct light only); Cycles' bounces
    # count the bounces after the first (0: direct light only).
    bounces = max(0, scene.get("integrator", {}).get("max_depth", 16) - 1)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces
    c.transmission_bounces = c.volume_bounces = bounces
    # A volume's boundary is a transparent surface to Cycles, lamina's index-matched boundaries
    # are no scattering events: let paths cross as many as they meet.
    c.transparent_max_bounces = 1024
    # Cycles 3.4 ray-marches heterogeneous volumes in steps of the voxel size times this rate.
    c.volume_step_rate = float(os.environ.get("LAMINA_PEER_VOLUME_STEP_RATE", "1"))
    c.min_light_bounces = 0
    c.min_transparent_bounces = 0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    bpy_scene.view_settings.view_transform = "Standard"
    bpy_scene.view_settings.look = "None"
    bpy_scene.view_settings.exposure = 0.0
    bpy_scene.view_settings.gamma = 1.0
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "32"
    r.image_settings.exr_codec = "ZIP"


def make_material(bpy, name, desc, emission):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if emission is not None:
        radiance = rgb(emission.get("radiance"), f"{name}: emission.radiance")
        scale = max(radiance)
        em = nodes.new("ShaderNodeEmission")
        em.inputs["Color"].default_value = tuple(v / scale if scale > 0 else 0.0 for v in radiance) + (1.0,)
        if emission.get("two_sided", False):
            em.inputs["Strength"].default_value = scale
        else:
            # One-sided like lamina's: strength x (1 - Backfacing), so colour x strength is
            # exactly the radiance on the front (Blender's area lamps are not radiometric,
            # radiance = P / (4 A), hence a mesh with an Emission shader).
            geometry = nodes.new("ShaderNodeNewGeometry")
            front = nodes.new("ShaderNodeMath")
            front.operation = "SUBTRACT"
            front.inputs[0].default_value = 1.0
            links.new(geometry.outputs["Backfacing"], front.inputs[1])
            strength = nodes.new("ShaderNodeMath")
            strength.operation = "MULTIPLY"
            strength.inputs[1].default_value = scale
            links.new(front.outputs["Value"], strength.inputs[0])
            links.new(strength.outputs["Value"], em.inputs["Strength"])
        surface = em.outputs["Emission"]
        reflectance = desc.get("reflectance", 0) if desc.get("type") == "lambert" else None
        if desc.get("type") != "lambert" or max(rgb(reflectance, name)) > 0:
            raise Unsupported(f"{name}: an emitter's own material must be a black lambert")
        links.new(surface, out.inputs["Surface"])
        return mat
    kind = desc.get("type")
    if kind == "lambert":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = rgb(desc.get("reflectance", 0.5), name) + (1.0,)
        bsdf.inputs["Roughness"].default_value = 0.0
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    elif kind == "dielectric" and set(desc) <= {"type", "ior", "roughness"} and \
            isinstance(desc.get("ior", 1.5), (int, float)) and desc.get("roughness", 0) == 0:
        # Sharp glass: exact dielectric Fresnel, reflection or refraction chosen by it; Cycles
        # leaves out radiance's 1 / eta^2 on refraction, which cancels on a closed object
        # entered and left in the same medium.
        bsdf = nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "SHARP"
        bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        bsdf.inputs["IOR"].default_value = float(desc.get("ior", 1.5))
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    elif kind == "conductor" and "f0" in desc:
        if desc.get("fresnel") != "schlick" or "f82" in desc:
            raise Unsupported(f"{name}: a conductor is compared as f0 with \"fresnel\": \"schlick\"")
        # Principled metal: base colour = F0, its Fresnel blends towards white at grazing
        # angles (not exactly Schlick in 3.4: it blends the base colour with the exact
        # dielectric Fresnel of ior 1.5, so the two differ at grazing angles only). Roughness
        # is Blender's: alpha = r^2, as lamina's.
        bsdf = nodes.new("ShaderNodeBsdfPrincipled")
        bsdf.distribution = "GGX"
        bsdf.inputs["Base Color"].default_value = rgb(desc["f0"], name) + (1.0,)
        bsdf.inputs["Metallic"].default_value = 1.0
        bsdf.inputs["Roughness"].default_value = float(desc.get("roughness", 0.0))
        bsdf.inputs["Specular"].default_value = 0.5
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    else:
        raise Unsupported(f"{name}: material type {kind!r} (this comparison knows lambert, "
                          f"conductor with f0 and dielectric with one numeric ior, smooth)")
    return mat


def add_shape(bpy, mathutils, i, shape, materials, scene_dir):
    what = f"shapes[{i}]"
    mat_desc = shape.get("material")
    if not isinstance(mat_desc, str) or mat_desc not in materials:
        raise Unsupported(f"{what}: material must name one of the scene's materials")
    # No analytic spheres or disks in Cycles: finely tessellated meshes (cycles_geometry), the
    # spheres smooth-shaded. A black lambert does not shade: an OBJ's normals do not matter.
    desc = materials[mat_desc]
    black = desc.get("type") == "lambert" and max(rgb(desc.get("reflectance", 0.5), mat_desc)) == 0
    positions, faces, matrix = cycles_geometry.shape_mesh(shape, scene_dir, what,
                                                          ignore_normals=black)
    mesh = bpy.data.meshes.new(shape.get("name", what))
    mesh.from_pydata(positions, [], faces)
    if shape.get("type") == "sphere":
        for polygon in mesh.polygons:
            polygon.use_smooth = True
    mesh.update()
    emission = shape.get("emission")
    key = (mat_desc, json.dumps(emission, sort_keys=True))
    if key not in add_shape.cache:
        add_shape.cache[key] = make_material(bpy, f"{mat_desc}-{len(add_shape.cache)}",
                                             materials[mat_desc], emission)
    mesh.materials.append(add_shape.cache[key])
    obj = bpy.data.objects.new(mesh.name, mesh)
    obj.matrix_world = mathutils.Matrix(matrix)
    bpy.context.scene.collection.objects.link(obj)


add_shape.cache = {}


def set_camera(bpy, mathutils, scene):
    c = scene.get("camera", {})
    if c.get("type", "perspective") != "perspective" or "focal_length" in c or c.get("aperture"):
        raise Unsupported("camera: a pinhole perspective camera with fov")
    position = mathutils.Vector(c.get("position", [0, 0, 0]))
    target = mathutils.Vector(c.get("look_at", [0, 0, 1]))
    up = mathutils.Vector(c.get("up", [0, 1, 0]))
    # Blender cameras look down local -Z with +Y up.
    z = (position - target).normalized()
    x = up.cross(z).normalized()
    y = z.cross(x)
    m = mathutils.Matrix((x, y, z)).transposed().to_4x4()
    m.translation = position
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(c.get("fov", 40.0))
    # In a medium the camera's rays start at clip_start: the fog before it is left out.
    data.clip_start = 1e-6 if cycles_media.side(c, "medium") else 1e-3
    data.clip_end = 1e7
    obj = bpy.data.objects.new("camera", data)
    obj.matrix_world = m
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def set_world(bpy, scene):
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    colour, strength = (0.0, 0.0, 0.0), 0.0
    for light in scene.get("lights", []):
        if light.get("type") != "environment" or "file" in light or "texture" in light:
            raise Unsupported(f"light {light!r}: only a constant environment")
        colour, strength = rgb(light.get("radiance", 1.0), "environment.radiance"), 1.0
    background.inputs["Color"].default_value = colour + (1.0,)
    background.inputs["Strength"].default_value = strength
    bpy.context.scene.world = world


def render_in_blender(scene_path, spp, seed, output):
    import bpy
    import mathutils

    # Cycles path traces whatever the scene's integrator (it has no BDPT or light tracing):
    # lamina's integrators converge to the same image.
    scene = load_scene(scene_path)
    scene_dir = os.path.dirname(os.path.abspath(scene_path))
    media_plan = cycles_media.plan(scene, scene_dir)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    s = bpy.context.scene
    cycles_settings(scene, s, spp, seed)
    set_camera(bpy, mathutils, scene)
    set_world(bpy, scene)
    materials = scene.get("materials", {})
    for i, shape in enumerate(scene.get("shapes", [])):
        if i not in media_plan.handled:
            add_shape(bpy, mathutils, i, shape, materials, scene_dir)
    tag = os.path.splitext(os.path.basename(output))[0]
    cycles_media.build(bpy, scene, media_plan, os.path.dirname(os.path.abspath(output)), tag)
    clock = time.process_time if os.environ.get("LAMINA_PEER_CLOCK") == "cpu" else time.perf_counter
    start = clock()
    bpy.ops.render.render()
    seconds = clock() - start
    bpy.data.images["Render Result"].save_render(output)
    print(f"lamina-peer-seconds {seconds:.4f}", flush=True)


# ---------------------------------------------------------------------------------------------
# Outside Blender: run both renderers, measure.


class Runner:
    def __init__(self, args, work):
        self.args, self.work = args, work

    def lamina(self, scene, spp, seed, name):
        try:
            out, _, seconds = peer_efficiency.run_lamina(
                self.args.lamina, scene, os.path.join(self.work, name + ".exr"), spp=spp,
                seed=seed, mode="rgb", clock=self.args.clock)
        except peer_efficiency.PeerError as e:
            sys.exit(f"cycles.py: {e}")
        return out, seconds

    def cycles(self, scene, spp, seed, name):
        out = os.path.join(self.work, name + ".exr")
        cmd = [self.args.blender, "-b", "--factory-startup", "-t", "2", "-P", os.path.abspath(__file__),
               "--", "--inside-blender", scene, str(spp), str(seed), out]
        env = dict(os.environ, LAMINA_PEER_CLOCK=self.args.clock,
                   LAMINA_PEER_VOLUME_STEP_RATE=str(self.args.volume_step_rate))
        p = subprocess.run(cmd, capture_output=True, text=True, env=env)
        m = re.search(r"lamina-peer-seconds ([0-9.]+)", p.stdout)
        if p.returncode != 0 or not m or not os.path.exists(out):
            sys.exit(f"cycles.py: Blender failed: {' '.join(cmd)}\n{p.stdout[-3000:]}\n{p.stderr[-3000:]}")
        return out, float(m.group(1))

    def mse(self, image, reference):
        try:
            return peer_efficiency.compare_mse(self.args.lamina, image, reference)
        except peer_efficiency.PeerError as e:
            sys.exit(f"cycles.py: {e}")


def reference_half_spp(args, timing):
    """Samples per reference half: --reference-spp / 2, or with --reference-time T what fits T / 2
    seconds by the renderer's calibration (fixed, per_spp), so that each renderer's reference is
    as long, whatever its speed."""
    if args.reference_time is None:
        return max(1, args.reference_spp // 2)
    fixed, per_spp = timing
    return max(1, round((args.reference_time / 2 - fixed) / per_spp))


def measure_scene(runner, scene, args):
    tag = os.path.splitext(os.path.basename(scene))[0]
    renderers = {"lamina": runner.lamina, "cycles": runner.cycles}
    timing, references = {}, {}
    for name, render in renderers.items():
        (n0, n1) = CALIBRATION_SPP
        t0 = render(scene, n0, 7, f"{tag}-{name}-calibration-{n0}")[1]
        t1 = render(scene, n1, 7, f"{tag}-{name}-calibration-{n1}")[1]
        per_spp = max(t1 - t0, 1e-6) / (n1 - n0)
        timing[name] = (max(0.0, t0 - n0 * per_spp), per_spp)
        half_spp = reference_half_spp(args, timing[name])
        halves = [render(scene, half_spp, seed, f"{tag}-{name}-reference-{seed}")
                  for seed in (101, 102)]
        h1, h2 = halves[0][0], halves[1][0]
        between_halves = runner.mse(h1, h2)
        references[name] = (h1, h2, between_halves[0] / 2.0, halves[0][1] + halves[1][1],
                            between_halves[1], 2 * half_spp)
    agreement = runner.mse(references["lamina"][0], references["cycles"][0])[1]
    print(f"\n## {scene}")
    print(f"references as two halves: lamina {references['lamina'][5]} spp in "
          f"{references['lamina'][3]:.1f} s, Cycles {references['cycles'][5]} spp in "
          f"{references['cycles'][3]:.1f} s; relMSE of lamina's half against Cycles' half: "
          f"{agreement:.3g}, of lamina's two halves {references['lamina'][4]:.3g}, of Cycles' two "
          f"halves {references['cycles'][4]:.3g} (the two renderers agree on the image when the "
          f"first lies between the other two: a difference between the images would add to it)")
    print("| time budget | lamina spp | lamina s | lamina MSE | Cycles spp | Cycles s | Cycles MSE "
          "| lamina / Cycles efficiency |")
    print("|---|---|---|---|---|---|---|---|")
    ratios = []
    for budget in args.times:
        row, noisy = {}, []
        for name, render in renderers.items():
            fixed, per_spp = timing[name]
            spp = max(1, round((budget - fixed) / per_spp))
            image, t = render(scene, spp, 0, f"{tag}-{name}-{budget:g}s")
            h1, h2, half_variance = references[name][:3]
            mse = 0.5 * (runner.mse(image, h1)[0] + runner.mse(image, h2)[0]) - half_variance
            # The subtraction is unbiased, but once a reference half is as noisy as the image
            # the estimate is mostly the halves' noise: such a row proves nothing.
            if not mse >= half_variance or not t > 0:
                noisy.append(name)
            row[name] = (spp, t, mse)
        (ls, lt, lm), (cs, ct, cm) = row["lamina"], row["cycles"]
        if noisy:
            print(f"| {budget:g} s | {ls} | {lt:.2f} | {lm:.3g} | {cs} | {ct:.2f} | {cm:.3g} | not "
                  f"measured: {' and '.join(noisy)}'s reference halves are as noisy as the image "
                  f"(raise --reference-spp or --reference-time) |")
            continue
        ratio = (cm * ct) / (lm * lt)
        ratios.append(ratio)
        print(f"| {budget:g} s | {ls} | {lt:.2f} | {lm:.3g} | {cs} | {ct:.2f} | {cm:.3g} | {ratio:.2f}x |")
    if not ratios:
        print("efficiency ratio lamina / Cycles: no budget measured (references too short)")
        return None
    geometric_mean = peer_efficiency.geometric_mean(ratios)
    print(f"efficiency ratio lamina / Cycles, geometric mean over the {len(ratios)} measured "
          f"budgets: {geometric_mean:.2f}x")
    return geometric_mean


def main():
    if "--inside-blender" in sys.argv:
        scene, spp, seed, output = sys.argv[sys.argv.index("--inside-blender") + 1:][:4]
        try:
            render_in_blender(scene, int(spp), int(seed), output)
        except Unsupported as e:
            print(f"cycles.py: {scene}: {e}", file=sys.stderr)
            sys.exit(1)
        return
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenes", nargs="+", help="lamina scene files")
    parser.add_argument("--lamina", default="build/app/lamina")
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--times", type=float, nargs="+", default=[2.0, 4.0, 8.0],
                        help="wall-time budgets in seconds")
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--reference-time", type=float,
                        help="seconds of each renderer's reference (its two halves together), "
                             "instead of --reference-spp: the samples that fit by its calibration")
    parser.add_argument("--volume-step-rate", type=float, default=1.0,
                        help="Cycles' volume step rate (render settings; its step through a grid "
                             "medium is the voxel size times this): smaller is less biased, slower")
    parser.add_argument("--clock", choices=["wall", "cpu"], default="wall",
                        help="wall: wall time (a quiet machine); cpu: CPU seconds of all the "
                             "renderer's threads, for a machine shared with other work, where "
                             "wall time measures the scheduler's share more than the renderer")
    parser.add_argument("--keep", help="directory to keep the images in (default: a temporary one)")
    args = parser.parse_args()
    print(f"at the start, {peer_efficiency.load_note()}")
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
        for scene in args.scenes:
            measure_scene(Runner(args, args.keep), scene, args)
    else:
        with tempfile.TemporaryDirectory() as work:
            for scene in args.scenes:
                measure_scene(Runner(args, work), scene, args)
    print(f"load average at the end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
