#!/usr/bin/env bash
# The rooms' dependency rule (docs/architecture.md): core <- spectral <- bsdf <- renderer <-
# experiments <- app, and python/ beside app. Fails, naming the file and the line, when a room
# includes a room to its right, python/ includes app/, or CLI11 is included outside app/. Run by
# ctest (label unit).
set -euo pipefail
cd "$(dirname "$0")/.."
rooms=(core spectral bsdf renderer experiments app)
headers=(core spectral bsdf render experiments app)  # lamina/<name>/ of each room's headers
status=0
for i in "${!rooms[@]}"; do
  room=${rooms[$i]}
  for j in "${!rooms[@]}"; do
    [ "$j" -le "$i" ] && continue
    if hits=$(grep -rnE "#include [<\"]lamina/${headers[$j]}/" "$room" --include='*.h' --include='*.cpp'); then
      echo "check-layering: $room may not include ${rooms[$j]}:"; echo "$hits"; status=1
    fi
  done
  if [ "$room" != app ] && hits=$(grep -rnE '#include [<"]CLI/' "$room" --include='*.h' --include='*.cpp'); then
    echo "check-layering: only app/ may include CLI11:"; echo "$hits"; status=1
  fi
done
# python/ sits beside app/: experiments and below, never app/'s sources or CLI11.
if hits=$(grep -rnE '#include [<"](CLI/|app/|\.\./)' python --include='*.h' --include='*.cpp'); then
  echo "check-layering: python/ may not include app/ or CLI11:"; echo "$hits"; status=1
fi
[ $status -eq 0 ] && echo "check-layering: every include points down the rooms"
exit $status
