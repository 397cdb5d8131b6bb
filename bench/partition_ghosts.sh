#!/usr/bin/env bash
# What a graph partition (Zoltan2, `hmfnet convert --partition P`) buys per step
# (docs/scaling.md): ghosts per rank, bytes imported per force evaluation and ms per step, with and
# without it, on a two-block SBM whose node labels were shuffled (as a network from elsewhere
# comes: its rows as given cut the blocks at random) and on ER (where no partition can help).
# The SBM as generated (blocks in label order) is the ideal reference. Ghosts and bytes at
# P = 2 and 4 ranks (oversubscribed ranks are fine for counting), times at P = 2 only (2 cores).
# A rank's ghosts are the distinct far ends of its cut entries: with the blocks on their own
# ranks (P = 2) each node has ~C neighbours in the other block, which cover a fraction 1 - e^-C
# of it, so ghosts ~ (N/2)(1 - e^-C): the partition pays only for C below ~1.
# Usage: bench/partition_ghosts.sh [BUILD_DIR (default build)] [HALF (default 50000)]
#        [D inside (default 100)] [C across (default 0.5)]
set -euo pipefail
build=${1:-build}
half=${2:-50000}
degree=${3:-100}
across=${4:-0.5}
hmfnet="$build/bin/hmfnet"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=$((2 * half))
mpi=(mpirun --allow-run-as-root --oversubscribe -x OMP_NUM_THREADS=1)
p_in=$(python3 -c "print($degree / ($half - 1))")
p_out=$(python3 -c "print($across / $half)")
"$hmfnet" generate sbm --half "$half" --p-in "$p_in" --p-out "$p_out" --seed 1 \
  -o "$tmp/sbm.h5" 2>/dev/null
"$hmfnet" generate er --n "$n" --mean-degree "$(python3 -c "print($degree + $across)")" --seed 1 \
  -o "$tmp/er.h5" 2>/dev/null
# Shuffle the SBM's labels (seeded) into an edge list, then read it back in parallel.
"${PYTHON:-/usr/bin/python3}" - "$tmp" <<'PY'
import sys
import h5py
import numpy as np
d = sys.argv[1]
with h5py.File(f"{d}/sbm.h5", "r") as f:
    row_ptr, col = f["network/row_ptr"][()], f["network/col"][()]
n = len(row_ptr) - 1
perm = np.random.default_rng(7).permutation(n)
rows = np.repeat(np.arange(n), np.diff(row_ptr))
upper = rows < col
edges = np.column_stack([perm[rows[upper]], perm[col[upper]]])
with open(f"{d}/sbm_shuffled.txt", "w") as out:
    out.write(f"# nodes {n}\n")
    np.savetxt(out, edges, fmt="%d")
PY
"${mpi[@]}" -np 2 "$hmfnet" convert "$tmp/sbm_shuffled.txt" -o "$tmp/sbm_shuffled.h5" 2>/dev/null
for ranks in 2 4; do
  for net in sbm_shuffled er; do
    "${mpi[@]}" -np "$ranks" "$hmfnet" convert "$tmp/$net.h5" --partition "$ranks" \
      -o "$tmp/${net}_part$ranks.h5" 2>&1 | grep partition | sed "s/^/$net, $ranks ranks: /"
  done
done
printf '%-22s %2s %12s %14s %14s %10s %10s\n' network P "nnz/rank" "ghosts/rank" \
  "bytes/eval/rk" "ghosts/N" "ms/step"
for ranks in 2 4; do
  for net in sbm sbm_shuffled "sbm_shuffled_part$ranks" er "er_part$ranks"; do
    "${mpi[@]}" -np "$ranks" "$hmfnet" simulate "$tmp/$net.h5" --seed 1 --K-over-Kc 2 --T 2 \
      --transient 0 --json --quiet | python3 -c "
import json, sys
j = json.loads(sys.stdin.read().strip().splitlines()[-1])
g, b, p = j['ghosts_per_rank'], j['bytes_imported_per_evaluation_per_rank'], j['ranks']
ms = '%10.3f' % (1e3 * j['integration_seconds'] / j['steps']) if p <= 2 else '%10s' % '-'
print('%-22s %2d %12.0f %14.0f %14.0f %10.3f %s' % ('$net', p, j['nnz'] / p, max(g), max(b),
      max(g) / j['n'], ms))
"
  done
done
