#!/usr/bin/env bash
# Peak resident memory per rank and wall time of `hmfnet generate er` (by rows over the ranks,
# into hmfnet HDF5), `hmfnet spectrum`, `hmfnet theory` (three K) and `hmfnet simulate` (20
# leap-frog steps) on ER
# N = 10^6, mean degree 100 (10^8 stored entries), read by row blocks, on 1 and 2 MPI ranks
# (docs/scaling.md, "Memory per rank"). Each rank reports its own peak
# (getrusage) in the JSON (`peak_rss_mb_per_rank`); the budget is summed over the ranks:
#   10 bytes per stored entry + 400 bytes per node + 250 MB per rank.
# The demonstration of item 5 (ER N = 10^7, degree 100: 10^9 stored entries, on 2 ranks) is
#   bench/scale_out_memory.sh build 10000000 100 2
# (~4 GB of HDF5 in TMPDIR, ~10 minutes here).
# Usage: bench/scale_out_memory.sh [BUILD_DIR (default build)] [N (default 1000000)] [DEGREE]
#        [RANK COUNTS (default "1 2")]
set -euo pipefail
build=${1:-build}
n=${2:-1000000}
degree=${3:-100}
rank_counts=${4:-1 2}
hmfnet="$build/bin/hmfnet"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
net="$tmp/er.h5"
report() {  # stage; JSON on stdin (for generate: its report line, turned into the same fields)
  python3 -c "
import json, re, sys
text = sys.stdin.read().strip().splitlines()[-1]
if '$1' == 'generate':
    m = re.search(r'N = (\d+), edges = (\d+).*peak memory per rank, MB: ([\d ]+)\)', text)
    j = {'n': int(m.group(1)), 'nnz': 2 * int(m.group(2)),
         'peak_rss_mb_per_rank': [float(x) for x in m.group(3).split()]}
else:
    j = json.loads(text)
peak = j['peak_rss_mb_per_rank']
nnz, n, ranks = j['nnz'], j['n'], len(peak)
budget = (10 * nnz + 400 * n) / 2**20 + 250 * ranks
print('%-9s %d rank(s): peak MB per rank %s, sum %.0f MB = %.2f bytes per stored entry '
      '(budget %.0f MB)' % ('$1', ranks, ' '.join('%.0f' % p for p in peak), sum(peak),
                           sum(peak) * 2**20 / nnz, budget))
"
}
for ranks in $rank_counts; do
  mpi=(mpirun --allow-run-as-root --oversubscribe -np "$ranks")
  start=$(date +%s.%N)
  "${mpi[@]}" "$hmfnet" generate er --n "$n" --mean-degree "$degree" --seed 1 -o "$net" 2>&1 |
    report generate
  echo "          wall $(echo "$(date +%s.%N) - $start" | bc) s"
  start=$(date +%s.%N)
  "${mpi[@]}" "$hmfnet" spectrum "$net" --json | report spectrum
  echo "          wall $(echo "$(date +%s.%N) - $start" | bc) s"
  start=$(date +%s.%N)
  "${mpi[@]}" "$hmfnet" theory "$net" --sigma0 1 --K-over-Kc 1.5,2,4 --json | report theory
  echo "          wall $(echo "$(date +%s.%N) - $start" | bc) s"
  start=$(date +%s.%N)
  "${mpi[@]}" "$hmfnet" simulate "$net" --seed 1 --K-over-Kc 2 --T 0.2 --transient 0 --json \
    --quiet | report simulate
  echo "          wall $(echo "$(date +%s.%N) - $start" | bc) s"
done
