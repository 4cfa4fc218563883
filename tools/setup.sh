#!/usr/bin/env bash
# Installs what simeco needs from Debian's packages (when missing) and builds it into build/ (Release), with the
# readers' fuzz targets in build-fuzz/.
# Usage: tools/setup.sh [--sanitize]   (--sanitize builds an AddressSanitizer/UBSan tree into build-asan/)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config git python3
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools spirv-tools
  glslang-tools glslang-dev
  libglm-dev libglfw3-dev libimgui-dev libopenexr-dev libpng-dev libtinyobjloader-dev
  xvfb xauth xdotool
  libgtest-dev libcli11-dev nlohmann-json3-dev libfmt-dev liblzma-dev
  gnuplot-nox
  clang libclang-rt-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "simeco setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build=build
flags=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  build=build-asan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSIMECO_SANITIZE=ON)
fi
cmake -S . -B "$build" "${flags[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"
# The readers' fuzz targets (clang, libFuzzer), which a test runs for a minute.
[ "$build" = build ] && ./tools/fuzz.sh --build-only
