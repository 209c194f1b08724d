"""Report pages (python/lamina/report_page.py, report_viewer.js) in a real browser: headless
Chromium from Debian loads the page of `lamina compare --html` and of an experiment's
directory with no console error, every image decodes, and the viewer shows each image's known
pixel values (read back through the page's own script, window.laminaViewers) when switched
between A and B, and under the cursor. Skips with a message where Chromium is not installed
(scripts/setup.sh installs it)."""

import json
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from conftest import run_cli

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

# Runs in the page before anything else: keeps every error and console.error, and at `load`
# writes what the test asks of the page into <pre id="lamina-test-result">.
HARNESS = r"""<script>
window.laminaErrors = [];
window.addEventListener("error", e => window.laminaErrors.push(String(e.message)));
const laminaConsoleError = console.error;
console.error = (...args) => { window.laminaErrors.push(args.join(" ")); laminaConsoleError(...args); };
window.addEventListener("load", () => {
  const result = {errors: window.laminaErrors, images: [], viewers: []};
  for (const img of document.images)
    result.images.push({alt: img.alt, decoded: img.complete && img.naturalWidth > 0});
  for (const v of (window.laminaViewers || [])) {
    const probe = PROBE;
    const entry = {decoded: v.decoded, width: v.width, height: v.height};
    if (probe) {
      v.show("a"); entry.a = v.value(probe[0], probe[1]);
      v.show("b"); entry.b = v.value(probe[0], probe[1]);
      v.show("difference"); entry.difference = v.value(probe[0], probe[1]);
      v.show("a");
      v.setZoom("8");
      const canvas = document.querySelector("section.pair canvas");
      const box = canvas.getBoundingClientRect();
      canvas.dispatchEvent(new MouseEvent("mousemove", {
        clientX: box.left + (probe[0] + 0.5) * box.width / v.width,
        clientY: box.top + (probe[1] + 0.5) * box.height / v.height}));
      entry.readout = document.querySelector("section.pair .readout").textContent;
      entry.pixel = Array.from(canvas.getContext("2d").getImageData(probe[0], probe[1], 1, 1).data);
    }
    result.viewers.push(entry);
  }
  const pre = document.createElement("pre");
  pre.id = "lamina-test-result";
  pre.textContent = JSON.stringify(result);
  document.body.appendChild(pre);
});
</script>"""


def open_in_chromium(page, tmp_path, probe=None):
    """Loads a copy of `page` with the harness in its head; returns the harness's result and
    Chromium's own log of the page's console."""
    text = open(page, encoding="utf-8").read()
    harness = HARNESS.replace("PROBE", json.dumps(probe))
    copy = tmp_path / ("probed-" + os.path.basename(page))
    copy.write_text(text.replace("<head>", "<head>" + harness, 1), encoding="utf-8")
    p = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--enable-logging=stderr", "--v=0", "--user-data-dir=" + str(tmp_path / "profile"),
         "--virtual-time-budget=20000", "--dump-dom", copy.as_uri()],
        capture_output=True, text=True, timeout=180)
    m = re.search(r'<pre id="lamina-test-result">(.*?)</pre>', p.stdout, re.S)
    assert m, "the page did not finish loading:\n" + p.stderr[-3000:]
    result = json.loads(m.group(1).replace("&amp;", "&").replace("&lt;", "<")
                        .replace("&gt;", ">").replace("&quot;", '"'))
    console = [line for line in p.stderr.splitlines() if "CONSOLE" in line]
    return result, console


def write_pfm(path, rgb):
    """A float RGB image in the PFM format (little-endian, rows from the bottom)."""
    h, w, _ = rgb.shape
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(np.ascontiguousarray(rgb[::-1], dtype="<f4").tobytes())


needs_chromium = pytest.mark.skipif(
    CHROMIUM is None, reason="headless Chromium (Debian's chromium, scripts/setup.sh) is missing")


@needs_chromium
def test_compare_html_shows_each_images_known_pixel(lamina_exe, tmp_path):
    a = np.full((6, 9, 3), 0.25, dtype=np.float32)
    b = np.full((6, 9, 3), 0.125, dtype=np.float32)
    a[2, 5] = (2.0, 0.5, 0.0625)  # the probed pixel: x 5, y 2 from the top
    b[2, 5] = (0.75, 1.5, 0.03125)
    write_pfm(tmp_path / "a.pfm", a)
    write_pfm(tmp_path / "b.pfm", b)
    page = tmp_path / "view.html"
    code, _, err = run_cli(lamina_exe, "compare", str(tmp_path / "a.pfm"), str(tmp_path / "b.pfm"),
                           "--html", str(page))
    assert code == 0, err
    assert "lamina: note" not in err, err
    # Self-contained: nothing fetched from the network or from beside the page.
    html = page.read_text()
    assert not re.search(r'(src|href)="(https?:|//)', html)
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".tmp")]  # the spec's directory went

    result, console = open_in_chromium(str(page), tmp_path, probe=[5, 2])
    assert result["errors"] == [] and not [c for c in console if "Uncaught" in c], (result, console)
    (viewer,) = result["viewers"]
    assert viewer["decoded"] and (viewer["width"], viewer["height"]) == (9, 6)
    assert viewer["a"] == pytest.approx(list(a[2, 5]))
    assert viewer["b"] == pytest.approx(list(b[2, 5]))
    assert viewer["difference"] == pytest.approx(float(np.mean(a[2, 5] - b[2, 5])))
    # Under the cursor: the pixel's coordinates and both images' values.
    assert "pixel (5, 2)" in viewer["readout"], viewer["readout"]
    assert "A (2.000, 0.5000, 0.06250)" in viewer["readout"], viewer["readout"]
    assert "B (0.7500, 1.500, 0.03125)" in viewer["readout"], viewer["readout"]
    # A at 0 EV: red 2.0 clips to 255, green 0.5 is sRGB 188, blue 0.0625 is sRGB 71.
    assert viewer["pixel"][:3] == [255, 188, 71], viewer["pixel"]


@needs_chromium
def test_a_broken_viewer_is_reported_as_an_error(tmp_path, source_dir):
    # The check of the test itself: a pair whose data is cut short must be caught as an error,
    # or the test above could pass on a page that shows nothing.
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "report_page_under_test", os.path.join(source_dir, "python", "lamina", "report_page.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    np.zeros(2 * 2 * 3, dtype="<f4").tofile(tmp_path / "p.a.f32")
    np.zeros(2 * 2 * 3, dtype="<f4").tofile(tmp_path / "p.b.f32")
    (tmp_path / "p.pair.json").write_text(json.dumps(
        {"lamina_pair": 1, "width": 2, "height": 2, "a": "p.a.f32", "b": "p.b.f32"}))
    page = module.write_pair_page(str(tmp_path / "p.pair.json"), str(tmp_path / "p.html"))
    text = open(page).read()
    # Cut the first image's base64 data short (still valid base64: 12 bytes, 3 values less).
    text = re.sub(r'"a": "([A-Za-z0-9+/]{16})', r'"a": "', text, count=1)
    (tmp_path / "p.html").write_text(text)
    result, _ = open_in_chromium(str(tmp_path / "p.html"), tmp_path)
    assert result["viewers"] == [] and any("expected 12 values" in e for e in result["errors"])


@needs_chromium
def test_an_experiments_page_holds_its_summary_figures_and_viewers(lamina_exe, source_dir,
                                                                    tmp_path):
    scene = os.path.join(source_dir, "scenes", "fresnel-spheres.json")
    out = tmp_path / "report"
    code, _, err = run_cli(lamina_exe, "fresnel", "Cu", "--scene", scene, "--spp", "2",
                           "--resolution", "48x24", "-o", str(out))
    assert code == 0, err
    page = out / "index.html"
    assert page.exists(), os.listdir(out)
    result, console = open_in_chromium(str(page), tmp_path, probe=[3, 4])
    assert result["errors"] == [] and not [c for c in console if "Uncaught" in c], (result, console)
    assert result["images"] and all(i["decoded"] for i in result["images"]), result["images"]
    # The figures of summary.md are in the page, in its order.
    summary = (out / "summary.md").read_text()
    figures = re.findall(r"!\[([^\]]*)\]\(", summary)
    assert [i["alt"] for i in result["images"]] == figures
    assert result["viewers"] and all(v["decoded"] for v in result["viewers"])
