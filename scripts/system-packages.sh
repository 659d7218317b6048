#!/usr/bin/env bash
# Debian packages the project needs: Mesa EGL (llvmpipe) for headless thumbnails (moderngl's EGL
# back end loads libEGL.so.1 and libGL.so.1: libegl1, libgl1), glslang-tools to validate generated
# GLSL/ESSL and compile Vulkan GLSL to SPIR-V, spirv-tools (spirv-val) to validate that SPIR-V, mesa-vulkan-drivers (lavapipe, with libvulkan1) for wgpu, which validates and draws
# generated WGSL, redis-server for the multi-machine back ends' tests, chromium and chromium-driver for
# the web editor's browser tests (WebGL2 on SwiftShader), and what scripts/osl.sh builds
# OpenShadingLanguage with, unless an oslc >= 1.13 is on PATH (LLVM and clang 15, OpenImageIO 2.4,
# whose CMake files name /usr/bin/iconvert from openimageio-tools and /usr/include/opencv4 from
# libopencv-core-dev, Imath/OpenEXR, pugixml, Boost, TBB, fmt, flex, bison). With --containers also what the
# container test needs: a Docker engine and compose (any already installed, such as Docker's own
# docker-ce, is used as it is) and debootstrap.
set -euo pipefail
pkgs=(libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libgbm1 mesa-vulkan-drivers glslang-tools spirv-tools redis-server python3-venv chromium chromium-driver)
if ! bash "$(dirname "$0")/osl.sh" --have; then
  pkgs+=(cmake g++ make curl flex bison llvm-15-dev clang-15 libclang-15-dev libclang-cpp15-dev
    libopenimageio-dev openimageio-tools libopencv-core-dev libimath-dev libopenexr-dev
    libpugixml-dev libboost-dev libboost-filesystem-dev libboost-system-dev libboost-thread-dev
    libtbb-dev libfmt-dev zlib1g-dev libtinfo-dev libzstd-dev libedit-dev libxml2-dev libpng-dev
    libtiff-dev)
fi
if [ "${1:-}" = "--containers" ]; then
  command -v dockerd >/dev/null || pkgs+=(docker.io)
  command -v docker-compose >/dev/null || docker compose version >/dev/null 2>&1 || pkgs+=(docker-compose)
  pkgs+=(debootstrap)
fi
missing=()
for p in "${pkgs[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
