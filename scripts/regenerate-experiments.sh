#!/usr/bin/env bash
# Regenerates the reports in docs/experiments/ (about 20 minutes on 2 cores). Run from the
# repository root after building: bash scripts/regenerate-experiments.sh [build/app/lamina]
set -euo pipefail
cd "$(dirname "$0")/.."
lamina=${1:-build/app/lamina}
out=docs/experiments

# Error against time: the Cornell box, every integrator, both modes.
rm -rf "$out/convergence"
"$lamina" convergence scenes/cornell-box.json --resolution 128x128 --integrators path,light,bdpt \
  --modes rgb,spectral --time 10 --reference-time 150 --levels 1e-2,3e-3,1e-3 \
  -o "$out/convergence"

# Spectral against RGB Fresnel: the measured metals and two glasses, and a scene of them in
# both modes.
rm -rf "$out/fresnel"
"$lamina" fresnel Au Ag Cu Al Cr bk7 diamond --scene scenes/fresnel-spheres.json --spp 256 \
  -o "$out/fresnel"

# Numerical stability: the default model set and the stiff scenes.
rm -rf "$out/stability"
"$lamina" stability --scenes scenes/stress/*.json --spp 256 -o "$out/stability"

# Analytic layered stacks against the random-walk coated material: the built-in set users meet,
# and the test object rendered with each in both modes.
rm -rf "$out/layering"
"$lamina" layering clear-paint varnished-wood coated-gold tinted-coat --estimates 1024 \
  --albedo-samples 32768 --scene scenes/layering/test-object.json -o "$out/layering"

# What ignoring polarisation costs: the glass and the gold mirror pairs (closed forms), the
# metal and glass spheres, the still life behind a polarising filter; and the Mueller matrices
# of reflection of gold, copper and BK7.
rm -rf "$out/polarisation/two-mirrors" "$out/polarisation/gold-mirrors" \
  "$out/polarisation/fresnel-spheres" "$out/polarisation/still-life" "$out/polarisation/materials"
"$lamina" polarisation scenes/polarisation/two-mirrors.json --spp 64 \
  -o "$out/polarisation/two-mirrors"
"$lamina" polarisation scenes/polarisation/gold-mirrors.json --spp 64 \
  -o "$out/polarisation/gold-mirrors"
"$lamina" polarisation scenes/fresnel-spheres.json --resolution 240x120 --spp 256 \
  -o "$out/polarisation/fresnel-spheres"
"$lamina" polarisation scenes/polarisation/still-life.json --spp 64 \
  -o "$out/polarisation/still-life"
"$lamina" polarisation Au Cu bk7 -o "$out/polarisation/materials"

# Chromatic participating media: RGB against spectral mode, and spectral MIS against the hero
# wavelength alone, on the chromatic cloud (a grid medium) and the glass of red liquid.
# The glass at half its resolution and 640 spp: its per-pixel noise (a pure absorber's free
# flights pass or end) needs the samples to resolve the difference, the pixels do not.
# (docs/experiments/media/README.md, written by hand, reads its numbers from the summaries.)
rm -rf "$out/media/chromatic-cloud" "$out/media/glass-of-wine"
"$lamina" media scenes/media/chromatic-cloud.json --spp 64 -o "$out/media/chromatic-cloud"
"$lamina" media scenes/media/glass-of-wine.json --resolution 100x75 --spp 640 \
  --reference-spp 4096 -o "$out/media/glass-of-wine"
