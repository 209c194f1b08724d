"""lamina.render against `lamina render`: the Cornell box from a dict is bit-identical to the
command line's image with the same seed; the GIL is released during a render; Ctrl-C stops it
after the pass in flight with the partial image; bad scenes and overrides are ValueErrors."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import lamina
from conftest import load_scene_dict, run_cli


@pytest.fixture(scope="module")
def cornell(source_dir):
    return os.path.join(source_dir, "scenes", "cornell-box.json")


def test_cornell_box_from_a_dict_equals_the_command_line(lamina_exe, cornell, tmp_path):
    out = tmp_path / "cli.exr"
    status, _, err = run_cli(lamina_exe, "render", cornell, "--spp", "4", "--resolution",
                             "48x48", "--seed", "5", "-q", "-o", str(out))
    assert status == 0, err
    cli, _ = lamina.read_image(str(out))
    img = lamina.render(load_scene_dict(cornell), spp=4, resolution=(48, 48), seed=5)
    assert img.rgb.dtype == np.float32 and img.rgb.shape == (48, 48, 3)
    assert np.array_equal(img.rgb, cli)
    meta = img.metadata
    assert meta["spp"] == 4 and meta["seed"] == 5 and meta["partial"] == 0
    assert meta["scene"] == "<scene dict>" and meta["integrator"] == "path"
    # save() writes the same EXR pixels.
    img.save(str(tmp_path / "py.exr"))
    saved, meta = lamina.read_image(str(tmp_path / "py.exr"))
    assert np.array_equal(saved, cli)


def test_a_path_and_the_overrides(cornell):
    img = lamina.render(cornell, spp=2, resolution="16x24", integrator="bdpt", mode="spectral",
                        max_depth=4, threads=1)
    assert img.rgb.shape == (24, 16, 3) and img.spp == 2 and not img.partial
    assert np.isfinite(img.rgb).all() and img.rgb.mean() > 0
    assert img.metadata["integrator"] == "bdpt" and img.metadata["mode"] == "spectral"


def test_aovs(cornell):
    img = lamina.render(cornell, spp=1, resolution=(16, 16), aovs=True)
    a = img.aovs
    assert a["albedo"].shape == (16, 16, 3) and a["normal"].shape == (16, 16, 3)
    assert a["depth"].shape == (16, 16) and a["variance"].shape == (16, 16)
    # A pixel whose sample hit the box has a positive depth and a unit normal; a pixel that
    # saw only the open front has neither. Most see the box.
    hit = a["depth"] > 0
    assert hit.mean() > 0.8
    np.testing.assert_allclose(np.linalg.norm(a["normal"][hit], axis=-1), 1, rtol=1e-3)
    assert (a["normal"][~hit] == 0).all()


def test_progress_is_called_per_pass(cornell):
    calls = []
    img = lamina.render(cornell, spp=8, resolution=(8, 8), progress=calls.append)
    # Passes of 1, 1, 2, 4 spp (pass_schedule.h).
    assert [c["spp"] for c in calls] == [1, 2, 4, 8]
    assert calls[-1]["fraction"] == 1 and img.spp == 8


def test_the_gil_is_released_during_a_render(cornell):
    ticks = []
    running = threading.Event()
    stop = threading.Event()

    def count():
        running.set()
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    running.wait()
    before = len(ticks)
    start = time.perf_counter()
    lamina.render(cornell, spp=64, resolution=(64, 64))
    end = time.perf_counter()
    during = [x for x in ticks[before:] if start < x < end]
    stop.set()
    t.join()
    # The thread ticks about once per millisecond when it gets the GIL; had the render held
    # the GIL, it could tick only at the seven pass boundaries. A tenth of the rate (at least
    # 30 ticks) leaves room for a loaded machine.
    assert end - start > 0.05
    assert len(during) > max(30, 0.1 * (end - start) / 0.001)


def test_ctrl_c_raises_keyboard_interrupt_with_the_partial_image(cornell):
    started = threading.Event()

    def interrupt():
        started.wait()
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt).start()
    with pytest.raises(KeyboardInterrupt) as e:
        lamina.render(cornell, spp=1 << 20, resolution=(32, 32), progress=lambda p: started.set())
    image = e.value.image
    assert isinstance(e.value, lamina.RenderInterrupted)
    assert image.partial and 1 <= image.spp < 1 << 20
    assert image.rgb.shape == (32, 32, 3) and np.isfinite(image.rgb).all()
    assert image.rgb.mean() > 0
    # The next render is not interrupted.
    assert not lamina.render(cornell, spp=1, resolution=(8, 8)).partial


def test_an_exception_in_progress_stops_the_render(cornell):
    def fail(p):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough") as e:
        lamina.render(cornell, spp=64, resolution=(8, 8), progress=fail)
    assert e.value.image.spp == 1


def test_errors(cornell, lamina_exe, tmp_path):
    scene = load_scene_dict(cornell)
    scene["film"]["resolution"] = [0, 10]
    with pytest.raises(ValueError, match=r"<scene dict>: film\.resolution"):
        lamina.render(scene)
    with pytest.raises(ValueError, match="spp"):
        lamina.render(cornell, spp=0)
    with pytest.raises(ValueError, match="integrator: expected one of path, light, bdpt"):
        lamina.render(cornell, integrator="photon")
    with pytest.raises(ValueError, match="resolution"):
        lamina.render(cornell, resolution=(0, 4))
    with pytest.raises(TypeError, match="spp_per_pass"):
        lamina.render(cornell, spp_per_pass=3)
    bad = tmp_path / "bad.json"
    bad.write_text('{"camera": {"fov": "wide"}}')
    status, _, err = run_cli(lamina_exe, "render", str(bad), "-o", str(tmp_path / "x.exr"))
    with pytest.raises(ValueError) as e:
        lamina.render(str(bad))
    assert status == 1 and err.strip() == "lamina: error: " + str(e.value)


def test_light_selection_and_every_override_the_command_line_has(cornell, lamina_exe, tmp_path):
    img = lamina.render(cornell, spp=1, resolution=(8, 8), seed=3, light_selection="uniform")
    assert img.metadata["light_selection"] == "uniform"
    out = tmp_path / "cli.exr"
    status, _, err = run_cli(lamina_exe, "render", cornell, "--spp", "1", "--resolution", "8x8",
                             "--seed", "3", "--light-selection", "uniform", "-q", "-o", str(out))
    assert status == 0, err
    cli, meta = lamina.read_image(str(out))
    assert np.array_equal(img.rgb, cli)
    with pytest.raises(ValueError, match="light_selection: expected one of bvh, power, uniform"):
        lamina.render(cornell, light_selection="random")


def _through_two_sheets(near):
    """A lamp of radiance 1 seen through a polariser along the image's right and `near`."""
    return {
        "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 5},
        "film": {"resolution": [4, 4]},
        "materials": {"far": {"type": "polariser", "axis": [1, 0, 0]}, "near": near,
                      "lamp": {"type": "lambert", "reflectance": 0}},
        "shapes": [{"type": "rectangle", "material": "near"},
                   {"type": "rectangle", "material": "far",
                    "transform": [{"translate": [0, 0, -1]}]},
                   {"type": "rectangle", "material": "lamp", "emission": {"radiance": 1},
                    "transform": [{"translate": [0, 0, -2]}]}]}


def test_a_polarised_render_returns_its_stokes_layers():
    """Linear light along the image's right through a quarter-wave plate at 45 degrees is
    circular: S3 = -S0 (docs/polarisation.md); the image is S0."""
    scene = _through_two_sheets({"type": "retarder", "axis": [1, 1, 0], "retardance": 90})
    img = lamina.render(scene, spp=2, mode="polarised")
    s = img.stokes
    assert s.dtype == np.float32 and s.shape == (4, 4, 4, 3)
    np.testing.assert_array_equal(s[0], img.rgb)
    # Half the lamp's radiance 1 (spectral colour noise of 2 spp aside), all of it circular.
    assert 0.3 < s[0].mean() < 0.7
    np.testing.assert_allclose(s[3], -s[0], rtol=1e-3, atol=1e-6)
    assert np.abs(s[1:3]).max() < 1e-3 * s[0].max()
    assert lamina.render(scene, spp=1, mode="spectral").stokes is None


def test_a_polarised_render_returns_its_spectral_film():
    """spectral_film=N adds (4, N, H, W) per-bin S0..S3 beside the Stokes layers: the light
    behind the quarter-wave plate (the same at every wavelength) is circular in every bin,
    S3 = -S0; the bins' centres divide 360-830 nm; the rgb mode refuses the keyword."""
    scene = _through_two_sheets({"type": "retarder", "axis": [1, 1, 0], "retardance": 90})
    img = lamina.render(scene, spp=2, mode="polarised", spectral_film=5)
    f = img.spectral_film
    assert f.dtype == np.float32 and f.shape == (4, 5, 4, 4)
    np.testing.assert_allclose(img.spectral_film_nm, 360 + 94 * (np.arange(5) + 0.5))
    assert (f[0].sum(axis=(1, 2)) > 0).all()
    np.testing.assert_allclose(f[3], -f[0], rtol=1e-3, atol=1e-6)
    assert np.abs(f[1:3]).max() < 1e-3 * f[0].max()
    assert img.metadata["spectral_film"] == 5
    plain = lamina.render(scene, spp=1, mode="polarised")
    assert plain.spectral_film is None and plain.spectral_film_nm is None
    assert lamina.render(scene, spp=1, mode="spectral", spectral_film=3).spectral_film.shape \
        == (1, 3, 4, 4)
    with pytest.raises(ValueError, match="--spectral-film: the rgb mode carries no spectrum"):
        lamina.render(scene, spp=1, spectral_film=3)
