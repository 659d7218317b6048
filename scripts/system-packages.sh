#!/usr/bin/env bash
# Debian packages the project needs: Mesa EGL (llvmpipe) for headless thumbnails (moderngl's EGL
# back end loads libEGL.so.1 and libGL.so.1: libegl1, libgl1), glslang-tools to validate generated
# GLSL/ESSL, mesa-vulkan-drivers (lavapipe, with libvulkan1) for wgpu, which validates and draws
# generated WGSL, redis-server for the multi-machine back ends' tests, chromium and chromium-driver for
# the web editor's browser tests (WebGL2 on SwiftShader). With --containers also what the
# container test needs: a Docker engine and compose (any already installed, such as Docker's own
# docker-ce, is used as it is) and debootstrap.
set -euo pipefail
pkgs=(libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libgbm1 mesa-vulkan-drivers glslang-tools redis-server python3-venv chromium chromium-driver)
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
