#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine for gtlab: installs the Debian packages it
# builds against, then configures and builds into ./build (Release with debug
# info). Safe to run again. clang, its libFuzzer runtime (libclang-rt-14-dev),
# its OpenMP (libomp-dev) and LLVM's tools (llvm) are for the fuzz build and
# the recursion audit (tests/fuzz, tests/audit). blender-data ships the eight
# CC0 HDR environments (techniques/environment/README.md, "The references"). chromium
# (headless) loads report.html in the browser test (tests/report).
# libvulkan-dev, mesa-vulkan-drivers (lavapipe: a Vulkan device on the CPU),
# libshaderc-dev with glslang-dev and spirv-tools (static libraries shaderc
# links) and glslc run shaders on Vulkan (gpu/, docs/shaders.md).
# libopenmpi-dev and openmpi-bin build and test MPI renders (GTLAB_MPI=AUTO,
# `mpirun -n N gtlab render ...`; docs/decisions.md, "Beyond one machine").
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  build-essential cmake pkg-config
  libembree-dev libopenexr-dev libopenimageio-dev openimageio-tools
  libceres-dev libeigen3-dev libtinygltf-dev libstb-dev nlohmann-json3-dev libcjson-dev python3-imath
  libssl-dev assimp-testmodels gnuplot-nox glslang-tools
  libdraco-dev libmeshoptimizer-dev gltfpack
  clang libclang-rt-14-dev libomp-dev llvm
  libsquish-dev liblcms2-dev libgsl-dev
  libopenmpi-dev openmpi-bin
  blender-data
  libvulkan-dev mesa-vulkan-drivers libshaderc-dev glslang-dev spirv-tools glslc
  chromium
)

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  as_root apt-get update
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j"$(nproc)"
