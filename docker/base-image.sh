#!/usr/bin/env bash
# Makes a local Debian 12 base image with Python 3.11, for machines that cannot pull
# python:3.11-slim-bookworm from a registry: debootstrap from Debian's own packages, then
# `docker import`. Prints the image's tag (shadergen-base:<hash of this script>).
#   docker build -f docker/Dockerfile --build-arg BASE="$(bash docker/base-image.sh)" ...
# The root filesystem is kept as a tarball in $SHADERGEN_DOCKER_CACHE (~/.cache/shadergen-docker),
# named by this script's content, so a second run (or a new dockerd) only imports it.
set -euo pipefail
script_hash=$(sha256sum "${BASH_SOURCE[0]}" | cut -c1-12)
tag="shadergen-base:$script_hash"
cache_dir="${SHADERGEN_DOCKER_CACHE:-$HOME/.cache/shadergen-docker}"
tarball="$cache_dir/bookworm-python3-$script_hash.tar"
mirror="${DEBIAN_MIRROR:-http://deb.debian.org/debian}"

if docker image inspect "$tag" >/dev/null 2>&1; then echo "$tag"; exit 0; fi

if [ ! -f "$tarball" ]; then
  mkdir -p "$cache_dir"
  rootfs=$(mktemp -d "$cache_dir/rootfs.XXXXXX")
  trap 'rm -rf "$rootfs" "$tarball.partial"' EXIT
  # what python:3.11-slim-bookworm offers: Debian 12, Python 3.11 with venv, CA certificates
  debootstrap --variant=minbase --include=python3,python3-venv,ca-certificates \
    bookworm "$rootfs" "$mirror" >&2
  # apt inside the image reads the same mirror; the downloaded packages are not part of the image
  echo "deb $mirror bookworm main" > "$rootfs/etc/apt/sources.list"
  rm -rf "$rootfs"/var/cache/apt/archives/*.deb "$rootfs"/var/lib/apt/lists/*
  # as Debian's own container images: packages installed in a build start no services, and
  # documentation is left out (now and in every later apt-get install)
  printf '#!/bin/sh\nexit 101\n' > "$rootfs/usr/sbin/policy-rc.d"
  chmod 755 "$rootfs/usr/sbin/policy-rc.d"
  printf '%s\n' 'path-exclude /usr/share/doc/*' 'path-include /usr/share/doc/*/copyright' \
    'path-exclude /usr/share/man/*' 'path-exclude /usr/share/info/*' 'path-exclude /usr/share/locale/*' \
    > "$rootfs/etc/dpkg/dpkg.cfg.d/docker-slim"
  find "$rootfs/usr/share/doc" -mindepth 1 -not -name copyright -not -type d -delete
  rm -rf "$rootfs"/usr/share/man/* "$rootfs"/usr/share/info/* "$rootfs"/usr/share/locale/*
  rm -f "$cache_dir"/bookworm-python3-*.tar  # made by other versions of this script
  tar -C "$rootfs" --numeric-owner -cf "$tarball.partial" .
  mv "$tarball.partial" "$tarball"
fi

docker import --change 'CMD ["/bin/bash"]' --change 'ENV LANG=C.UTF-8' "$tarball" "$tag" >/dev/null
echo "$tag"
