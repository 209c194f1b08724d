"""The figure module (python/lamina/figures.py): its scales follow the data, problems() finds
what would mislead a reader (and finds it in a figure broken on purpose), and every figure of
short runs of the experiments is drawn with no problem."""

import importlib.util
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import run_cli


@pytest.fixture(scope="module")
def figures(source_dir):
    # The file the experiments run (its path is compiled into lamina), not a copy.
    path = os.path.join(source_dir, "python", "lamina", "figures.py")
    spec = importlib.util.spec_from_file_location("lamina_figures_under_test", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_map(directory, name, values, **keys):
    values = np.asarray(values, dtype="<f4")
    values.tofile(os.path.join(directory, name + ".f32"))
    spec = {"lamina_figure": 1, "kind": "map", "title": name, "data": name + ".f32",
            "width": values.shape[1], "height": values.shape[0], "quantity": "q", "unit": "u"}
    spec.update(keys)
    path = os.path.join(directory, name + ".figure.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


def write_lines(directory, name, series, **keys):
    spec = {"lamina_figure": 1, "kind": "lines", "title": name, "x_label": "x (m)",
            "y_label": "y (s)", "series": series}
    spec.update(keys)
    path = os.path.join(directory, name + ".figure.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


# ----------------------------------------------------------------- scales from the data

def test_unsigned_scale_runs_from_zero_to_the_99th_percentile(figures):
    v = np.random.default_rng(1).gamma(2.0, 1.5, (200, 300))
    norm, cmap, caption = figures.map_scale(v, signed=False, from_zero=True)
    assert cmap == "viridis" and norm.vmin == 0
    assert norm.vmax == pytest.approx(np.percentile(v, 99))
    # 60000 continuous values: 1% lie above the 99th percentile (to sampling resolution).
    assert figures.clipped_fraction(v, norm) == pytest.approx(0.01, abs=1e-3)
    assert "99th percentile" in caption


def test_signed_scale_is_symmetric_and_diverging(figures):
    v = np.random.default_rng(2).normal(0.3, 0.2, (50, 50))  # mostly positive, still signed
    norm, cmap, _ = figures.map_scale(v, signed=True)
    assert cmap == "RdBu_r"
    assert norm.vmin == -norm.vmax
    assert norm.vmax == pytest.approx(np.percentile(np.abs(v), 99))


def test_a_cyclic_angle_uses_a_cyclic_map_over_its_whole_period(figures, tmp_path):
    v = np.random.default_rng(4).uniform(-30.0, 60.0, (20, 30))
    norm, cmap, caption = figures.map_scale(v, signed=False, cycle=[-90, 90])
    assert cmap == "twilight" and (norm.vmin, norm.vmax) == (-90, 90)
    # -90 and +90 degrees are one line: the map's two ends are one colour (within 2%).
    colours = figures.matplotlib.colormaps[cmap]
    assert np.allclose(colours(0.0), colours(1.0), atol=0.02)
    assert "percentile" in caption
    path = write_map(str(tmp_path), "aolp", v, cycle=[-90, 90])
    fig = figures.draw(figures.load(path))
    assert figures.problems(fig) == []
    assert fig.axes[0].images[0].get_cmap().name == "twilight"


def test_log_scale_only_where_values_span_decades(figures):
    rng = np.random.default_rng(3)
    wide = 10 ** rng.uniform(-3, 1, (40, 40))
    narrow = rng.uniform(1, 5, (40, 40))
    assert type(figures.map_scale(wide, signed=False)[0]).__name__ == "LogNorm"
    assert type(figures.map_scale(narrow, signed=False)[0]).__name__ == "Normalize"
    assert figures.spans_decades([1e-4, 1e-1]) and not figures.spans_decades([1, 50])
    assert not figures.spans_decades([0, 1, 1000])  # a zero cannot go on a log axis


# ----------------------------------------------------------------- problems()

def test_drawn_figures_have_no_problems(figures, tmp_path):
    rng = np.random.default_rng(4)
    spp = [1, 2, 4, 8, 16, 32, 64, 128]
    series = [{"name": f"run {k}", "x": spp, "y": [(1 + k) / s for s in spp],
               "se": [0.1 / s for s in spp]} for k in range(4)]
    lines = figures.draw(figures.load(write_lines(str(tmp_path), "lines", series)))
    axes = lines.axes[0]
    assert axes.get_xscale() == "log" and axes.get_yscale() == "log"
    # The standard errors are bands (PolyCollections), not lines of their own.
    assert len(axes.get_lines()) == 4 and len(axes.collections) == 4
    assert figures.problems(lines) == []
    grid = figures.draw(figures.load(write_map(
        str(tmp_path), "grid", rng.normal(0, 1, (8, 12)), signed=True,
        x_axis={"label": "a (deg)", "first": 0, "last": 88},
        y_axis={"label": "b", "categories": [f"case {i}" for i in range(8)]})))
    assert figures.problems(grid) == []


def test_a_saturated_map_is_a_problem(figures, tmp_path):
    # The shipped layering maps were this: errors of 30-60% on a +-20% scale.
    v = np.random.default_rng(5).uniform(0.3, 0.6, (20, 20))
    fig = figures.draw(figures.load(write_map(str(tmp_path), "m", v, signed=True)))
    assert figures.problems(fig) == []
    fig.axes[0].images[0].set_clim(-0.2, 0.2)
    found = figures.problems(fig)
    assert any("100.0% of the map's values lie beyond" in p for p in found), found
    assert any("1st-99th percentiles" in p for p in found), found


def test_a_clipped_map_with_a_reason_is_not_a_problem_but_limits_still_are(figures, tmp_path):
    v = np.random.default_rng(6).uniform(0, 1, (20, 20))
    spec = figures.load(write_map(str(tmp_path), "m", v, percentile=90,
                                  clip_reason="The brightest tenth is the lamp."))
    fig = figures.draw(spec)
    found = figures.problems(fig)
    assert not any("beyond its colour limits" in p for p in found)
    assert any("1st-99th percentiles" in p for p in found)  # 90th < 99th: still reported


def test_overlapping_text_and_a_legend_outside_are_problems(figures, tmp_path):
    series = [{"name": "a", "x": [0, 1, 2], "y": [1, 2, 3]}]
    fig = figures.draw(figures.load(write_lines(str(tmp_path), "l", series)))
    fig.text(0.5, 0.5, "first label")
    fig.text(0.5, 0.5, "second label")
    assert any("overlaps" in p for p in figures.problems(fig))
    fig = figures.draw(figures.load(write_lines(str(tmp_path), "l", series)))
    fig.axes[0].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    assert any("legend is not inside" in p for p in figures.problems(fig))
    fig = figures.draw(figures.load(write_lines(str(tmp_path), "l", series, y_label="")))
    assert any("without a label" in p for p in figures.problems(fig))


def test_category_labels_beside_a_map_not_over_it(figures, tmp_path):
    # The stability maps' y labels were once centred on their ticks, half over the map.
    axis = lambda label, names: {"label": label, "first": 0, "last": 0, "categories": names}
    spec = figures.load(write_map(
        str(tmp_path), "c", np.arange(12.0).reshape(3, 4), from_zero=True, upper=11.0,
        x_axis=axis("cos", ["1", "0.5", "0.1", "0.01"]),
        y_axis=axis("alpha", ["0.0001", "0.001", "0.5"])))
    fig = figures.draw(spec)
    assert figures.problems(fig) == []
    for label in fig.axes[0].get_yticklabels():
        label.set_horizontalalignment("center")
    assert any("lies over its axes' plot" in p for p in figures.problems(fig))


# ----------------------------------------------------------------- the script

def test_the_script_writes_png_and_pdf_and_refuses_a_bad_spec(source_dir, tmp_path):
    script = os.path.join(source_dir, "python", "lamina", "figures.py")
    write_lines(str(tmp_path), "l", [{"name": "a", "x": [0, 1], "y": [0, 1]}])
    p = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True, text=True)
    assert p.returncode == 0 and p.stderr == "", p.stderr
    with open(tmp_path / "l.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    with open(tmp_path / "l.pdf", "rb") as f:
        assert f.read(5) == b"%PDF-"
    bad = write_map(str(tmp_path), "bad", np.zeros((2, 2)))
    with open(bad) as f:
        spec = json.load(f)
    spec["width"] = 3
    with open(bad, "w") as f:
        json.dump(spec, f)
    p = subprocess.run([sys.executable, script, bad], capture_output=True, text=True)
    assert p.returncode == 1
    assert p.stderr.count("\n") == 1 and p.stderr.startswith("lamina: error: ")
    assert "expected 3 x 2 float32 values, found 4" in p.stderr


# ----------------------------------------------------------------- the experiments' figures

def specs_of(directory):
    return sorted(f for f in os.listdir(directory) if f.endswith(".figure.json"))


def assert_drawn_without_problems(figures, directory):
    """Every figure of a report was drawn by its run (PNG and PDF), and drawn again here it
    shows no problem."""
    specs = specs_of(directory)
    assert specs, os.listdir(directory)
    for name in specs:
        stem = os.path.join(directory, name[: -len(".figure.json")])
        assert os.path.getsize(stem + ".png") > 0 and os.path.getsize(stem + ".pdf") > 0, stem
        spec = figures.load(stem + ".figure.json")
        spec["name"] = name
        assert figures.problems(figures.draw(spec)) == []
    return specs


def test_fresnel_figures(figures, lamina_exe, source_dir, tmp_path):
    scene = os.path.join(source_dir, "scenes", "fresnel-spheres.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "fresnel", "Au", "bk7", "--scene", scene, "--spp", "4",
                           "--resolution", "96x48", "-o", str(out))
    assert code == 0, err
    assert "lamina: note" not in err, err
    specs = assert_drawn_without_problems(figures, str(out))
    assert {"Au.figure.json", "Au_swatches.figure.json", "scene_ciede2000.figure.json",
            "scene_difference.figure.json"} <= set(specs)
    # Per channel, not luminance alone: one panel for each of R, G, B.
    au = figures.load(str(out / "Au.figure.json"))
    assert [p["title"] for p in au["panels"]] == ["R channel", "G channel", "B channel"]
    # CIEDE2000 is a distance: a sequential scale from 0.
    de = figures.load(str(out / "scene_ciede2000.figure.json"))
    assert de["from_zero"] and not de["signed"]
    assert de["values"].shape == (48, 96)  # --resolution
    norm = figures.draw(de).axes[0].images[0].norm
    assert norm.vmin == 0 and norm.vmax == pytest.approx(
        np.nanpercentile(de["values"], 99), rel=1e-6)
    # Every CIEDE2000 statistic beside its noise floor.
    summary = (out / "summary.md").read_text()
    assert "| mean | " in summary and "| 95th percentile | " in summary
    assert summary.count("(noise floor ") == 2, summary


def test_without_matplotlib_the_data_is_written_and_one_line_says_so(lamina_exe, tmp_path):
    fake = tmp_path / "fake"
    (fake / "matplotlib").mkdir(parents=True)
    (fake / "matplotlib" / "__init__.py").write_text("raise ImportError('no matplotlib here')\n")
    env = dict(os.environ, PYTHONPATH=str(fake), LAMINA_PYTHON=sys.executable)
    out = tmp_path / "report"
    p = subprocess.run([lamina_exe, "fresnel", "Cu", "-o", str(out)], capture_output=True,
                       text=True, env=env)
    assert p.returncode == 0, p.stderr
    notes = [line for line in p.stderr.splitlines() if line.startswith("lamina: note")]
    assert len(notes) == 1 and "has no matplotlib" in notes[0], p.stderr
    assert "Cu.figure.json" in specs_of(str(out))
    assert not os.path.exists(out / "Cu.png")
    env["LAMINA_PYTHON"] = str(tmp_path / "no-such-python")
    p = subprocess.run([lamina_exe, "fresnel", "Cu", "-o", str(tmp_path / "r2")],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    assert p.stderr.count("lamina: note: figures not drawn (cannot run") == 1, p.stderr


def test_layering_figures(figures, lamina_exe, source_dir, tmp_path):
    scene = os.path.join(source_dir, "scenes", "layering", "test-object.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "layering", "clear-paint", "--estimates", "16",
                           "--albedo-samples", "4096", "--scene", scene, "--spp", "2",
                           "--resolution", "48x40", "-o", str(out))
    assert code == 0, err
    assert "lamina: note" not in err, err
    specs = assert_drawn_without_problems(figures, str(out))
    error_maps = [s for s in specs if s.endswith("_error.figure.json")]
    assert len(error_maps) == 2, specs  # one per twin
    for name in error_maps:
        spec = figures.load(str(out / name))
        assert spec["signed"]
        norm = figures.draw(spec).axes[0].images[0].norm
        # Limits from the data (the shipped maps were fixed at +-20%): symmetric, at the 99th
        # percentile of |error|.
        assert norm.vmin == -norm.vmax
        assert norm.vmax == pytest.approx(np.nanpercentile(np.abs(spec["values"]), 99),
                                          rel=1e-6)
    maps = [s for s in specs if s.endswith("_ciede2000.figure.json")]
    assert len(maps) == 4  # two twins, two modes
    assert figures.load(str(out / maps[0]))["values"].shape == (40, 48)  # --resolution
    # Each twin's mean and 95th percentile in each mode beside the noise floor: 2 x 2 x 2.
    assert (out / "summary.md").read_text().count("(noise floor ") == 8
    albedo = figures.load(str(out / "clear-paint_albedo.figure.json"))
    walk = albedo["panels"][0]["series"][0]
    assert walk["name"] == "random walk" and len(walk["se"]) == len(walk["y"])
    # The table's own script draws the standard errors as bands too, not as series.
    import runpy
    from unittest import mock
    with mock.patch.object(sys, "argv", ["script", str(tmp_path / "table.png")]):
        runpy.run_path(str(out / "clear-paint_albedo.py"), run_name="__main__")
    import matplotlib.pyplot as plt
    ax = plt.gcf().axes[0]
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels == ["walk", "fresnel", "albedo"], labels
    assert len(ax.collections) == 3  # a band for each: the walk's and the twins' albedo SE
    plt.close("all")


def test_convergence_figures(figures, lamina_exe, source_dir, tmp_path):
    scene = os.path.join(source_dir, "scenes", "cornell-box.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "convergence", scene, "--integrators", "path",
                           "--modes", "rgb", "--time", "1", "--reference-time", "2",
                           "--resolution", "32x32", "-o", str(out))
    assert code == 0, err
    assert "lamina: note" not in err, err
    assert_drawn_without_problems(figures, str(out))
    spec = figures.load(str(out / "convergence.figure.json"))
    fig = figures.draw(spec)
    # Error against time and against samples, both log-log, each pass with its standard error.
    assert [p["title"] for p in spec["panels"]] == ["against time", "against samples"]
    for ax in fig.axes:
        assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    for panel in spec["panels"]:
        (path,) = panel["series"]
        assert len(path["se"]) == len(path["y"]) and all(e > 0 for e in path["se"])


def test_stability_and_reciprocity_figures(figures, lamina_exe, source_dir, tmp_path):
    out = tmp_path / "stability"
    code, _, err = run_cli(lamina_exe, "stability", '{"type":"conductor","material":"Au"}',
                           "--samples", "64", "-o", str(out))
    assert code == 0, err
    assert "lamina: note" not in err, err
    specs = assert_drawn_without_problems(figures, str(out))
    assert {"model1_conductor_issues.figure.json",
            "model1_conductor_float_error.figure.json"} <= set(specs)
    scene = os.path.join(source_dir, "scenes", "reciprocity", "rough-conductor.json")
    out = tmp_path / "reciprocity"
    code, _, err = run_cli(lamina_exe, "reciprocity", scene, "--integrators", "path,light",
                           "--spp", "16", "--batches", "4", "--resolution", "32x24",
                           "-o", str(out))
    assert code in (0, 2), err
    assert "lamina: note" not in err, err
    specs = assert_drawn_without_problems(figures, str(out))
    assert {"t_path_vs_light_pixels.figure.json", "t_path_vs_light_blocks.figure.json"} <= set(specs)
    spec = figures.load(str(out / "t_path_vs_light_pixels.figure.json"))
    assert spec["signed"]  # diverging, symmetric about 0


def test_bsdf_plot_and_spectrum_figures(figures, lamina_exe, tmp_path):
    code, _, err = run_cli(lamina_exe, "bsdf", "plot", '{"type":"standard","roughness":0.3}',
                           "--wo", "0.7,0,0.7", "-o", str(tmp_path / "lobe.png"))
    assert code == 0, err
    assert "lamina: note" not in err, err
    code, _, err = run_cli(lamina_exe, "spectrum", "Cu", "--plot", str(tmp_path / "cu.png"))
    assert code == 0, err
    assert "lamina: note" not in err, err
    assert set(assert_drawn_without_problems(figures, str(tmp_path))) == {
        "lobe.figure.json", "lobe-hemisphere.figure.json", "cu.figure.json"}


def test_polarisation_figures(figures, lamina_exe, source_dir, tmp_path):
    scene = os.path.join(source_dir, "scenes", "polarisation", "two-mirrors.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "polarisation", scene, "--spp", "4", "-o", str(out))
    assert code == 0, err
    specs = assert_drawn_without_problems(figures, str(out))
    assert {"dolp.figure.json", "aolp.figure.json", "ciede2000.figure.json",
            "relative_difference.figure.json"} <= set(specs)
    # DoLP: sequential over its whole range 0..1, grey (NaN) where there is no light.
    dolp = figures.load(str(out / "dolp.figure.json"))
    norm = figures.draw(dolp).axes[0].images[0].norm
    assert (norm.vmin, norm.vmax) == (0, 1)
    # The parallel pair at Brewster's angle passes s light alone (DoLP 1); the crossed pair
    # passes nothing: no value, as the background (64x12 film; the pairs' mirror pixels).
    assert np.allclose(dolp["values"][2:10, 45:59], 1.0, atol=1e-4)
    assert np.all(np.isnan(dolp["values"][2:10, 5:19]))
    # AoLP: cyclic over -90..90, masked where DoLP is below the threshold; the parallel pair's
    # s axis is the image's x: AoLP 0.
    aolp = figures.load(str(out / "aolp.figure.json"))
    assert aolp["cycle"] == [-90, 90]
    assert np.allclose(aolp["values"][2:10, 45:59], 0.0, atol=0.5)
    assert np.all(np.isnan(aolp["values"]) == np.isnan(dolp["values"]))
    summary = (out / "summary.md").read_text()
    # Four statistics, each of the spectral and of the RGB render against the polarised one.
    assert summary.count("(noise floor ") == 8, summary
    assert {"rgb_relative_difference.figure.json", "rgb_ciede2000.figure.json"} <= set(specs)


def test_media_figures(figures, lamina_exe, source_dir, tmp_path):
    scene = os.path.join(source_dir, "scenes", "media", "chromatic-sphere.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "media", scene, "--spp", "4", "--resolution", "32x32",
                           "-o", str(out))
    assert code == 0, err
    specs = assert_drawn_without_problems(figures, str(out))
    assert {"chromatic-sphere_relative_difference.figure.json",
            "chromatic-sphere_ciede2000.figure.json",
            "chromatic-sphere_error_spectral_mis.figure.json",
            "chromatic-sphere_error_hero_only.figure.json"} <= set(specs)
    # The relative difference over its whole range 0..2; the two error maps on one scale.
    relative = figures.load(str(out / "chromatic-sphere_relative_difference.figure.json"))
    norm = figures.draw(relative).axes[0].images[0].norm
    assert (norm.vmin, norm.vmax) == (0, 2)
    limits = [figures.draw(figures.load(str(out / f"chromatic-sphere_error_{n}.figure.json")))
              .axes[0].images[0].norm.vmax for n in ("spectral_mis", "hero_only")]
    assert limits[0] == limits[1] and limits[0] > 0
    summary = (out / "summary.md").read_text()
    # Four statistics of RGB against spectral, each with its floor, and the premises.
    assert summary.count("(noise floor ") == 4, summary
    assert "reference noise (" in summary
    assert not (out / "renders").exists()


def test_polarisation_material_figures(figures, lamina_exe, tmp_path):
    out = tmp_path / "materials"
    code, _, err = run_cli(lamina_exe, "polarisation", "Au", "bk7", "-o", str(out))
    assert code == 0, err
    specs = assert_drawn_without_problems(figures, str(out))
    for stem in ("Au", "bk7"):
        assert {f"{stem}_mueller.figure.json", f"{stem}_reflectance.figure.json",
                f"{stem}_diattenuation.figure.json", f"{stem}_retardance.figure.json"} <= set(specs)
    # The Mueller matrix as a 4 x 4 grid of panels sharing both axes: the x label on the bottom
    # row alone, the y label on the first column alone.
    spec = figures.load(str(out / "Au_mueller.figure.json"))
    assert spec["columns"] == 4 and len(spec["panels"]) == 16
    fig = figures.draw(spec)
    labelled_x = [i for i, ax in enumerate(fig.axes) if ax.get_xlabel()]
    labelled_y = [i for i, ax in enumerate(fig.axes) if ax.get_ylabel()]
    assert labelled_x == [12, 13, 14, 15] and labelled_y == [0, 4, 8, 12]
    # Every number is in the CSV: a row per wavelength (3) and angle (181).
    rows = (out / "Au_mueller.csv").read_text().splitlines()
    assert len(rows) == 1 + 3 * 181 and rows[0].startswith("nm,degrees,Rs,Rp,reflectance")
