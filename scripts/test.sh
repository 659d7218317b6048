#!/usr/bin/env bash
# The test command: installs what the tests need, then runs them. pytest's exit 5 (no tests) is a failure.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/system-packages.sh --containers || exit 1
[ -x .venv/bin/python ] || python3 -m venv .venv || exit 1
bash scripts/osl.sh || exit 1  # oslc & co. for the OSL target, built once into ~/.cache/shadergen
.venv/bin/pip install -q --upgrade pip || exit 1
.venv/bin/pip install -q -e ".[render,wgpu,service,usd,ocio,slang,dev]" --config-settings editable_mode=compat || exit 1  # see install.sh
.venv/bin/python -m pytest -q "$@"
rc=$?
[ $rc -eq 5 ] && { echo "pytest collected no tests: failing"; exit 1; }
exit $rc
