#!/usr/bin/env bash
# The rooms' dependency rule (docs/architecture.md): core <- spectral <- bsdf <- image,
# interchange <- scene <- render <- experiments <- app, and python/ beside app. Inside the
# render library: geometry <- lights <- render, integrators <- output (the render loop runs an
# integrator and an integrator writes to the film, so those two folders use each other). Fails,
# naming the file and the line, when a room includes a header of a room it may not use, python/
# includes app/, or CLI11 is included outside app/. Run by ctest (label unit).
set -euo pipefail
cd "$(dirname "$0")/.."
# room folder : the lamina/<name>/ header folders it may include (its own first)
rules=(
  "core:core"
  "spectral:spectral core"
  "bsdf:bsdf spectral core"
  "renderer/image:image core"
  "renderer/interchange:interchange spectral core"
  "renderer/scene:scene interchange image bsdf spectral core"
  "renderer/geometry:geometry scene image bsdf spectral core"
  "renderer/lights:lights geometry scene image bsdf spectral core"
  "renderer/render:render integrators lights geometry scene image bsdf spectral core"
  "renderer/integrators:integrators render lights geometry scene image bsdf spectral core"
  "renderer/output:output render integrators lights geometry scene image bsdf spectral core"
  "experiments:experiments output render integrators lights geometry scene interchange image bsdf spectral core"
  "app:app experiments output render integrators lights geometry scene interchange image bsdf spectral core"
  "python:experiments output render integrators lights geometry scene interchange image bsdf spectral core"
)
status=0
for rule in "${rules[@]}"; do
  room=${rule%%:*}
  allowed=" ${rule#*:} "
  # Every lamina/<name>/ include of the room's sources, as FILE:LINE:NAME.
  while IFS= read -r hit; do
    [ -z "$hit" ] && continue
    name=$(sed -E 's#.*\#include [<"]lamina/([a-z_]+)/.*#\1#' <<<"$hit")
    [ "$name" = version ] && continue  # the generated version header (app/, python/)
    if [[ "$allowed" != *" $name "* ]]; then
      echo "check-layering: $room may not include lamina/$name/: ${hit%%#include*}"; status=1
    fi
  done < <(grep -rnE "#include [<\"]lamina/[a-z_]+/" "$room" --include='*.h' --include='*.cpp' || true)
  if [ "$room" != app ] && hits=$(grep -rnE '#include [<"]CLI/' "$room" --include='*.h' --include='*.cpp'); then
    echo "check-layering: only app/ may include CLI11:"; echo "$hits"; status=1
  fi
done
# Every folder of renderer/ is a room above (a new one needs its rule).
for dir in renderer/*/; do
  dir=${dir%/}
  if ! printf '%s\n' "${rules[@]}" | grep -q "^$dir:"; then
    echo "check-layering: $dir has no rule in scripts/check-layering.sh"; status=1
  fi
done
# The rooms below lamina_render link no Embree: their sources include none of its headers.
if hits=$(grep -rnE '#include [<"]embree' core spectral bsdf renderer/image renderer/interchange \
          renderer/scene --include='*.h' --include='*.cpp'); then
  echo "check-layering: only lamina_render may include Embree:"; echo "$hits"; status=1
fi
# python/ sits beside app/: experiments and below, never app/'s sources or CLI11.
if hits=$(grep -rnE '#include [<"](CLI/|app/|\.\./)' python --include='*.h' --include='*.cpp'); then
  echo "check-layering: python/ may not include app/ or CLI11:"; echo "$hits"; status=1
fi
# A material type lives in its own files (docs/architecture.md, "A new material"): the files
# every type passes through name none of them.
models=$(grep -hoE '^LAMINA_MATERIAL_MODEL\([A-Za-z0-9_]+\)' bsdf/include/lamina/bsdf/*.h |
         sed -E 's/.*\((.*)\)/\1/')
for model in $models; do
  if hits=$(grep -nw "$model" bsdf/include/lamina/bsdf/material.h \
            bsdf/include/lamina/bsdf/material_builder.h bsdf/include/lamina/bsdf/material_kind.h \
            bsdf/src/material_kinds.cpp bsdf/src/material_parser.cpp \
            bsdf/src/bsdf_instantiations.cpp); then
    echo "check-layering: $model is named in a file every material type passes through:"
    echo "$hits"; status=1
  fi
done
[ -n "$models" ] || { echo "check-layering: no LAMINA_MATERIAL_MODEL marks found"; status=1; }
[ $status -eq 0 ] && echo "check-layering: every include points down the rooms"
exit $status
