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
