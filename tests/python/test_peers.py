"""The arithmetic of the peer benchmarks (benchmarks/peers/peer_efficiency.py and pbrt.py) on
synthetic images of known variance: the reference's noise is taken out, the per-sample variance
and the sample rate multiply to the efficiency, lamina's summary line is read. Fixed seeds;
each statistical check allows 4 standard errors (two-sided significance about 6e-5)."""

import os
import sys

import numpy as np
import pytest

PEERS = os.path.join(os.environ["LAMINA_SOURCE_DIR"], "benchmarks", "peers")
sys.path.insert(0, PEERS)
import peer_efficiency as pe  # noqa: E402
import pbrt  # noqa: E402

SHAPE = (120, 160, 3)
N = SHAPE[0] * SHAPE[1] * SHAPE[2]


def truth(rng):
    return rng.uniform(0.1, 2.0, SHAPE)


def noisy(rng, image, variance):
    return image + rng.normal(0.0, np.sqrt(variance), SHAPE)


def test_halves_take_the_references_noise_out():
    rng = np.random.default_rng(11)
    t = truth(rng)
    var_x, var_h = 0.04, 0.01
    x, h1, h2 = noisy(rng, t, var_x), noisy(rng, t, var_h), noisy(rng, t, var_h)
    estimate, var_mean = pe.mse_against_halves(x, h1, h2)
    # Per value the estimator is e^2 - e (a + b) + a b (e, a, b: the three noises), of variance
    # 2 var_x^2 + 2 var_x var_h + var_h^2.
    se = np.sqrt((2 * var_x**2 + 2 * var_x * var_h + var_h**2) / N)
    assert abs(estimate - var_x) < 4 * se
    assert abs(var_mean - var_h / 2) < 4 * np.sqrt(2 * (2 * var_h) ** 2 / N) / 4
    # Without the correction the reference's noise is counted against the image.
    assert pe.mse(x, h1) - var_x > 10 * se


def test_own_reference_gives_the_per_sample_variance():
    rng = np.random.default_rng(12)
    t = truth(rng)
    v, n, n_ref = 0.5, 16, 256
    x, ref = noisy(rng, t, v / n), noisy(rng, t, v / n_ref)
    v_hat, var_ref = pe.own_reference_variance(pe.mse(x, ref), n, n_ref)
    assert abs(v_hat - v) < 4 * np.sqrt(2.0 / N) * v
    assert var_ref == pytest.approx(v_hat / n_ref, rel=1e-12)


def test_efficiency_is_rate_over_variance():
    lamina = pe.Measurement("lamina", 483, 20.0, 0.19)
    peer = pe.Measurement("peer", 512, 52.0, 0.0935)
    assert lamina.efficiency == pytest.approx(lamina.sample_rate / lamina.per_sample_variance,
                                              rel=1e-12)
    q = pe.ratios(lamina, peer)
    assert q["efficiency"] == pytest.approx(q["variance"] * q["rate"], rel=1e-12)
    assert q["efficiency"] == pytest.approx((0.0935 * 52.0) / (0.19 * 20.0), rel=1e-12)


def test_pbrt_script_recovers_both_factors():
    # A pbrt-v4 image of per-sample variance 2 at 512 spp in 52 s, lamina's of variance 1 at 483
    # spp in 20 s, against lamina's own reference of 8192 spp: the variance ratio is 2, the
    # rate ratio (483 / 20) / (512 / 52).
    rng = np.random.default_rng(13)
    t = truth(rng)
    v_lamina, v_pbrt, n_ref = 1.0, 2.0, 8192
    ref = noisy(rng, t, v_lamina / n_ref)
    lamina_image = noisy(rng, t, v_lamina / 483)
    pbrt_image = noisy(rng, t, v_pbrt / 512)
    [row] = pbrt.measure([(lamina_image, 483, 20.0)], pbrt_image, 512, 52.0, [ref], n_ref)
    q = row["ratios"]
    # Each per-sample variance is estimated within about sqrt(2 / N) (0.5%).
    assert abs(q["variance"] - v_pbrt / v_lamina) < 4 * np.sqrt(2.0 / N) * 2 * 2
    assert q["rate"] == pytest.approx((483 / 20.0) / (512 / 52.0), rel=1e-12)
    assert abs(row["lamina_vs_pbrt"]) < 1e-3
    # A 1% brighter pbrt-v4 image shows in the means.
    [biased] = pbrt.measure([(lamina_image, 483, 20.0)], pbrt_image * 1.01, 512, 52.0, [ref],
                            n_ref)
    assert biased["pbrt_vs_reference"] == pytest.approx(0.01, abs=2e-3)


def test_summary_line_not_progress_line():
    stderr = ("progress: 50% (240 spp, 10.0 s, ETA 10 s)\n"
              "out.exr: 320x180, 483 spp, spectral mode, path integrator, 20.01 s, 1.39e+06 "
              "paths/s, 5.1e+06 rays/s, 0 rejected samples\n")
    assert pe.parse_render_summary(stderr) == (483, 20.01)
    with pytest.raises(pe.PeerError):
        pe.parse_render_summary("progress: 50% (240 spp, 10.0 s, ETA 10 s)\n")


# benchmarks/peers/mesh_loading.py: the meshes it writes are the ones it claims (every triangle
# read back by lamina from both formats, normals on the side the winding faces) and its table's
# arithmetic.
import mesh_loading as ml  # noqa: E402


def test_height_field_winding_faces_its_normals():
    positions, normals, tris = ml.height_field(7, 0.0)
    assert len(tris) == 2 * 7 * 7 and len(positions) == 8 * 8
    p = positions.astype(np.float64)
    face = np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]])
    for k in range(3):
        assert (np.einsum("ij,ij->i", face, normals[tris[:, k]]) > 0).all()
    assert np.allclose(np.linalg.norm(normals, axis=1), 1, atol=1e-6)


@pytest.mark.parametrize("fmt", ["ply", "obj"])
def test_lamina_reads_every_triangle_written(tmp_path, fmt):
    import subprocess

    paths, triangles = ml.make_meshes(str(tmp_path), fmt, 3000, 2)
    assert triangles == 2 * 2 * ml.grid_size(1500) ** 2
    scene = ml.lamina_scene(str(tmp_path), fmt, paths, 2)
    info = subprocess.run([os.environ["LAMINA_EXECUTABLE"], "info", scene], check=True,
                          capture_output=True, text=True).stdout
    assert ml.lamina_triangles(info) == triangles + 2  # and the light's rectangle


def test_mesh_loading_table_divides_as_stated():
    row = {"format": "ply", "triangles": 1000, "MB": 50.0,
           "lamina": {"read": 0.5, "first_pixel": 1.0, "bytes_per_triangle": 100.0},
           "blender": {"read": 5.0, "first_pixel": 8.0, "bytes_per_triangle": 400.0}}
    table = ml.report([row])
    assert "| ply | 1,000 | 50 | lamina | 100.0 | 1.00 | 100 |" in table
    assert "| ply | | | Blender / lamina | 10.00x (time) | 8.00x | 4.00x |" in table
    row["lamina"]["bytes_per_triangle"] = -3.0
    assert "not resolved" in ml.report([row])


# benchmarks/peers/cycles.py's scene translation for Cycles 3.4 (cycles_geometry.py and
# cycles_media.py), without Blender: the volume nodes give lamina's coefficients back, the media's
# domains are closed and wound as Cycles reads them, the density grid lands on lamina's cell
# centres, and what cannot be translated exactly is refused.
import copy  # noqa: E402
import math  # noqa: E402

import cycles  # noqa: E402
import cycles_geometry as cg  # noqa: E402
import cycles_media as cm  # noqa: E402

MEDIA = os.path.join(os.environ["LAMINA_SOURCE_DIR"], "scenes", "media")


def media_scene(name):
    return cycles.load_scene(os.path.join(MEDIA, name))


@pytest.mark.parametrize("medium", [
    {"type": "homogeneous", "sigma_a": 0.02, "sigma_s": 0.25, "g": 0.2},
    {"type": "grid", "sigma_a": [0.4, 0.2, 0.1], "sigma_s": [2, 4, 7], "g": 0.6},
    {"type": "homogeneous", "sigma_a": [0.12, 0.0, 0.2], "sigma_s": [0.0, 0.07, 0.04], "scale": 3},
    {"type": "homogeneous", "sigma_s": [0.5, 1.0, 1.75]},
])
def test_volume_nodes_give_lamina_coefficients(medium):
    sigma_a, sigma_s, g = cm.coefficients("m", medium)
    scale = medium.get("scale", 1)
    assert sigma_s == pytest.approx([scale * v for v in cycles.rgb(medium.get("sigma_s", 0), "")])
    scatter, absorption = cm.scatter_node(sigma_s), cm.absorption_node(sigma_a)
    for node in (scatter, absorption):
        if node is not None:  # colours a node accepts, a density >= 0
            assert all(0.0 <= c <= 1.0 for c in node[0]) and node[1] > 0
    assert (absorption is None) == (max(sigma_a) == 0)
    a, s = cm.cycles_coefficients(scatter, absorption)
    assert a == pytest.approx(sigma_a, rel=1e-12, abs=1e-15)
    assert s == pytest.approx(sigma_s, rel=1e-12, abs=1e-15)
    assert g == medium.get("g", 0.0)


def test_room_domain_is_closed_around_the_camera_with_the_ball_cut_out():
    scene = media_scene("volumetric-caustic.json")
    plan = cm.plan(scene, MEDIA)
    assert plan.camera_medium == "fog" and plan.handled == {0} and not plan.grids
    fog, positions, faces, glass_ior = plan.room
    assert fog == "fog" and cg.is_closed(faces)
    # The room's walls span [-2, 2] x [0, 3] x [-2, 2]; the domain is that box grown by 1e-3 of its
    # largest side, its faces outwards, less the glass ball wound inwards.
    margin = 4e-3
    box = (4 + 2 * margin) * (3 + 2 * margin) * (4 + 2 * margin)
    ball_positions, ball_faces = cg.uv_sphere((0, 1.1, 0), 0.4)
    ball = cg.signed_volume(ball_positions, ball_faces)
    assert ball == pytest.approx(4 / 3 * math.pi * 0.4**3, rel=1e-3)
    assert cg.signed_volume(positions, faces) == pytest.approx(box - ball, rel=1e-12)
    cavity = faces[6:]  # after the box's six
    assert len(cavity) == len(ball_faces) and cg.signed_volume(positions, cavity) < 0
    lo, hi = cg.bounds(positions)
    camera = scene["camera"]["position"]
    assert all(l < c < h for l, c, h in zip(lo, camera, hi))
    assert math.dist(camera, (0, 1.1, 0)) > 0.4
    # Cycles' Glass takes the IOR on a face's front and its inverse on the back; the cavity's
    # faces are turned, so a ray from outside the ball (on their back) sees 1 / (1 / 1.5) = 1.5.
    assert glass_ior == pytest.approx(1 / 1.5)
    # Without the ball, the domain is the box alone, with no surface.
    scene["shapes"][0].pop("exterior")
    assert cm.plan(scene, MEDIA).room[3] is None


def test_room_must_be_closed():
    scene = media_scene("volumetric-caustic.json")
    del scene["shapes"][4]  # the ceiling
    with pytest.raises(cg.Unsupported, match="closed box room"):
        cm.plan(scene, MEDIA)
    with pytest.raises(cg.Unsupported, match="closed box room"):
        cm.plan(media_scene("camera-in-fog.json"), MEDIA)


def test_grid_lands_on_lamina_cell_centres():
    plan = cm.plan(media_scene("chromatic-cloud.json"), MEDIA)
    [(name, size, values, lo, hi)] = plan.grids
    assert name == "cloud" and size == [32, 32, 32] and plan.handled == {0}
    assert lo == [-1.5, -0.5, -1.5] and hi == [1.5, 2.5, 1.5]
    assert cm.outer_cells_zero(size, values) and max(values) > 1
    m = cm.vdb_index_to_world(size, lo, hi)
    h = [(b - a) / n for a, b, n in zip(lo, hi, size)]
    for ijk in [(0, 0, 0), (31, 0, 7), (5, 17, 31)]:
        # Cycles reads voxel ijk's value at index coordinates ijk + 1/2 (measured with a probe grid:
        # docs/media.md); that point must be lamina's cell centre lo + (ijk + 1/2) h.
        row = [ijk[0] + 0.5, ijk[1] + 0.5, ijk[2] + 0.5, 1.0]
        world = [sum(row[r] * m[r][c] for r in range(4)) for c in range(3)]
        assert world == pytest.approx([lo[a] + (ijk[a] + 0.5) * h[a] for a in range(3)], abs=1e-12)
    # The file's values in lamina's order (x fastest): the inline form of the same grid reads alike.
    inline = {"type": "grid", "density": {"size": size, "values": values}}
    assert cm.read_density("c", inline, MEDIA) == (size, values)


def test_vdb_file_holds_the_grid(tmp_path):
    vdb = pytest.importorskip("pyopenvdb", reason="python3-openvdb writes the Cycles grids")
    size, values = [4, 3, 5], [float(v) for v in range(60)]
    lo, hi = [-1.0, 0.0, 2.0], [1.0, 3.0, 7.0]
    path = str(tmp_path / "g.vdb")
    cm.write_vdb(path, size, values, lo, hi)
    grid = vdb.read(path, "density")
    accessor = grid.getConstAccessor()
    for x, y, z in [(0, 0, 0), (3, 2, 4), (1, 2, 3)]:
        assert accessor.getValue((x, y, z)) == values[(z * 3 + y) * 4 + x]
    assert grid.transform.indexToWorld((3.5, 2.5, 4.5)) == pytest.approx((0.75, 2.5, 6.5))


REFUSED = [
    ("emitting", lambda s: s["media"]["fog"].update(Le=1), "Le"),
    ("transformed", lambda s: s["media"]["fog"].update(transform=[{"scale": 2}]), "transform"),
    ("rough cavity", lambda s: s["materials"]["glass"].update(roughness=0.1), "smooth dielectric"),
    ("dispersive cavity", lambda s: s["materials"]["glass"].update(ior="bk7"), "smooth dielectric"),
    ("fog inside the ball", lambda s: s["shapes"][0].update(interior="fog"), "interior 'fog'"),
    ("grid around the camera", lambda s: s["media"]["fog"].update(
        type="grid", density={"size": [1, 1, 1], "values": [0]}), "homogeneous"),
]


@pytest.mark.parametrize("case", REFUSED, ids=[c[0] for c in REFUSED])
def test_unsupported_media_are_refused(case):
    _, edit, message = case
    scene = copy.deepcopy(media_scene("volumetric-caustic.json"))
    edit(scene)
    with pytest.raises(cg.Unsupported, match=message):
        cm.plan(scene, MEDIA)


@pytest.mark.parametrize("edit, message", [
    (lambda m: m.update(density={"size": [2, 1, 1], "values": [0, 1]}), "outermost cells"),
    (lambda m: m.update(density={"size": [1, 1, 1], "values": [0], "channels": 3}), "one channel"),
    (lambda m: m.update(sigma_s_grid="cloud.lgrid"), "sigma_s_grid"),
    (lambda m: m.update(bounds={"min": [-3, -3, -3], "max": [3, 3, 3]}), "contain"),
])
def test_unsupported_grids_are_refused(edit, message):
    scene = media_scene("chromatic-cloud.json")
    edit(scene["media"]["cloud"])
    with pytest.raises(cg.Unsupported, match=message):
        cm.plan(scene, MEDIA)
    for name in ("fog-slab.json", "chromatic-sphere.json", "glass-of-wine.json"):
        with pytest.raises(cg.Unsupported):
            cm.plan(media_scene(name), MEDIA)


def test_disk_keeps_its_area_and_faces_its_normal():
    normal = (0.3, -1.0, 0.2)
    positions, faces = cg.disk((0.5, 2.0, -1.0), normal, 0.11, segments=24)
    area = sum(cg.polygon_area([positions[k] for k in f]) for f in faces)
    assert area == pytest.approx(math.pi * 0.11**2, rel=1e-12)
    for f in faces:
        a, b, c = (positions[k] for k in f)
        n = cg.cross([b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)])
        assert sum(n[i] * normal[i] for i in range(3)) > 0


def test_shapes_as_meshes():
    positions, faces = cg.uv_sphere((1, 2, 3), 2.0, 32, 16)
    assert cg.is_closed(faces) and cg.signed_volume(positions, faces) > 0
    assert all(math.dist(p, (1, 2, 3)) == pytest.approx(2.0) for p in positions)
    positions, faces = cg.box((0, 0, 0), (1, 2, 3))
    assert cg.is_closed(faces) and cg.signed_volume(positions, faces) == pytest.approx(6.0)
    assert not cg.is_closed(faces[1:]) and cg.is_closed(cg.flipped(faces))
    # lamina's transforms apply in order: scale, then a rotation of 90 degrees about x (y to z),
    # then a translation.
    m = cg.transform_matrix([{"scale": 2}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                             {"translate": [0, 3, 0]}], "t")
    assert cg.apply(m, (0, 1, 0)) == pytest.approx((0, 3, 2))
    barrel = {"type": "obj", "file": "lamp-barrel.obj", "material": "black"}
    positions, faces, _ = cg.shape_mesh(barrel, MEDIA, "barrel", ignore_normals=True)
    assert len(positions) == 48 and len(faces) == 24
    with pytest.raises(cg.Unsupported, match="vertex normals"):
        cg.shape_mesh(barrel, MEDIA, "barrel")


def test_reference_time_sets_each_renderers_samples():
    class Args:
        reference_spp, reference_time = 1024, None
    assert cycles.reference_half_spp(Args, (0.5, 0.01)) == 512
    Args.reference_time = 100.0
    # Each half gets 50 s: 0.5 s fixed, then 0.01 s a sample.
    assert cycles.reference_half_spp(Args, (0.5, 0.01)) == 4950
