"""The experiments as functions: compare against NumPy's metrics; fresnel, stability,
layering, convergence and reciprocity return their results (kept small: seconds each)."""

import os

import numpy as np
import pytest

import lamina


@pytest.fixture(scope="module")
def scene(source_dir):
    return os.path.join(source_dir, "scenes", "cornell-box.json")


def test_compare_equals_numpy():
    rng = np.random.default_rng(3)
    a = rng.random((8, 6, 3)).astype(np.float32)
    b = rng.random((8, 6, 3)).astype(np.float32) + 0.1
    d = (a.astype(float) - b.astype(float))
    m = lamina.compare(a, b)
    assert m["mse"] == pytest.approx(np.mean(d**2), rel=1e-12)
    assert m["mae"] == pytest.approx(np.mean(np.abs(d)), rel=1e-12)
    assert m["max"] == pytest.approx(np.max(np.abs(d)), rel=1e-12)
    assert m["relmse"] == pytest.approx(np.mean(d**2 / (b.astype(float) ** 2 + 1e-2)), rel=1e-12)
    assert lamina.compare(a, b, metric="rmse") == pytest.approx(np.sqrt(np.mean(d**2)))
    assert lamina.compare(a, a, metric="max") == 0
    with pytest.raises(ValueError):
        lamina.compare(a, b[:4])


def test_compare_refuses_an_image_of_nans_and_warns_of_some():
    nans = np.full((4, 4, 3), np.nan, dtype=np.float32)
    grey = np.full((4, 4, 3), 0.5, dtype=np.float32)
    with pytest.raises(ValueError, match=r"^a: the image has no finite pixels"):
        lamina.compare(nans, grey)
    some = grey + 0.25
    some[0, 0, 0] = np.nan
    with pytest.warns(RuntimeWarning, match="1 of 48 channel values are NaN"):
        m = lamina.compare(some, grey)
    assert all(np.isfinite(v) for v in m.values())
    assert m["max"] == pytest.approx(0.25)


def test_fresnel():
    (au,) = lamina.fresnel(["Au"])
    assert au["degrees"].shape == (91,)
    exact = au["models"][0]
    assert exact["max_error"] == 0 and exact["rgb"].shape == (91, 3)
    # Every model is 1 at grazing incidence and errs somewhere in between.
    for model in au["models"][1:]:
        np.testing.assert_allclose(model["rgb"][-1], 1, atol=1e-9)
        assert model["max_error"] > 0


def test_stability():
    (model,) = lamina.stability(['{"type":"conductor","material":"Au","alpha":0.3}'], samples=64)
    assert model["issues"].shape == (len(model["alphas"]), len(model["cosines"]))
    assert model["nan"] == 0 and model["inf"] == 0
    polarised = model["polarised"]
    assert polarised["evaluations"] > 0 and polarised["discontinuities"] == 0
    assert polarised["nan"] == 0 and polarised["inf"] == 0


def test_polarisation_of_materials():
    # One name alone is the list of it; materials give the Mueller matrices against angle.
    (bk7,) = lamina.polarisation("bk7", wavelengths=[550])
    (curve,) = bk7["wavelengths"]
    assert curve["mueller"].shape == (181, 4, 4) and bk7["degrees"][-1] == 90
    # Brewster's angle of the index at 550 nm, where only s is reflected: M01 / M00 = 1.
    assert curve["principal_angle"] == pytest.approx(np.degrees(np.arctan(curve["n"])), abs=1e-9)
    np.testing.assert_allclose(curve["diattenuation"], curve["mueller"][:, 0, 1] /
                               curve["mueller"][:, 0, 0])
    au, cu = lamina.polarisation(["Au", "Cu"])
    assert au["conductor"] and [c["nm"] for c in au["wavelengths"]] == [450, 550, 650]
    with pytest.raises(ValueError, match="neither a scene file"):
        lamina.polarisation("Unobtainium")


def test_media(source_dir):
    # One scene alone is the list of it; the result of each scene with its maps and premises.
    sphere = os.path.join(source_dir, "scenes", "media", "chromatic-sphere.json")
    (r,) = lamina.media(sphere, spp=2, reference_spp=8, resolution=(16, 12))
    assert r["spp"] == 2 and r["reference_spp"] == 8
    assert r["relative_difference"].shape == (12, 16) and r["delta_e"].shape == (12, 16)
    for estimator in ("spectral_mis", "hero_only"):
        e = r[estimator]
        assert e["relmse"] > 0 and e["efficiency"] == pytest.approx(
            1 / (e["relmse"] * e["seconds"]))
    assert [p["check"] for p in r["premises"]][0] == "reference"
    assert set(r["mean_delta_e"]) == {"value", "noise_floor", "resolved", "other_seed"}
    cornell = os.path.join(source_dir, "scenes", "cornell-box.json")
    with pytest.raises(ValueError, match="has no participating media"):
        lamina.media(cornell, spp=1)


def test_convergence(scene):
    r = lamina.convergence(scene, integrators=["path"], seconds=0.4, reference_seconds=1.0,
                           resolution=(16, 16))
    (curve,) = r["curves"]
    assert curve["integrator"] == "path" and curve["seconds"].size >= 2
    # Error falls with time.
    assert curve["relmse"][-1] < curve["relmse"][0]
    # Both slopes are numbers or None (too few passes), never NaN.
    for key in ("slope", "slope_spp"):
        assert curve[key] is None or np.isfinite(curve[key])
    # The premises: the reference it rendered is flagged as its own, its noise measured.
    checks = {(p["mode"], p["check"]): p for p in r["premises"]}
    assert checks[("rgb", "reference")]["outcome"] == "flagged"
    assert "self-rendered" in checks[("rgb", "reference")]["detail"]
    assert checks[("rgb", "reference noise")]["outcome"] in ("holds", "flagged")


def test_convergence_refuses_a_reference_of_another_mode_before_rendering(scene, tmp_path):
    import time
    image = lamina.render(scene, spp=2, seed=9, mode="spectral", resolution=(16, 16))
    path = str(tmp_path / "spectral.exr")
    image.save(path)
    start = time.monotonic()
    with pytest.raises(ValueError, match="rendered with mode spectral, the measured renders use rgb"):
        lamina.convergence(scene, integrators=["path"], seconds=30, resolution=(16, 16),
                           reference=path)
    assert time.monotonic() - start < 20, "refused only after rendering"


def test_reciprocity(scene):
    r = lamina.reciprocity(scene, integrators=["path", "light"], spp=8, batches=4,
                           resolution=(12, 12), max_depth=3)
    (pair,) = r["pairs"]
    assert {pair["a"], pair["b"]} == {"path", "light"} and isinstance(r["agree"], bool)
    assert len(r["materials"]) > 0


def test_layering():
    (m,) = lamina.layering(['{"type":"coated","ior":1,"base":{"type":"lambert","reflectance":0.6}}'],
                           estimates=4, albedo_samples=65536)
    # An index-matched coat is the bare base: the walk's albedo is 0.6 exactly, and both
    # twins agree within 1% at every angle.
    np.testing.assert_allclose(m["walk_albedo"], 0.6, atol=1e-12)
    assert [t["name"] for t in m["twins"]] == ["fresnel coupling", "albedo coupling"]
    for t in m["twins"]:
        assert set(t["albedo_agreement"]) == {"within 1%"}
        n = len(m["map_angles"])
        assert t["map_error"].shape == (n, n)
        assert np.all(np.abs(t["map_error"]) < 1e-6)
    # Coated gold's twins are one pass through the coat over the rough conductor (the note
    # says so); a smooth conductor base has no twin at all.
    (gold,) = lamina.layering(["coated-gold"], estimates=4, albedo_samples=256)
    assert [t["name"] for t in gold["twins"]] == ["fresnel coupling", "albedo coupling"]
    assert "one pass" in gold["note"]
    for t in gold["twins"]:
        assert np.all((t["albedo"] > 0) & (t["albedo"] < 1))
    (mirror,) = lamina.layering(
        ['{"type":"coated","ior":1.5,"base":{"type":"conductor","material":"Au","roughness":0}}'],
        estimates=2, albedo_samples=64)
    assert mirror["twins"] == [] and "smooth conductor" in mirror["note"]


def test_convergence_takes_the_command_lines_options(scene):
    r = lamina.convergence(scene, integrators=["light"], seconds=0.3, reference_seconds=0.6,
                           resolution=(12, 12), levels=[0.5, "1e-1"], reference_integrator="bdpt",
                           sampler="independent")
    (curve,) = r["curves"]
    assert curve["integrator"] == "light"
    assert list(curve["time_to_relmse"]) == ["0.5", "1e-1"]
    with pytest.raises(ValueError, match="reference_integrator: expected one of path, light, bdpt"):
        lamina.convergence(scene, reference_integrator="photon")
    with pytest.raises(ValueError, match="levels: expected numbers"):
        lamina.convergence(scene, levels=["small"])
    with pytest.raises(TypeError, match="merged"):
        lamina.convergence(scene, merged="a.exr")


def test_reciprocity_takes_the_ablations(scene):
    with pytest.raises(ValueError, match='ablate: unknown "drop"; expected adjoint-correction'):
        lamina.reciprocity(scene, ablate=["drop"])


def test_ctrl_c_during_convergence_carries_the_finished_runs(scene):
    # The reference (1 s) and the path run (4 s) are done before the signal at 7 s, the
    # light run (4 s more) is in flight: KeyboardInterrupt comes within a second with
    # .partial, the result of what was finished.
    import signal
    import subprocess
    import sys
    import time
    code = (
        "import lamina\n"
        f"SCENE = {scene!r}\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    lamina.convergence(SCENE, integrators=['path', 'light'], seconds=4,\n"
        "                       reference_seconds=1, resolution=(16, 16))\n"
        "except KeyboardInterrupt as e:\n"
        "    print('interrupted', flush=True)\n"
        "    print([c['integrator'] for c in e.partial['curves']])\n"
        "    print(sorted({p['check'] for p in e.partial['premises']}))\n"
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True,
                         env=dict(os.environ))
    assert p.stdout.readline().strip() == "started"
    time.sleep(7)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    line = p.stdout.readline().strip()
    stopped = time.monotonic() - sent
    # Line by line: communicate() with a timeout reads the pipe itself, past what readline
    # has already buffered.
    curves, checks = p.stdout.readline().strip(), p.stdout.readline().strip()
    assert p.wait(timeout=30) == 0
    assert line == "interrupted", line
    assert stopped < 1.0, f"KeyboardInterrupt {stopped:.2f} s after SIGINT"
    assert curves == "['path']", curves
    assert "reference" in checks, checks


def test_ctrl_c_during_reciprocity_carries_the_finished_renders(scene):
    # 768 batch renders of a few milliseconds each, SIGINT after two seconds: KeyboardInterrupt
    # within a second, with .partial holding the batches finished, in order, as images.
    import signal
    import subprocess
    import sys
    import time
    code = (
        "import lamina\n"
        f"SCENE = {scene!r}\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    lamina.reciprocity(SCENE, spp=2048, batches=256, resolution=(16, 16))\n"
        "except KeyboardInterrupt as e:\n"
        "    print('interrupted', flush=True)\n"
        "    renders = e.partial['renders']\n"
        "    print(len(renders), renders[0]['name'], renders[-1]['name'], flush=True)\n"
        "    print(renders[0]['rgb'].shape, renders[0]['spp'], renders[0]['integrator'])\n"
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True,
                         env=dict(os.environ))
    assert p.stdout.readline().strip() == "started"
    time.sleep(2)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    line = p.stdout.readline().strip()
    stopped = time.monotonic() - sent
    counts, first = p.stdout.readline().split(), p.stdout.readline().strip()
    assert p.wait(timeout=30) == 0
    assert line == "interrupted", line
    assert stopped < 1.0, f"KeyboardInterrupt {stopped:.2f} s after SIGINT"
    assert 1 <= int(counts[0]) < 768, counts
    assert counts[1] == "path_batch00", counts
    assert first == "(16, 16, 3) 8 path", first


@pytest.mark.parametrize("call", [
    'lamina.layering(["varnished-wood"], estimates=1000000)',
    'lamina.convergence(SCENE, integrators=["path"], seconds=60, reference_seconds=120, '
    'resolution=(64, 64))',
])
def test_ctrl_c_stops_an_experiment_within_a_second(scene, call):
    # SIGINT two seconds into minutes of work: KeyboardInterrupt reaches the caller, the
    # process ends within a second of the signal (well before the work would), and the
    # interrupt flag is cleared for the next call.
    import signal
    import subprocess
    import sys
    import time
    code = (
        "import sys, time, lamina\n"
        f"SCENE = {scene!r}\n"
        "print('started', flush=True)\n"
        "try:\n"
        f"    {call}\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    m = lamina.Material({'type': 'lambert'})\n"
        "    r = lamina.layering(['{\"type\":\"coated\",\"ior\":1,\"base\":{\"type\":\"lambert\"}}'],\n"
        "                        estimates=2, albedo_samples=64)\n"
        "    print('next call ran', len(r), flush=True)\n"
        "    sys.exit(3)\n"
    )
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True,
                         env=dict(os.environ))
    assert p.stdout.readline().strip() == "started"
    time.sleep(2)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    line = p.stdout.readline().strip()
    stopped = time.monotonic() - sent
    out, _ = p.communicate(timeout=30)
    assert line == "interrupted", line + out
    assert stopped < 1.0, f"KeyboardInterrupt {stopped:.2f} s after SIGINT"
    assert p.returncode == 3, out
    assert "next call ran 1" in out, out
