#!/usr/bin/env bash
# Two builds' benchmarks in one run: OLD and NEW alternated, ROUNDS rounds, every benchmark that
# FILTER selects (Google Benchmark's regular expression). These machines are noisy: only ratios
# within a round mean much, so each row gives the median of the per-round ratios NEW / OLD beside
# the per-round ones and the median rates (unit G/s: a benchmark's rate counter, G stored entries
# or rotors x replicas x steps/s; 1/t: the inverse of its real time, in its own time unit).
# Usage: bench/before_after.sh OLD_BUILD_DIR NEW_BUILD_DIR FILTER [ROUNDS (3)] [MIN_TIME (1)]
# Environment: OMP_WAIT_POLICY and the rest pass through to both (the thread rows of
# docs/performance.md ran with OMP_WAIT_POLICY=active: spinning threads).
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 OLD_BUILD_DIR NEW_BUILD_DIR FILTER [ROUNDS] [MIN_TIME]" >&2
  exit 2
fi
old=$1 new=$2 filter=$3 rounds=${4:-3} min_time=${5:-1}
for build in "$old" "$new"; do
  if [ ! -x "$build/bin/hmfnet_bench" ]; then
    echo "$0: $build/bin/hmfnet_bench: no benchmark binary (configure with -DHMFNET_BUILD_BENCH=ON)" >&2
    exit 2
  fi
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for which in old new; do
    build=$old
    [ "$which" = new ] && build=$new
    if ! "$build/bin/hmfnet_bench" --benchmark_filter="$filter" --benchmark_min_time="$min_time" \
      --benchmark_format=json >"$out/${which}_${round}.json" 2>"$out/stderr"; then
      echo "$0: $build/bin/hmfnet_bench failed:" >&2
      cat "$out/stderr" >&2
      exit 1
    fi
    if [ ! -s "$out/${which}_${round}.json" ]; then
      echo "$0: $build/bin/hmfnet_bench ran no benchmark: FILTER '$filter' matches none" >&2
      exit 1
    fi
  done
done
python3 - "$out" "$rounds" <<'PY'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
def rates(which, r):
    got = {}
    for b in json.load(open(f"{out}/{which}_{r}.json"))["benchmarks"]:
        counter = [k for k in b if k.endswith("_per_s")]
        got[b["name"]] = (b[counter[0]] / 1e9, "G/s") if counter else (1.0 / b["real_time"], "1/t")
    return got
data = {(w, r): rates(w, r) for w in ("old", "new") for r in range(1, rounds + 1)}
names = [n for n in data[("new", 1)] if all(n in data[(w, r)] for w in ("old", "new")
                                            for r in range(1, rounds + 1))]
if not names:
    sys.exit("no benchmark ran in both builds")
width = max(len(n) for n in names)
print("%-*s %9s %9s %4s %8s  %s" % (width, "benchmark", "old", "new", "unit", "new/old",
                                    "rounds"))
for n in names:
    old = [data[("old", r)][n][0] for r in range(1, rounds + 1)]
    new = [data[("new", r)][n][0] for r in range(1, rounds + 1)]
    ratios = [b / a for a, b in zip(old, new)]
    print("%-*s %9.4g %9.4g %4s %7.2fx  %s" % (width, n, statistics.median(old),
          statistics.median(new), data[("new", 1)][n][1], statistics.median(ratios),
          "/".join("%.2f" % x for x in ratios)))
PY
