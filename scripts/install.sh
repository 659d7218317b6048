#!/usr/bin/env bash
# One command: system packages, a virtual environment with everything, then a shader for the sample document.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/system-packages.sh
[ -x .venv/bin/python ] || python3 -m venv .venv
bash scripts/osl.sh  # oslc & co. for the OSL target, built once into ~/.cache/shadergen
mkdir -p out
.venv/bin/pip install -q --upgrade pip
# compat: the checkout goes on sys.path through a plain .pth line; setuptools' default editable
# install hooks a finder into every process start, which imports pathlib and re (a tenth of a
# cold `shadergen generate`)
.venv/bin/pip install -q -e ".[render,wgpu,service,usd,ocio]" --config-settings editable_mode=compat
# an editable install compiles nothing: write the bytecode now, or every cold process compiles it
.venv/bin/python -m compileall -q shadergen service > /dev/null
.venv/bin/shadergen generate examples/marble_checker.mtlx --out out/marble_checker > out/marble_checker.jsonl
echo "shader written to out/marble_checker; start the service with: .venv/bin/shadergen serve"
