"""Error against time for two integrators on the Cornell box: relMSE after every pass
against seconds, log-log, with each curve's fitted slope (lamina.convergence).

    PYTHONPATH=build/python /usr/bin/python3 examples/error_vs_time.py scenes/cornell-box.json err.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import lamina  # noqa: E402

scene = sys.argv[1] if len(sys.argv) > 1 else "scenes/cornell-box.json"
# Each integrator renders for 5 s; the reference (path tracing, its own seed) for 30 s.
result = lamina.convergence(scene, integrators=["path", "bdpt"], seconds=5,
                            reference_seconds=30, resolution=(128, 128))

fig, ax = plt.subplots(figsize=(6, 4))
for curve in result["curves"]:
    slope = curve["slope"]
    label = curve["integrator"] + (f" (slope {slope:.2f})" if slope is not None else "")
    ax.loglog(curve["seconds"], curve["relmse"], "o-", ms=3, label=label)
ax.set_xlabel("render time (s)")
ax.set_ylabel("relMSE (epsilon 1e-2)")
ax.set_title("Cornell box, 128 x 128")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2] if len(sys.argv) > 2 else "error_vs_time.png", dpi=120)
