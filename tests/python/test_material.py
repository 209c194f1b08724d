"""lamina.Material against the command line (`lamina bsdf eval|sample|albedo`), the
identity weight = eval / pdf, a chi-square test of sample() against pdf(), and the errors."""

import json
import math
import pathlib

import numpy as np
import pytest

import lamina
from conftest import run_cli

# A sample of the material models: layered standard, lobes alone, conductor, glass, mix.
MATERIALS = [
    '{"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.4}',
    '{"type":"standard","base_color":[0.9,0.9,0.9],"metalness":1,"roughness":0.2}',
    '{"type":"standard","base_color":0.5,"roughness":0.3,"transmission":1,"ior":1.5}',
    '{"type":"conductor","material":"Au","alpha":0.3}',
    '{"type":"dielectric","ior":1.5,"alpha":0.25}',
    '{"type":"lambert","reflectance":[0.2,0.6,0.3]}',
    '{"type":"phong","reflectance":0.7,"shininess":40}',
]


def directions(n, seed, lower=True):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3))
    if not lower:
        v[:, 2] = np.abs(v[:, 2])
    return v / np.linalg.norm(v, axis=1, keepdims=True)


@pytest.mark.parametrize("material", MATERIALS)
@pytest.mark.parametrize("mode", ["rgb", "spectral"])
def test_eval_and_pdf_equal_the_command_line(lamina_exe, material, mode):
    wo = directions(40, 1, lower=False)
    wi = directions(40, 2)
    lines = "".join(
        json.dumps({"wo": list(o), "wi": list(i)}) + "\n" for o, i in zip(wo, wi)
    )
    status, out, err = run_cli(lamina_exe, "bsdf", "eval", material, "--mode", mode,
                               stdin=lines)
    assert status == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    m = lamina.Material(material, mode=mode)
    f, pdf, rev = m.eval(wo, wi), m.pdf(wo, wi), m.pdf_reverse(wo, wi)
    # The command line prints 9 significant digits of the same double-precision values.
    np.testing.assert_allclose(f, [r["f"] for r in rows], rtol=1e-8, atol=1e-300)
    np.testing.assert_allclose(pdf, [r["pdf"] for r in rows], rtol=1e-8, atol=1e-300)
    np.testing.assert_allclose(rev, [r["pdf_reverse"] for r in rows], rtol=1e-8, atol=1e-300)


@pytest.mark.parametrize("material", MATERIALS)
def test_sample_equals_the_command_line(lamina_exe, material):
    wo = np.array([0.3, -0.2, 0.8])
    status, out, err = run_cli(lamina_exe, "bsdf", "sample", material, "--wo", "0.3,-0.2,0.8",
                               "--count", "50", "--seed", "7")
    assert status == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    u = lamina.random_numbers(50, 3, seed=7)
    s = lamina.Material(material).sample(wo, u[:, 0], u[:, 1:])
    for k, r in enumerate(rows):
        if r["wi"] is None:
            assert not s["valid"][k] and s["lobe"][k] == ""
            continue
        np.testing.assert_allclose(s["wi"][k], r["wi"], rtol=1e-8, atol=1e-9)
        np.testing.assert_allclose(s["weight"][k], r["weight"], rtol=1e-8, atol=1e-300)
        np.testing.assert_allclose(s["pdf"][k], r["pdf"], rtol=1e-8)
        assert s["lobe"][k] == r["lobe"]


def test_albedo_equals_the_command_line(lamina_exe):
    material = MATERIALS[0]
    status, out, err = run_cli(lamina_exe, "bsdf", "albedo", material, "--samples", "2000",
                               "--seed", "3")
    assert status == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    a = lamina.Material(material).albedo([r["cos_theta_o"] for r in rows], samples=2000, seed=3)
    np.testing.assert_allclose(a["reflection"], [r["reflection"] for r in rows], rtol=1e-8)
    np.testing.assert_allclose(a["transmission"], [r["transmission"] for r in rows], rtol=1e-8,
                               atol=1e-300)
    np.testing.assert_allclose(a["stderr"], [r["stderr"] for r in rows], rtol=1e-8)


@pytest.mark.parametrize("material", MATERIALS)
@pytest.mark.parametrize("mode", ["rgb", "spectral"])
def test_weight_is_eval_over_pdf(material, mode):
    m = lamina.Material(material, mode=mode)
    n = 4000
    rng = np.random.default_rng(11)
    wo = directions(n, 12, lower=False)
    s = m.sample(wo, rng.random(n), rng.random((n, 2)))
    smooth = s["valid"] & ~np.char.startswith(s["lobe"].astype(str), "specular")
    assert smooth.sum() > n // 4
    f = m.eval(wo[smooth], s["wi"][smooth])
    pdf = m.pdf(wo[smooth], s["wi"][smooth])
    np.testing.assert_allclose(s["pdf"][smooth], pdf, rtol=1e-6)
    np.testing.assert_allclose(s["weight"][smooth], f / pdf[:, None], rtol=1e-6, atol=1e-12)


def chi2_sf(statistic, dof):
    """P(X >= statistic) for X chi-square with dof degrees of freedom: the regularised upper
    incomplete gamma Q(dof/2, statistic/2) (series of Numerical Recipes 6.2 for P)."""
    a, x = dof / 2.0, statistic / 2.0
    term = total = 1.0 / a
    for n in range(1, 10000):
        term *= x / (a + n)
        total += term
        if term < total * 1e-15:
            break
    return max(0.0, 1.0 - total * math.exp(-x + a * math.log(x) - math.lgamma(a)))


@pytest.mark.parametrize("material", [MATERIALS[0], MATERIALS[2], MATERIALS[3], MATERIALS[6]])
def test_chi_square_of_sample_against_pdf(material):
    """Pearson's chi-square over a (cos theta, phi) grid of the sphere: observed counts of
    sample() against the counts pdf() predicts (midpoint rule, 16 x 16 points per cell); cells
    expecting fewer than 5 are pooled. Fixed seed; significance level 1e-3."""
    m = lamina.Material(material)
    wo = np.array([0.5, 0.1, 0.86])
    n, rows, cols, sub = 200000, 20, 40, 16
    rng = np.random.default_rng(2024)
    s = m.sample(np.tile(wo, (n, 1)), rng.random(n), rng.random((n, 2)))
    keep = s["valid"] & ~np.char.startswith(s["lobe"].astype(str), "specular")
    wi = s["wi"][keep]
    ci = np.clip(((wi[:, 2] + 1) / 2 * rows).astype(int), 0, rows - 1)
    phi = np.mod(np.arctan2(wi[:, 1], wi[:, 0]), 2 * np.pi)
    pj = np.clip((phi / (2 * np.pi) * cols).astype(int), 0, cols - 1)
    observed = np.bincount(ci * cols + pj, minlength=rows * cols).astype(float)
    # Expected: n * integral of pdf over each cell; d(solid angle) = d(cos theta) d(phi).
    cz = -1 + (np.arange(rows * sub) + 0.5) * 2 / (rows * sub)
    ph = (np.arange(cols * sub) + 0.5) * 2 * np.pi / (cols * sub)
    z, p = np.meshgrid(cz, ph, indexing="ij")
    r = np.sqrt(1 - z**2)
    grid = np.stack([r * np.cos(p), r * np.sin(p), z], -1).reshape(-1, 3)
    density = m.pdf(wo, grid).reshape(rows, sub, cols, sub)
    cell = (2 / (rows * sub)) * (2 * np.pi / (cols * sub))
    expected = n * density.sum(axis=(1, 3)).ravel() * cell
    order = np.argsort(expected)
    e, o = expected[order], observed[order]
    small = np.cumsum(e) < 5 * 4  # pool the least likely cells into one
    pooled_e = [e[small].sum()] + list(e[~small]) if small.any() else list(e)
    pooled_o = [o[small].sum()] + list(o[~small]) if small.any() else list(o)
    pe, po = np.array(pooled_e), np.array(pooled_o)
    valid = pe > 0
    statistic = float(np.sum((po[valid] - pe[valid]) ** 2 / pe[valid]))
    dof = int(valid.sum()) - 1
    assert chi2_sf(statistic, dof) > 1e-3, (statistic, dof)


def test_spectral_eval_over_many_wavelengths_matches_four_at_a_time():
    m = lamina.Material(MATERIALS[3], mode="spectral")
    wo, wi = directions(10, 3, lower=False), directions(10, 4, lower=False)
    nm = np.linspace(380, 780, 11)
    whole = m.eval(wo, wi, wavelengths=nm)
    assert whole.shape == (10, 11)
    for first in range(0, 11, 3):
        part = m.eval(wo, wi, wavelengths=nm[first:first + 3])
        np.testing.assert_array_equal(whole[:, first:first + 3], part)
    per_row = m.eval(wo, wi, wavelengths=np.tile(nm, (10, 1)))
    np.testing.assert_array_equal(per_row, whole)


def test_errors_are_value_errors_with_the_json_path(lamina_exe):
    text = '{"type":"standard","roughness":-0.2}'
    status, _, err = run_cli(lamina_exe, "bsdf", "eval", text)
    assert status == 1
    with pytest.raises(ValueError) as e:
        lamina.Material(text)
    assert err.strip() == "lamina: error: " + str(e.value)
    with pytest.raises(ValueError, match=r"<material dict>: roughness: .*-0\.2"):
        lamina.Material({"type": "standard", "roughness": -0.2})
    with pytest.raises(ValueError, match=r"\bb\.colour"):
        lamina.Material({"type": "mix", "a": {"type": "lambert"},
                         "b": {"type": "lambert", "colour": 1}})
    with pytest.raises(ValueError, match="wo"):
        lamina.Material(MATERIALS[0]).eval(np.zeros((2, 4)), np.ones((2, 3)))
    with pytest.raises(ValueError, match="mode"):
        lamina.Material(MATERIALS[0], mode="hyperspectral")


def test_a_nan_in_a_dict_is_named_by_its_path_not_malformed_json():
    # json.dumps writes NaN as a token JSON does not have; the error must name the value.
    with pytest.raises(ValueError) as e:
        lamina.Material({"type": "mix", "a": {"type": "lambert"},
                         "b": {"type": "lambert", "reflectance": [0.5, float("nan"), 0.5]}})
    assert str(e.value) == "<material dict>: b.reflectance[1]: expected a finite number, got NaN"
    with pytest.raises(ValueError, match=r"^<material dict>: ior: expected a finite number, "
                                         r"got infinity$"):
        lamina.Material({"type": "dielectric", "ior": float("inf")})
    with pytest.raises(ValueError, match=r"^<scene dict>: film\.resolution\[0\]: .*-infinity$"):
        lamina.render({"film": {"resolution": [float("-inf"), 4]}})


def test_lobes_and_info():
    m = lamina.Material({"type": "dielectric", "ior": 1.5})
    assert m.lobes == ["specular_reflection", "specular_transmission"]
    info = m.info()
    assert info["type"] == "dielectric" and info["delta"]


def test_material_kinds_are_the_readers_types_with_their_schema(monkeypatch):
    """lamina.material_kinds() is the registrations: every type builds a Material from the
    examples of its schema branch, and the schema file holds exactly these branches."""
    kinds = lamina.material_kinds()
    names = [k["name"] for k in kinds]
    assert names[0] == "standard" and "coated" in names and len(set(names)) == len(names)
    docs = pathlib.Path(__file__).resolve().parents[2] / "docs"
    with open(docs / "scene.schema.json") as f:
        schema = json.load(f)
    # The examples name their files (a measured material's RGL file) relative to docs/, where
    # the scene schema test reads them too.
    monkeypatch.chdir(docs)
    assert schema["$defs"]["material"]["oneOf"] == [k["schema"] for k in kinds]
    for kind in kinds:
        assert kind["schema"]["properties"]["type"] == {"const": kind["name"]}
        assert set(kind["texturable"].values()) <= {"color", "roughness"}
        for example in kind["schema"]["examples"]:
            assert lamina.Material(example).info()["type"] == kind["name"]


# ----------------------------------------------------------------- Mueller matrices

def _hemisphere(n, seed):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    return v / np.linalg.norm(v, axis=1, keepdims=True)


@pytest.mark.parametrize("material", [
    {"type": "conductor", "material": "Au", "roughness": 0.3},
    {"type": "dielectric", "ior": 1.5, "roughness": 0.2},
    {"type": "standard", "roughness": 0.4},
    {"type": "lambert", "reflectance": 0.7},
])
def test_mueller_first_element_is_eval(material):
    m = lamina.Material(material, mode="spectral")
    wo, wi = _hemisphere(64, 1), _hemisphere(64, 2)
    nm = np.array([420.0, 510.0, 600.0, 700.0, 780.0])
    mueller = m.mueller(wo, wi, wavelengths=nm)
    assert mueller.shape == (64, 5, 4, 4)
    assert np.all(np.isfinite(mueller))
    np.testing.assert_allclose(mueller[..., 0, 0], m.eval(wo, wi, wavelengths=nm),
                               rtol=1e-12, atol=1e-15)


def test_a_lambertian_surface_depolarises():
    m = lamina.Material({"type": "lambert", "reflectance": 0.7}, mode="spectral")
    mueller = m.mueller(_hemisphere(16, 3), _hemisphere(16, 4))
    rest = mueller.copy()
    rest[..., 0, 0] = 0
    assert np.all(mueller[..., 0, 0] > 0) and np.all(rest == 0)


def diattenuation(mueller):
    # sqrt(M01^2 + M02^2 + M03^2) / M00: unchanged by a rotation of either Stokes frame, so
    # the test does not depend on the frames' convention.
    return np.linalg.norm(mueller[..., 0, 1:], axis=-1) / mueller[..., 0, 0]


def test_near_specular_dielectric_reflection_polarises_at_brewster_and_not_at_normal():
    # Rough glass of ior 1.5 in the mirror configuration, where the half vector is the normal:
    # at Brewster's angle (56.3 degrees) it reflects s light only (diattenuation 1: Rp = 0);
    # at normal incidence Rs = Rp (diattenuation 0; the 0.01 tilt keeps it a little above 0).
    m = lamina.Material({"type": "dielectric", "ior": 1.5, "roughness": 0.1}, mode="spectral")
    brewster = math.atan(1.5)
    wo = np.array([[math.sin(brewster), 0.0, math.cos(brewster)]])
    wi = wo * np.array([-1.0, -1.0, 1.0])  # the mirror direction
    assert diattenuation(m.mueller(wo, wi))[0] == pytest.approx([1, 1, 1], abs=1e-9)
    normal = np.array([[0.0, 0.0, 1.0]])
    tilted = np.array([[0.01, 0.0, 1.0]])
    assert np.all(diattenuation(m.mueller(normal, tilted))[0] < 0.01)


def test_mueller_needs_spectral_mode():
    with pytest.raises(ValueError, match="spectral mode"):
        lamina.Material({"type": "lambert"}).mueller([0, 0, 1], [0, 0, 1])
