#!/usr/bin/env bash
# Quick start, command 2: install and build if needed, then run the test suite
# (labels unit, verification, regression, mpi, python, install; verification-full and paper are left out).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/build.sh
cd build
ctest -L '^(unit|verification|regression|mpi|python|install)$' -j "$(nproc)" --output-on-failure --timeout 900
