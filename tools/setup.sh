#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages), then configures and builds the release preset.
# Idempotent: a second run only rebuilds what changed. Usage: bash tools/setup.sh [preset]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"

packages=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools libspirv-cross-c-shared-dev
  libglfw3-dev libglm-dev libopenvdb-dev libopenvdb-tools libblosc-dev zlib1g-dev time
  libgtest-dev libgmock-dev libbenchmark-dev
  libstb-dev libopenexr-dev libtomlplusplus-dev libcli11-dev libfmt-dev libspdlog-dev libimgui-dev
  libsqlite3-dev libzstd-dev  # the world store (docs/WORLD_STORE.md)
  python3 python3-matplotlib xvfb xauth clang clang-format
  ffmpeg  # optional: vox capture writes an MP4 when it is on PATH
  slurm-wlm munge parallel  # capture and sweep jobs (--scheduler slurm|parallel); the test starts a one-node Slurm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: run as root or install sudo" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

echo "setup: building preset '$preset'"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
