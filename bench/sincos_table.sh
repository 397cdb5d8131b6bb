#!/usr/bin/env bash
# sincos per angle, one thread (docs/performance.md "sincos"): bench/sincos_versions.cpp built
# with this tree's src/dynamics/sincos.cpp and with REV's (default b72fe30, the last commit
# before the AVX-512 version), timed alternately in one process beside SLEEF's AVX-512 sincos
# where Debian's libsleef-dev is installed (a benchmark's comparison only: hmfnet does not link
# it), then numpy's sin and cos on the same 4096 angles. Needs g++ and python3 with numpy
# (PYTHON: the interpreter, default python3).
# Usage: bench/sincos_table.sh [REV]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rev=${1:-b72fe30}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/before/dynamics"
for f in sincos.hpp sincos.cpp kernel_arithmetic.hpp vector_lanes.hpp; do
  # vector_lanes.hpp joined the sincos after b72fe30: taken where REV has it.
  git -C "$root" cat-file -e "$rev:src/dynamics/$f" 2>/dev/null || continue
  git -C "$root" show "$rev:src/dynamics/$f" >"$tmp/before/dynamics/$f"
done
# The Release build's flags and the ones src/CMakeLists.txt adds for sincos.cpp.
flags=(-O3 -DNDEBUG -std=c++17 -fopenmp -ffp-contract=off -Wno-psabi)
g++ "${flags[@]}" -I"$tmp/before" -Dhmfnet=hmfnet_before -c "$tmp/before/dynamics/sincos.cpp" \
  -o "$tmp/before.o"
g++ "${flags[@]}" -I"$root/src" -c "$root/src/dynamics/sincos.cpp" -o "$tmp/after.o"
sleef=()
if [[ -f /usr/include/x86_64-linux-gnu/sleef.h ]]; then
  g++ "${flags[@]}" -mavx512f -DHMFNET_BENCH_SLEEF_WRAPPERS -I"$root/src" -c \
    "$root/bench/sincos_versions.cpp" -o "$tmp/sleef.o"
  sleef=(-DHMFNET_BENCH_SLEEF "$tmp/sleef.o" -lsleef)
else
  echo "libsleef-dev not installed: SLEEF not measured"
fi
g++ "${flags[@]}" -I"$root/src" "$root/bench/sincos_versions.cpp" "$tmp/before.o" "$tmp/after.o" \
  "${sleef[@]}" -o "$tmp/sincos_versions"
lscpu | sed -n 's/^Model name: *//p'
"$tmp/sincos_versions"
"${PYTHON:-python3}" - <<'PY'
import time
import numpy as np
x = np.random.default_rng(1).uniform(-100.0, 100.0, 4096)
out = np.empty_like(x)
best = {}
for _ in range(7):
    for f in (np.sin, np.cos):
        t0 = time.perf_counter()
        for _ in range(2000):
            f(x, out=out)
        ns = (time.perf_counter() - t0) / (2000 * x.size) * 1e9
        best.setdefault(f.__name__, []).append(ns)
med = {k: sorted(v)[len(v) // 2] for k, v in best.items()}
print("numpy %s sin + cos: %.3f + %.3f = %.3f ns/angle (medians of 7)"
      % (np.__version__, med["sin"], med["cos"], med["sin"] + med["cos"]))
PY
