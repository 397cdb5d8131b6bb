#!/usr/bin/env bash
# Installs the dependencies, configures and builds hmfnet into build/ (CLI at build/bin/hmfnet).
# CI (CI=true) builds with warnings as errors.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/install-deps.sh
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DHMFNET_WERROR="$werror" > build.log 2>&1 \
  || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)"
