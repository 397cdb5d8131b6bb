#!/usr/bin/env bash
# `pip install .` as a Python user types it (README, "Installing elsewhere"): the build installed
# into a fresh prefix, a fresh venv that sees Debian's numpy, scipy, networkx, h5py, setuptools and
# pybind11, then `pip install --no-build-isolation .` from the checkout, which builds only the
# extension module against that prefix (python/CMakeLists.txt). tests/python must pass inside the
# venv with the module pip installed there (not the build tree's, not the prefix's copy), and the
# checkout must be left as it was: setuptools' build and egg-info folders go to WORK_DIR.
#   pip_install.sh BUILD_DIR SOURCE_DIR WORK_DIR PYTHON
set -euo pipefail
build="$1"
src="$2"
work="$3"
python="$4"
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"
venv="$work/venv"
log="$work/log.txt"
fail() { cat "$log"; echo "pip_install.sh: $*"; exit 1; }
# Each step's wall time goes into the summary line: this test's cost counts against CI's budget.
times=""
mark() { times+="$1 $((SECONDS - start)) s, "; start=$SECONDS; }
start=$SECONDS
tree_state() { git -C "$src" --no-optional-locks status --porcelain 2> /dev/null || true; }
before="$(tree_state)"

cmake --install "$build" --prefix "$prefix" > "$log" 2>&1 || fail "cmake --install failed"
mark install
"$python" -m venv --system-site-packages "$venv" >> "$log" 2>&1 || fail "venv failed"
mark venv
# Offline and deterministic: no index, no cache, no version check, no PYTHONPATH from outside.
export PIP_NO_INDEX=1 PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1
unset PYTHONPATH
(cd "$src" && CMAKE_PREFIX_PATH="$prefix" HMFNET_PIP_BUILD_DIR="$work/pip-build" \
  "$venv/bin/python" -m pip install --no-build-isolation . >> "$log" 2>&1) \
  || fail "pip install failed"
mark "pip install"

# From WORK_DIR, so that no copy of the package in the checkout can be imported.
cd "$work"
"$venv/bin/python" - "$venv" >> "$log" 2>&1 <<'PY' || fail "the venv imports another hmfnet"
import os, sys
import hmfnet, hmfnet._hmfnet
venv = os.path.realpath(sys.argv[1])
for f in (hmfnet.__file__, hmfnet._hmfnet.__file__):
    assert os.path.realpath(f).startswith(venv + os.sep), f
print("hmfnet from", os.path.dirname(hmfnet._hmfnet.__file__))
PY
HMFNET_CLI="$prefix/bin/hmfnet" "$venv/bin/python" -m pytest -q -p no:cacheprovider \
  "$src/tests/python" >> "$log" 2>&1 || fail "tests/python failed in the venv"
mark pytest
summary="$(tail -n 1 "$log")"

[ "$(tree_state)" = "$before" ] || fail "the checkout changed: $(tree_state)"
leftovers="$(find "$src/python" "$src/build" -maxdepth 1 \
  \( -name '*.egg-info' -o -name 'lib.*' -o -name 'temp.*' -o -name 'bdist.*' \) 2> /dev/null \
  || true)"
[ -z "$leftovers" ] || fail "setuptools wrote into the checkout: $leftovers"
echo "pip_install.sh: ${times}tests/python in the venv: $summary"
cd / && rm -rf "$work"
