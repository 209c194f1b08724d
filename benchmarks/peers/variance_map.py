#!/usr/bin/env python3
"""Where lamina's per-sample variance differs from Cycles', pixel by pixel, on one scene.

A benchmark, not a test (never run in CI): it needs Blender 3.4 (`apt-get install -y blender`)
and OpenImageIO's Python module (`apt-get install -y python3-openimageio`). It renders
--images independent images of --spp samples with each renderer (seeds 1001, 1002, ...;
lamina through `lamina render`, Cycles through cycles.py's scene translation), estimates
each pixel's variance from the spread of those images (unbiased, --images - 1 degrees of
freedom), and prints, for the whole image and for the regions the camera sees first:

  sky       pixels whose camera ray leaves the scene (lamina's Z AOV is not finite),
  grey      surfaces of grey albedo (max - min of Albedo.RGB below 2% of its max),
  coloured  the other surfaces,

the mean per-pixel variance of each renderer, their ratio, each region's share of the
renderer's total, the median of the per-pixel ratio and the two images' means (which must
agree: the renderers render the same scene). Variance at equal samples is the per-sample
part of the efficiency that cycles.py measures; the time per sample is the other.

  python3 benchmarks/peers/variance_map.py scenes/glossy-metal-sphere.json --images 4 --spp 16

--map FILE writes a PNG of log2(lamina / Cycles) over 8x8-pixel blocks: red where lamina's
variance is higher (saturated at 8x), blue where Cycles' is.
"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles  # noqa: E402  (the scene translation and the renderer runners)


def read_channels(path, names):
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit(f"variance_map.py: cannot read {path}: {oiio.geterror()}")
    spec = image.spec()
    pixels = np.asarray(image.read_image(0, 0, 0, spec.nchannels, "float"))
    image.close()
    pixels = pixels.reshape(spec.height, spec.width, spec.nchannels)
    channels = list(spec.channelnames)
    missing = [n for n in names if n not in channels]
    if missing:
        sys.exit(f"variance_map.py: {path} has no channels {missing}")
    return np.stack([pixels[..., channels.index(n)] for n in names], -1)


def regions(aov_path):
    albedo = read_channels(aov_path, ("Albedo.R", "Albedo.G", "Albedo.B"))
    depth = read_channels(aov_path, ("Z",))[..., 0]
    sky = ~(np.isfinite(depth) & (depth > 0) & (depth < 1e30))
    spread = albedo.max(-1) - albedo.min(-1)
    grey = ~sky & (spread <= 0.02 * albedo.max(-1))
    return {"all": np.ones_like(sky), "sky": sky, "grey": grey, "coloured": ~sky & ~grey}


def write_map(path, ratio_log2):
    rgb = np.zeros(ratio_log2.shape + (3,), np.float32)
    rgb[..., 0] = np.clip(ratio_log2 / 3, 0, 1)
    rgb[..., 2] = np.clip(-ratio_log2 / 3, 0, 1)
    out = oiio.ImageOutput.create(path)
    if out is None or not out.open(path, oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, "uint8")):
        sys.exit(f"variance_map.py: cannot write {path}: {oiio.geterror()}")
    out.write_image((rgb * 255 + 0.5).astype(np.uint8))
    out.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--lamina", default="build/app/lamina")
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--images", type=int, default=4, help="independent images per renderer")
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--map", help="PNG of the block-wise log2 variance ratio")
    parser.add_argument("--keep", help="directory to keep the images in")
    args = parser.parse_args()
    if args.images < 2:
        parser.error("--images must be at least 2 (a variance needs two images)")
    args.clock = "cpu"
    work = args.keep or tempfile.mkdtemp(prefix="lamina-variance-")
    os.makedirs(work, exist_ok=True)
    runner = cycles.Runner(args, work)
    tag = os.path.splitext(os.path.basename(args.scene))[0]
    stacks = {}
    for name, render in (("lamina", runner.lamina), ("cycles", runner.cycles)):
        files = [render(args.scene, args.spp, 1000 + k, f"{tag}-{name}-{k}")[0]
                 for k in range(1, args.images + 1)]
        stacks[name] = np.stack([read_channels(f, ("R", "G", "B")) for f in files])
    aov = os.path.join(work, f"{tag}-aovs.exr")
    subprocess.run([args.lamina, "render", args.scene, "-o", aov, "--spp", "4", "--aovs", "-q"],
                   check=True)
    masks = regions(aov)
    variance = {n: s.var(0, ddof=1).mean(-1) for n, s in stacks.items()}
    mean = {n: s.mean(0).mean(-1) for n, s in stacks.items()}
    vl, vc = variance["lamina"], variance["cycles"]
    print(f"{tag}: {args.images} images of {args.spp} spp per renderer; per-pixel variance of one "
          f"image (mean of R, G, B)")
    print("| region | pixels | lamina variance | Cycles variance | lamina / Cycles | median of "
          "the per-pixel ratio | share of lamina's | share of Cycles' | mean lamina | mean Cycles |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for region, m in masks.items():
        if not m.any():
            continue
        ratio = vl[m].mean() / vc[m].mean() if vc[m].mean() > 0 else float("inf")
        positive = m & (vc > 0)
        median = np.median(vl[positive] / vc[positive]) if positive.any() else float("nan")
        print(f"| {region} | {int(m.sum())} | {vl[m].mean():.3g} | {vc[m].mean():.3g} | "
              f"{ratio:.2f} | {median:.2f} | {vl[m].sum() / vl.sum():.2f} | "
              f"{vc[m].sum() / vc.sum():.2f} | {mean['lamina'][m].mean():.4f} | "
              f"{mean['cycles'][m].mean():.4f} |")
    if args.map:
        b = 8
        h, w = (vl.shape[0] // b) * b, (vl.shape[1] // b) * b
        blocks = [v[:h, :w].reshape(h // b, b, w // b, b).mean((1, 3)) for v in (vl, vc)]
        tiny = 1e-12
        write_map(args.map, np.kron(np.log2((blocks[0] + tiny) / (blocks[1] + tiny)),
                                    np.ones((b, b))))


if __name__ == "__main__":
    main()
