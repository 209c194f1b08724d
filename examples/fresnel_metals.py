"""Exact spectral Fresnel reflectance against RGB mode's models (Schlick, shadowed F90,
Hoffman's F82, Lagarde's spherical Gaussian) for three metals: the luminance of each model's
colour against the angle of incidence, and its largest RGB error (lamina.fresnel).

    PYTHONPATH=build/python /usr/bin/python3 examples/fresnel_metals.py fresnel.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import lamina  # noqa: E402

Y = lamina.rgb_to_xyz(np.eye(3))[:, 1]  # luminance weights of linear Rec.709

fig, axes = plt.subplots(1, 3, figsize=(12, 3.6), sharey=True)
for ax, result in zip(axes, lamina.fresnel(["Au", "Cu", "Al"])):
    for model in result["models"]:
        style = "-" if model["name"] == result["models"][0]["name"] else "--"
        ax.plot(result["degrees"], model["rgb"] @ Y, style,
                label=f"{model['name']} (max |dRGB| {model['max_error']:.3f})")
    ax.set_title(result["name"])
    ax.set_xlabel("angle of incidence (degrees)")
    ax.legend(fontsize=7)
axes[0].set_ylabel("reflectance (luminance)")
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "fresnel.png", dpi=120)
