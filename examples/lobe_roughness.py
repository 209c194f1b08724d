"""A BSDF lobe in the plane of incidence for several roughnesses: f |cos theta_i| of a rough
conductor (gold) for wo at 45 degrees, wi swept from -90 to 90 degrees in the x-z plane.

    PYTHONPATH=build/python /usr/bin/python3 examples/lobe_roughness.py lobes.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import lamina  # noqa: E402

theta_o = np.radians(45)
wo = np.array([np.sin(theta_o), 0.0, np.cos(theta_o)])
theta = np.radians(np.linspace(-89.5, 89.5, 719))
wi = np.stack([np.sin(theta), np.zeros_like(theta), np.cos(theta)], axis=1)

fig, ax = plt.subplots(figsize=(6, 4))
for alpha in [0.05, 0.1, 0.2, 0.4, 0.8]:
    m = lamina.Material({"type": "conductor", "material": "Au", "alpha": alpha})
    f = m.eval(wo, wi).mean(axis=1)  # the average of R, G, B
    ax.semilogy(np.degrees(theta), np.maximum(f, 1e-6), label=f"alpha = {alpha}")
ax.axvline(-45, color="grey", lw=0.5)  # the mirror direction of wo
ax.set_xlabel("theta_i in the plane of incidence (degrees; wo at +45)")
ax.set_ylabel("f |cos theta_i| (mean of R, G, B)")
ax.set_title("Rough gold (GGX) in RGB mode")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "lobes.png", dpi=120)
