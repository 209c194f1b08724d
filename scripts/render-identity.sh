#!/usr/bin/env bash
# Renders every shipped scene with a fixed seed, a few samples and every integrator, then (with
# a baseline directory) compares the pixels bit for bit. For refactors that must not change
# an image:
#   bash scripts/render-identity.sh OLD_LAMINA baseline/      # before
#   bash scripts/render-identity.sh NEW_LAMINA after/ baseline/  # after: fails on any change
# Light tracing and BDPT splat from several threads in an order that varies, so every render
# runs on one thread.
set -euo pipefail
lamina=$1 out=$2 baseline=${3:-}
cd "$(dirname "$0")/.."
mkdir -p "$out"
status=0
for scene in scenes/*.json scenes/reciprocity/*.json scenes/stress/*.json; do
  name=$(echo "${scene#scenes/}" | tr / _); name=${name%.json}
  for variant in "path rgb --aovs" "path spectral" "light rgb" "bdpt rgb" "bdpt spectral"; do
    set -- $variant
    integrator=$1 mode=$2; shift 2
    image="$out/$name-$integrator-$mode.exr"
    "$lamina" render "$scene" -o "$image" --integrator "$integrator" --mode "$mode" --spp 4 \
      --resolution 64x48 --seed 7 --threads 1 -q "$@"
    if [ -n "$baseline" ]; then
      if [ ! -e "$baseline/$(basename "$image")" ]; then
        echo "render-identity: $image is new (no image of it in $baseline)"
      elif ! idiff -q -fail 0 -failpercent 0 -warn 0 "$baseline/$(basename "$image")" "$image" >/dev/null; then
        echo "render-identity: $image differs from $baseline"; status=1
      fi
    fi
  done
done
# Scenes with media: every integrator renders them (docs/media.md). A baseline older than a
# scene or an integrator's media has no image of it: that is reported, not failed.
for scene in scenes/media/*.json; do
  name=$(echo "${scene#scenes/}" | tr / _); name=${name%.json}
  for variant in "path rgb --aovs" "path spectral" "light rgb" "light spectral" "bdpt rgb" \
                 "bdpt spectral"; do
    set -- $variant
    integrator=$1 mode=$2; shift 2
    image="$out/$name-$integrator-$mode.exr"
    "$lamina" render "$scene" -o "$image" --integrator "$integrator" --mode "$mode" --spp 4 \
      --resolution 64x48 --seed 7 --threads 1 -q "$@"
    if [ -n "$baseline" ]; then
      if [ ! -e "$baseline/$(basename "$image")" ]; then
        echo "render-identity: $image is new (no image of it in $baseline)"
      elif ! idiff -q -fail 0 -failpercent 0 -warn 0 "$baseline/$(basename "$image")" "$image" >/dev/null; then
        echo "render-identity: $image differs from $baseline"; status=1
      fi
    fi
  done
done
# Scenes of the polarised mode: every integrator in it, beside the spectral path tracer (the
# still life's polarising filter, a delta sheet in front of the lens, leaves light tracing and
# BDPT's light paths black there: still an image to keep identical).
for scene in scenes/polarisation/*.json; do
  name=$(echo "${scene#scenes/}" | tr / _); name=${name%.json}
  for variant in "path polarised" "light polarised" "bdpt polarised" "path spectral"; do
    set -- $variant
    integrator=$1 mode=$2; shift 2
    image="$out/$name-$integrator-$mode.exr"
    "$lamina" render "$scene" -o "$image" --integrator "$integrator" --mode "$mode" --spp 4 \
      --seed 7 --threads 1 -q "$@"
    if [ -n "$baseline" ]; then
      if [ ! -e "$baseline/$(basename "$image")" ]; then
        echo "render-identity: $image is new (no image of it in $baseline)"
      elif ! idiff -q -fail 0 -failpercent 0 -warn 0 "$baseline/$(basename "$image")" "$image" >/dev/null; then
        echo "render-identity: $image differs from $baseline"; status=1
      fi
    fi
  done
done
[ -n "$baseline" ] && [ $status -eq 0 ] && echo "render-identity: every image is bit-identical to $baseline"
exit $status
