#!/usr/bin/env bash
# Segmented rows (docs/performance.md, "Segmented rows"): hmfnet's leap-frog step (LeapFrogStep,
# ER mean degree 100, 1 thread, B = 1, 2 and 8 (where a build has no B = 2 rows: '-'), float64
# and float32) at N = 10^4 and 10^6 from two builds, OLD and NEW, alternated in ROUNDS rounds
# (these machines are noisy: only ratios within a round mean much); one process per binary and
# N, so each process's peak RSS is that N's.
# Prints per row the median rate of each binary (G stored entries x replicas x steps/s), the
# median of the per-round ratios NEW / OLD, N = 10^6 as a share of N = 10^4, and peak RSS.
# Usage: bench/segmented_rows_table.sh OLD_BUILD_DIR NEW_BUILD_DIR [ROUNDS (3)] [MIN_TIME (1)]
# OLD_ENV and NEW_ENV (environment, default empty): assignments each side runs with, e.g. one
# build against itself with OLD_ENV=HMFNET_SINCOS_ISA=avx2 (the vector kernels below AVX-512).
set -euo pipefail
old=$1 new=$2 rounds=${3:-3} min_time=${4:-1}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for n in 10000 1000000; do
    for which in old new; do
      build=$old side_env=${OLD_ENV:-}
      [ "$which" = new ] && build=$new side_env=${NEW_ENV:-}
      # shellcheck disable=SC2086  # the assignments are words
      /usr/bin/time -f "%M" -o "$out/rss_${which}_${n}_${round}" env $side_env "$build/bin/hmfnet_bench" \
        --benchmark_filter="^LeapFrogStep/$n/100/(1|2|8)/1/(0|1)/" \
        --benchmark_min_time="$min_time" --benchmark_format=json \
        >"$out/${which}_${n}_${round}.json" 2>/dev/null
    done
  done
done
python3 - "$out" "$rounds" <<'PY'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
def rates(which, n, r):
    runs = json.load(open(f"{out}/{which}_{n}_{r}.json"))["benchmarks"]
    return {tuple(int(a) for a in x["name"].split("/")[1:6]): x["nnz_steps_per_s"] for x in runs}
def rss(which, n):
    return max(int(open(f"{out}/rss_{which}_{n}_{r}").read().split()[-1]) for r in range(1, rounds + 1))
data = {(w, n, r): rates(w, n, r) for w in ("old", "new") for n in (10000, 1000000)
        for r in range(1, rounds + 1)}
med = lambda w, n, key: statistics.median(data[(w, n, r)][key] for r in range(1, rounds + 1))
print("%-8s %2s %-7s %8s %8s %9s %14s %9s %9s" % ("N", "B", "prec", "old", "new", "new/old",
      "rounds", "old/1e4", "new/1e4"))
for n in (10000, 1000000):
    for b in (1, 2, 8):
        for prec in (0, 1):
            key = (n, 100, b, 1, prec)
            if any(key not in data[(w, n, 1)] for w in ("old", "new")):
                print("%-8d %2d %-7s %8s" % (n, b, ("float64", "float32")[prec], "-"))
                continue
            ratios = [data[("new", n, r)][key] / data[("old", n, r)][key] for r in range(1, rounds + 1)]
            small = (10000, 100, b, 1, prec)
            print("%-8d %2d %-7s %8.3f %8.3f %8.2fx %14s %8.0f%% %8.0f%%" % (
                n, b, ("float64", "float32")[prec], med("old", n, key) / 1e9, med("new", n, key) / 1e9,
                statistics.median(ratios), "/".join("%.2f" % x for x in ratios),
                100 * med("old", n, key) / med("old", 10000, small),
                100 * med("new", n, key) / med("new", 10000, small)))
print("\npeak RSS (MB): N = 10^4 old %d new %d; N = 10^6 old %d new %d" % (
    rss("old", 10000) / 1024, rss("new", 10000) / 1024, rss("old", 1000000) / 1024,
    rss("new", 1000000) / 1024))
PY
