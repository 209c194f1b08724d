#!/usr/bin/env bash
# Installs every build and test dependency of lamina from Debian 12 packages.
# Idempotent: packages already installed are skipped; `apt-get update` runs at most once,
# and only when something is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools libopenexr-dev
  libglm-dev nlohmann-json3-dev libcli11-dev libyaml-cpp-dev libnanovdb-dev libboost-dev
  colord-data libtinyobjloader-dev libpugixml-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-jsonschema
  python3-dev pybind11-dev python3-pybind11 python3-pytest python3-openvdb
  clang libclang-rt-14-dev
  slurm-wlm munge
  chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "setup: need root to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
