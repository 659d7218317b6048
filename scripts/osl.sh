#!/usr/bin/env bash
# OpenShadingLanguage's oslc, oslinfo, testshade and testrender for the OSL target, its checker and
# its benchmark. OSL is in no package registry these machines reach (not Debian 12, not PyPI), so
# it is built once from the release's source into ~/.cache/shadergen/osl-<sha256 of the tarball>/
# (bin/, lib/, share/OSL/shaders/: where oslc looks for stdosl.h beside itself) and linked into
# .venv/bin. An oslc >= 1.13 already on PATH is taken as it is.
#   SHADERGEN_OSL_SOURCE  the source tarball: a path or an http(s) URL (default: the vendored copy in
#                         ../shared/vendor/ when there is one, else the project's v1.13.12.0 release)
#   scripts/osl.sh --have  exits 0 when a usable oslc is on PATH (system-packages.sh asks it)
# The build (Debian 12's LLVM 15, OpenImageIO 2.4: scripts/system-packages.sh installs them) runs
# at -j2 and builds only the four programs; an interrupted build resumes in its .build folder, and
# the cache folder appears in one rename when everything is in it. A cold build (configure and
# make, not the unpacking) took 428 s on the project's 2-core machine (2026-12-02, its own "osl:
# built in" line); the cache keeps that line in build-time.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
VERSION=1.13.12.0
RELEASE_URL="https://github.com/AcademySoftwareFoundation/OpenShadingLanguage/archive/refs/tags/v$VERSION.tar.gz"
VENDORED="../shared/vendor/OpenShadingLanguage-v$VERSION-src.tar.gz"
PROGRAMS=(oslc oslinfo testshade testrender)

usable_oslc() {  # an oslc on PATH that says it is 1.13 or newer ("oslc -- ... compiler 1.13.12")
  command -v oslc >/dev/null || return 1
  local version
  version=$(oslc --help 2>/dev/null | awk 'NR == 1 { print $NF }')
  [ -n "$version" ] || return 1
  printf '%s\n1.13\n' "$version" | sort -V -C -r
}

if [ "${1:-}" = "--have" ]; then usable_oslc; exit; fi
if usable_oslc && [ "$(command -v oslc)" != "$PWD/.venv/bin/oslc" ]; then
  echo "osl: using $(command -v oslc)"
  exit 0
fi

source="${SHADERGEN_OSL_SOURCE:-}"
if [ -z "$source" ]; then
  # beside the checkout, or beside the main checkout of a git worktree
  main=$(dirname "$(git rev-parse --path-format=absolute --git-common-dir 2>/dev/null || echo .)")
  for candidate in "$VENDORED" "$main/$VENDORED" "$RELEASE_URL"; do
    source="$candidate"; [ -f "$candidate" ] && break
  done
fi
cache="${XDG_CACHE_HOME:-$HOME/.cache}/shadergen"
mkdir -p "$cache"
tarball="$source"
case "$source" in
  http://*|https://*)
    tarball="$cache/osl-download-$$.tar.gz"
    trap 'rm -f "$tarball"' EXIT
    echo "osl: fetching $source"
    curl -fsSL --retry 3 -o "$tarball" "$source" ;;
esac
[ -f "$tarball" ] || { echo "osl: no OSL source at $source (set SHADERGEN_OSL_SOURCE)" >&2; exit 1; }
sum=$(sha256sum "$tarball" | cut -d' ' -f1)
home="$cache/osl-$sum"

if [ ! -x "$home/bin/oslc" ]; then
  work="$home.build"
  mkdir -p "$work"
  if [ ! -f "$work/src/CMakeLists.txt" ]; then
    rm -rf "$work/src" && mkdir -p "$work/src"
    # the vendored tarball holds the tree itself, the project's release archive one folder of it
    strip=0
    case "$(tar tzf "$tarball" | awk 'NR == 1')" in */*) strip=1 ;; esac
    tar xzf "$tarball" -C "$work/src" --strip-components=$strip
    # testshade and testrender are built only with the whole test suite registered, which the
    # vendored tarball leaves out: build them with OSL_BUILD_TESTS alone
    sed -i 's/^if (OSL_BUILD_TESTS AND BUILD_TESTING)$/if (OSL_BUILD_TESTS)/' "$work/src/CMakeLists.txt"
  fi
  echo "osl: building OSL $VERSION (oslc, oslinfo, testshade, testrender) in $work"
  started=$(date +%s)
  if [ ! -f "$work/build/Makefile" ]; then
    cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DLLVM_ROOT=/usr/lib/llvm-15 \
      -DUSE_PYTHON=0 -DUSE_QT=0 -DOSL_BUILD_TESTS=ON -DBUILD_TESTING=OFF -DUSE_PARTIO=0 \
      -DUSE_OPTIX=0 -DOSL_BUILD_MATERIALX=0 -DOSL_BUILD_PLUGINS=0 -DSTOP_ON_WARNING=0 \
      -DCMAKE_BUILD_RPATH_USE_ORIGIN=ON > "$work/configure.log" 2>&1 \
      || { tail -40 "$work/configure.log" >&2; exit 1; }
  fi
  make -C "$work/build" -j2 "${PROGRAMS[@]}" > "$work/make.log" 2>&1 || { tail -40 "$work/make.log" >&2; exit 1; }
  staged="$home.staged-$$"
  rm -rf "$staged" && mkdir -p "$staged/bin" "$staged/lib" "$staged/share/OSL/shaders"
  for program in "${PROGRAMS[@]}"; do cp "$work/build/bin/$program" "$staged/bin/"; done
  cp -P "$work"/build/lib/*.so* "$staged/lib/"
  cp "$work"/src/src/shaders/*.h "$staged/share/OSL/shaders/"
  "$staged/bin/oslc" --help > /dev/null  # finds its libraries through $ORIGIN/../lib
  built="osl: built in $(( $(date +%s) - started )) s at -j2 on $(nproc) cores, $(date -u +%Y-%m-%d)"
  echo "$built" > "$staged/build-time.txt"
  mv -T "$staged" "$home"
  rm -rf "$work"
  echo "$built into $home"
fi
mkdir -p .venv/bin
for program in "${PROGRAMS[@]}"; do ln -sfn "$home/bin/$program" ".venv/bin/$program"; done
echo "osl: $(.venv/bin/oslc --help | head -1) in .venv/bin"
