#!/usr/bin/env bash
# What a rank imports per force evaluation and what it computes, against the rank count P
# (docs/scaling.md): ER and scale-free (Chung-Lu, alpha = 2.5) networks of N
# nodes and mean degree D, generated to HDF5 and simulated for a short window at P = 1, 2, 4
# ranks (oversubscribed ranks are fine: the ghost counts and bytes do not depend on timing; the
# times do, so read them at P <= 2 on this 2-core machine only).
# Usage: bench/scaling_bytes.sh [BUILD_DIR (default build)] [N (default 100000)] [D (100)]
set -euo pipefail
build=${1:-build}
n=${2:-100000}
degree=${3:-100}
hmfnet="$build/bin/hmfnet"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$hmfnet" generate er --n "$n" --mean-degree "$degree" --seed 1 -o "$tmp/er.h5" 2>/dev/null
"$hmfnet" generate sf --n "$n" --alpha 2.5 --mean-degree "$degree" --seed 1 -o "$tmp/sf.h5" \
  2>/dev/null
printf '%-4s %2s %12s %14s %14s %12s %12s\n' net P "nnz/rank" "ghosts/rank" \
  "bytes/eval/rk" "ghosts/N" "ms/step"
for net in er sf; do
  for ranks in 1 2 4; do
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" -x OMP_NUM_THREADS=1 \
      "$hmfnet" simulate "$tmp/$net.h5" --seed 1 --K-over-Kc 2 --T 2 --transient 0 --json \
      --quiet | python3 -c "
import json, sys
j = json.loads(sys.stdin.read().strip().splitlines()[-1])
g, b, p = j['ghosts_per_rank'], j['bytes_imported_per_evaluation_per_rank'], j['ranks']
print('%-4s %2d %12.0f %14.0f %14.0f %12.3f %12.3f' % ('$net', p, j['nnz'] / p, max(g), max(b),
      max(g) / j['n'], 1e3 * j['integration_seconds'] / j['steps']))
"
  done
done
