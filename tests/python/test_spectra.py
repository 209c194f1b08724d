"""Spectra and colour: the CIE tables, XYZ <-> Rec.709, RGB -> spectrum, emission spectra
normalised to luminance, n/k data, and RGB mode's conductor reduction (F0, F82)."""

import numpy as np
import pytest

import lamina

NM = np.arange(360.0, 831.0, 1.0)


def luminance(spectrum):
    """Y of a spectrum over NM relative to the integral of y-bar (the CIE convention the
    emission spectra are normalised with)."""
    y = lamina.cie_cmf(NM)[:, 1]
    return np.trapz(spectrum * y, NM) / np.trapz(y, NM)


def test_cie_y_peaks_at_555_nm():
    cmf = lamina.cie_cmf(NM)
    assert cmf.shape == (NM.size, 3)
    assert NM[np.argmax(cmf[:, 1])] == 555 and cmf[:, 1].max() == pytest.approx(1, abs=1e-3)


def test_xyz_and_rec709_round_trip_and_white():
    rgb = np.random.default_rng(1).random((100, 3))
    np.testing.assert_allclose(lamina.xyz_to_rgb(lamina.rgb_to_xyz(rgb)), rgb, atol=1e-12)
    # Rec.709's white (1, 1, 1) is D65: Y = 1.
    assert lamina.rgb_to_xyz([1.0, 1.0, 1.0])[1] == pytest.approx(1, abs=1e-9)


def test_white_stays_white():
    s = lamina.rgb_to_spectrum([1, 1, 1], NM)
    np.testing.assert_allclose(s, 1, atol=1e-3)
    d65 = lamina.rgb_to_spectrum([1, 1, 1], NM, kind="illuminant")
    np.testing.assert_allclose(d65, lamina.illuminant("D65", NM), rtol=1e-3)
    with pytest.raises(ValueError, match="kind"):
        lamina.rgb_to_spectrum([1, 1, 1], NM, kind="emission")


@pytest.mark.parametrize("spectrum", [lambda: lamina.illuminant("A", NM, scale=3),
                                      lambda: lamina.blackbody(4000, NM, scale=3)])
def test_emission_spectra_have_the_luminance_of_their_scale(spectrum):
    assert luminance(spectrum()) == pytest.approx(3, rel=2e-3)


def test_named_and_file_ior(tmp_path):
    assert lamina.ior("bk7", [587.56])["n"][0] == pytest.approx(1.5168, abs=1e-4)
    au = lamina.ior("Au", NM)
    assert au["n"].shape == NM.shape and (au["n"] > 0).all() and (au["k"] > 0).all()
    f = tmp_path / "metal.csv"
    f.write_text("nm,n,k\n400,1.5,2\n700,0.5,4\n")
    nk = lamina.ior(str(f), [400, 550, 700])
    np.testing.assert_allclose(nk["n"], [1.5, 1.0, 0.5])
    np.testing.assert_allclose(nk["k"], [2, 3, 4])
    with pytest.raises(ValueError, match="unobtainium"):
        lamina.ior("unobtainium", NM)
    assert "Au" in lamina.metals() and "bk7" in lamina.glasses() and "D65" in lamina.illuminants()


def fresnel_conductor(cos, n, k):
    """The unpolarised Fresnel reflectance of a conductor n + ik in air (the standard
    closed form, e.g. pbrt-v3 section 8.2.1)."""
    sin2 = 1 - cos**2
    t = n**2 - k**2 - sin2
    a2b2 = np.sqrt(t**2 + 4 * n**2 * k**2)
    a = np.sqrt((a2b2 + t) / 2)
    rs = (a2b2 + cos**2 - 2 * a * cos) / (a2b2 + cos**2 + 2 * a * cos)
    rp = rs * (cos**2 * a2b2 + sin2**2 - 2 * a * cos * sin2) / (
        cos**2 * a2b2 + sin2**2 + 2 * a * cos * sin2)
    return (rs + rp) / 2


def test_conductor_reduction_is_the_exact_fresnel_colour():
    """F0 and F82 are the colours under D65 of the exact reflectance at cos theta = 1 and 1/7
    (Hoffman 2019), here integrated with NumPy over 1 nm steps."""
    f0, f82 = lamina.conductor_f0_f82("Cu")
    nk = lamina.ior("Cu", NM)
    d65 = lamina.illuminant("D65", NM)
    cmf = lamina.cie_cmf(NM)
    for cos, expected in [(1.0, f0), (1 / 7, f82)]:
        r = fresnel_conductor(cos, nk["n"], nk["k"])
        xyz = np.trapz((r * d65)[:, None] * cmf, NM, axis=0) / np.trapz(d65 * cmf[:, 1], NM)
        np.testing.assert_allclose(expected, lamina.xyz_to_rgb(xyz), atol=2e-3)
    assert f0[0] > f0[1] > f0[2]
