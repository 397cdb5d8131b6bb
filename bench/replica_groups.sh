#!/usr/bin/env bash
# Run-time replica counts (3, 5, 7, 16, 24 float64; 3, 7, 16 float32) of the sparse force, an
# older and a newer hmfnet alternated: `hmfnet simulate` on ER N = 2000 and 10^4, degree 100,
# 1 thread, ~4 10^9 entries x replicas a run. Prints seconds, G entries x replicas / s and peak
# RSS per run (docs/performance.md, "Run-time replica counts in groups").
#   bench/replica_groups.sh OLD_HMFNET NEW_HMFNET [ROUNDS]
set -euo pipefail
old=$1 new=$2 rounds=${3:-2}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for n in 2000 10000; do
  "$new" generate er --n $n --mean-degree 100 --seed 1 -o "$dir/er$n.h5" > /dev/null
done
printf '%-6s %-4s %-8s %-5s %-4s %9s %8s %7s\n' N B prec round bin seconds G/s rss_MB
for n in 2000 10000; do
  for cfg in "3 float64" "5 float64" "7 float64" "16 float64" "24 float64" "3 float32" \
             "7 float32" "16 float32"; do
    read -r b prec <<< "$cfg"
    steps=$((4000000000 / (n * 100 * b)))
    for r in $(seq "$rounds"); do
      for which in old new; do
        bin=$old
        [ "$which" = new ] && bin=$new
        "$bin" simulate "$dir/er$n.h5" --K-over-Kc 1.5 --replicas "$b" --precision "$prec" \
          --h 0.1 --T $((steps / 10)) --transient 0 --seed 1 --threads 1 --json --quiet \
          -o "$dir/out.h5" | /usr/bin/python3 -c '
import json, sys
w = json.load(sys.stdin)
n, b, prec, r, which = sys.argv[1:]
secs = w["integration_seconds"]
rate = w["nnz"] * int(b) * w["steps"] / secs / 1e9
print("%-6s %-4s %-8s %-5s %-4s %9.3f %8.3f %7.0f"
      % (n, b, prec, r, which, secs, rate, max(w["peak_rss_mb_per_rank"])))' \
          "$n" "$b" "$prec" "$r" "$which"
      done
    done
  done
done
