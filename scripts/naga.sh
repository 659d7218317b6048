#!/usr/bin/env bash
# naga, the WGSL validator wgpu itself runs, pinned: the tests validate every generated WGSL module with it.
# Built from crates.io with cargo (a few minutes the first time); an installed naga of this version is kept.
set -euo pipefail
VERSION=30.0.1
if naga --version 2>/dev/null | grep -qx "$VERSION"; then exit 0; fi
if ! command -v cargo >/dev/null; then
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends cargo
fi
cargo install naga-cli --version "$VERSION" --locked --root "${NAGA_ROOT:-$HOME/.cargo}"
