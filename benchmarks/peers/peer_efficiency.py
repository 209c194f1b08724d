"""What the peer scripts (cycles.py, pbrt.py) share: running lamina and reading the time it
reports, image errors, and the arithmetic of efficiency.

Efficiency is 1 / (MSE x seconds). For an unbiased renderer at n samples per pixel,
MSE = v / n with v the per-sample variance (averaged over the pixels), so efficiency is the
sample rate n / seconds divided by v: the two factors are reported separately, since they have
different causes (time per sample: tracing and shading; variance per sample: the estimator).

A reference is noisy too. For an image x and a reference h of an independent unbiased render,
E[(x - h)^2] = MSE(x) + var(h); the reference's variance is taken out:
  - from two independent halves h1, h2: E[(h1 - h2)^2] = 2 var(h), so
    MSE(x) = (MSE(x, h1) + MSE(x, h2)) / 2 - MSE(h1, h2) / 2 (against the mean of the halves);
  - from one reference rendered by lamina itself at N samples: var(h) = v / N with lamina's own
    per-sample variance v, and lamina's image at n samples gives MSE(x, h) = v / n + v / N.
"""

import math
import os
import re
import resource
import subprocess
import sys


class PeerError(Exception):
    """A failed run or an unreadable output: the scripts print it and stop."""


# ---------------------------------------------------------------------------------------------
# Running lamina.


def lamina_command(lamina, scene, out, *, spp=None, seconds=None, seed=0, mode="rgb", threads=2,
                   extra=()):
    cmd = [lamina, "render", scene, "-o", out, "--seed", str(seed), "--mode", mode,
           "--threads", str(threads)]
    if spp is not None:
        cmd += ["--spp", str(spp)]
    if seconds is not None:
        cmd += ["--time", f"{seconds:g}"]
    return cmd + list(extra)


def parse_render_summary(stderr):
    """(spp, seconds) of lamina's summary line "OUT: WxH, N spp, MODE mode, INTEGRATOR
    integrator, T s, R paths/s, ...", not of a progress line "progress: P% (N spp, T s, ETA E
    s)" before it: fields never run across lines."""
    m = re.search(r"^.*, (\d+) spp, [^,\n]+, [^,\n]+, ([0-9.]+) s, [^,\n]+ paths/s", stderr,
                  re.MULTILINE)
    if not m:
        raise PeerError(f"no render time in lamina's output:\n{stderr}")
    return int(m.group(1)), float(m.group(2))


def run_lamina(lamina, scene, out, *, spp=None, seconds=None, seed=0, mode="rgb", clock="wall",
               threads=2, extra=()):
    """Renders and returns (image, spp rendered, seconds). clock "wall": the render time lamina
    prints (BVH and sampling, not the process start-up); "cpu": the CPU seconds of the whole
    process (start-up and scene loading included), for a machine shared with other work."""
    cmd = lamina_command(lamina, scene, out, spp=spp, seconds=seconds, seed=seed, mode=mode,
                         threads=threads, extra=extra)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise PeerError(f"lamina failed: {' '.join(cmd)}\n{p.stderr}")
    rendered, wall = parse_render_summary(p.stderr)
    if spp is not None and rendered != spp:
        raise PeerError(f"lamina rendered {rendered} spp where {spp} were asked:\n{p.stderr}")
    if clock == "cpu":
        return out, rendered, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out, rendered, wall


def compare_mse(lamina, image, reference):
    """(MSE, relMSE) of two images by `lamina compare`."""
    p = subprocess.run([lamina, "compare", image, reference, "--metric", "mse,relmse"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise PeerError(f"lamina compare failed:\n{p.stderr}")
    values = dict(line.split() for line in p.stdout.splitlines() if line.strip())
    return float(values["mse"]), float(values["relmse"])


def read_rgb(path, python_path=None):
    """An image's R, G, B as an (H, W, 3) float array, through lamina's Python module
    (lamina.read_image; PYTHONPATH=build/python or python_path)."""
    if python_path and python_path not in sys.path:
        sys.path.insert(0, python_path)
    try:
        import lamina
    except ImportError as e:
        raise PeerError(f"cannot import lamina's Python module ({e}): build it and give "
                        f"--python build/python") from e
    return lamina.read_image(path)[0]


# ---------------------------------------------------------------------------------------------
# Arithmetic (numpy arrays of one shape, or numbers).


def mse(a, b):
    """Mean of the squared difference over every pixel and channel."""
    d = (a - b).astype("float64")
    return float((d * d).mean())


def mse_against_halves(image, h1, h2):
    """The image's MSE net of two independent reference halves' own noise (module docstring),
    and the variance of their mean, MSE(h1, h2) / 4."""
    between = mse(h1, h2)
    return 0.5 * (mse(image, h1) + mse(image, h2)) - 0.5 * between, between / 4.0


def own_reference_variance(raw_mse, spp, reference_spp):
    """lamina's per-sample variance v and the reference's variance v / N, from lamina's image at
    n = spp against lamina's own reference at N = reference_spp: MSE = v / n + v / N."""
    v = raw_mse / (1.0 / spp + 1.0 / reference_spp)
    return v, v / reference_spp


class Measurement:
    """One renderer's image: samples per pixel, seconds, MSE net of the reference's noise."""

    def __init__(self, name, spp, seconds, mse_value):
        self.name, self.spp, self.seconds, self.mse = name, spp, seconds, mse_value

    @property
    def efficiency(self):
        return 1.0 / (self.mse * self.seconds)

    @property
    def per_sample_variance(self):
        return self.mse * self.spp

    @property
    def sample_rate(self):
        return self.spp / self.seconds


def ratios(lamina, peer):
    """lamina / peer efficiency and its two factors: the variance ratio peer / lamina (above 1:
    lamina's samples are less noisy) and the rate ratio lamina / peer (above 1: lamina draws more
    samples per second). Their product is the efficiency ratio."""
    variance = peer.per_sample_variance / lamina.per_sample_variance
    rate = lamina.sample_rate / peer.sample_rate
    return {"efficiency": lamina.efficiency / peer.efficiency, "variance": variance, "rate": rate}


def relative_mean_difference(a, b):
    """(mean(a) - mean(b)) / mean(b) over every pixel and channel."""
    return float(a.mean()) / float(b.mean()) - 1.0


def geometric_mean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


def load_note():
    load = os.getloadavg()[0]
    return (f"load average: {load:.2f} on {os.cpu_count()} cores"
            + (" (the machine is busy: compare the ratios, not the times)" if load > 0.5 else ""))
