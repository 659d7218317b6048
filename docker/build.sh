#!/usr/bin/env bash
# Builds the image shadergen:latest on a machine that cannot use a registry: the base is a local
# Debian 12 made by docker/base-image.sh, and pip in the build takes its wheels from a folder
# served on 127.0.0.1 only. The wheels are made beforehand by the base image's own Python (its
# version decides which wheels and markers apply) on the host's network, trusting the certificates
# this machine's pip trusts ($PIP_CERT, else Debian's bundle). Where registries can be reached,
# the plain `docker build -f docker/Dockerfile -t shadergen .` needs none of this.
# Usage: bash docker/build.sh [extra docker build arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
cache_dir="${SHADERGEN_DOCKER_CACHE:-$HOME/.cache/shadergen-docker}"

base=$(bash docker/base-image.sh)

# the wheels of exactly what the image installs, in a folder named by that list and the base
requirements=$(python3 docker/requirements.py pyproject.toml)
wheels="$cache_dir/wheels-$(sha256sum <<<"$base $requirements" | cut -c1-12)"
if [ ! -f "$wheels/complete" ]; then
  mkdir -p "$wheels"
  docker run --rm -i --network host -v "$wheels:/wheels" \
    -v "${PIP_CERT:-/etc/ssl/certs/ca-certificates.crt}:/etc/ssl/host-certificates.pem:ro" \
    -e PIP_CERT=/etc/ssl/host-certificates.pem -e PIP_DISABLE_PIP_VERSION_CHECK=1 "$base" \
    sh -c 'python3 -m venv /tmp/pip && /tmp/pip/bin/pip wheel -q --wheel-dir /wheels -r /dev/stdin' <<<"$requirements"
  touch "$wheels/complete"
fi

# the server's address is a build argument, hence part of the build cache's key: a port chosen by
# the wheels' folder keeps the cache valid from one build to the next (another one if it is taken)
port=$(python3 - "$wheels" <<'EOF'
import socket, sys, zlib
with socket.socket() as s:
    try:
        s.bind(("127.0.0.1", 20000 + zlib.crc32(sys.argv[1].encode()) % 20000))
    except OSError:
        s.bind(("127.0.0.1", 0))
    print(s.getsockname()[1])
EOF
)
python3 -m http.server --bind 127.0.0.1 --directory "$wheels" "$port" >/dev/null 2>&1 &
server=$!
trap 'kill $server' EXIT
for _ in $(seq 100); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/', timeout=1)" 2>/dev/null && break
  sleep 0.1
done

# the classic builder: it runs RUN steps on the host's network, where the wheel server listens
DOCKER_BUILDKIT=0 docker build --network host -f docker/Dockerfile -t shadergen:latest \
  --build-arg BASE="$base" --build-arg PIP_FIND_LINKS="http://127.0.0.1:$port/" --build-arg PIP_NO_INDEX=1 \
  "$@" .
