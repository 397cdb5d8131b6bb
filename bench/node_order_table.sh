#!/usr/bin/env bash
# Node ordering as a lever for large N (issue #16 item 4): the force kernel's rate per stored
# entry at N = 10^6, degree 100, 1 thread, B = 1, float64 and float32, with the nodes as given,
# in reverse Cuthill-McKee order and by degree (`hmfnet convert --order rcm|degree`), on three
# networks: ER (no structure: no order can narrow its band), scale-free Chung-Lu alpha = 2.5 (hubs
# first puts the columns most rows read side by side) and a ring lattice of degree 100 with
# shuffled labels (locality that a network from elsewhere hides: RCM finds the ring again).
# Beside each rate: its ratio to the original order and to ER N = 10^4 (goal 4: >= 50%), and
# the band (max |i - j| over stored entries) after ordering. One run of every cell.
# Usage: bench/node_order_table.sh [BUILD_DIR (default build)] [N (default 1000000)] [D (100)]
set -euo pipefail
build=${1:-build}
n=${2:-1000000}
degree=${3:-100}
hmfnet="$build/bin/hmfnet"
python=${PYTHON:-/usr/bin/python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMP_NUM_THREADS=1

"$hmfnet" generate er --n 10000 --mean-degree "$degree" --seed 1 -o "$tmp/er-small.h5" 2>/dev/null
"$hmfnet" generate er --n "$n" --mean-degree "$degree" --seed 1 -o "$tmp/er.h5" 2>/dev/null
"$hmfnet" generate sf --n "$n" --alpha 2.5 --mean-degree "$degree" --seed 1 -o "$tmp/sf.h5" \
  2>/dev/null
# The ring lattice: node i linked to i +- 1 .. i +- D/2 (mod N), labels shuffled (seed 1).
PYTHONPATH="$build/python" "$python" - "$n" "$degree" "$tmp/ring.h5" <<'PY'
import sys
import numpy as np
import scipy.sparse as sp
import hmfnet
n, d, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
label = np.random.default_rng(1).permutation(n)
i = np.repeat(np.arange(n, dtype=np.int64), d)
offsets = np.concatenate([np.arange(1, d // 2 + 1), -np.arange(1, d // 2 + 1)])
j = (i + np.tile(offsets, n)) % n
A = sp.coo_matrix((np.ones(i.size), (label[i], label[j])), shape=(n, n))
hmfnet.Network.from_scipy(A).save(out)
PY

rate() {  # FILE PRECISION -> Gnnz*steps/s of 30 leap-frog steps
  "$hmfnet" simulate "$1" --K 1 --h 0.01 --T 0.3 --transient 0 --seed 1 --threads 1 \
    --force sparse --precision "$2" --json --quiet |
    "$python" -c "import json, sys; print(json.load(sys.stdin)['nnz_steps_per_second'] / 1e9)"
}

declare -A small
for precision in float64 float32; do small[$precision]=$(rate "$tmp/er-small.h5" "$precision"); done

printf '%-8s %-9s %-8s %9s %8s %8s %10s %9s\n' network order prec Gnnz/s /orig /N=1e4 band convert_s
for net in er sf ring; do
  for order in original rcm degree; do
    file="$tmp/$net.h5"
    band="-"
    seconds="-"
    if [ "$order" != original ]; then
      start=$(date +%s.%N)
      "$hmfnet" convert "$tmp/$net.h5" -o "$tmp/$net-$order.h5" --order "$order" \
        2> "$tmp/convert.log"
      seconds=$("$python" -c "print(f'{$(date +%s.%N) - $start:.1f}')")
      band=$(sed -n 's/.*bandwidth [0-9]* -> \([0-9]*\).*/\1/p' "$tmp/convert.log")
      file="$tmp/$net-$order.h5"
    fi
    for precision in float64 float32; do
      r=$(rate "$file" "$precision")
      [ "$order" = original ] && eval "orig_${net}_${precision}=$r"
      base=$(eval echo "\$orig_${net}_${precision}")
      printf '%-8s %-9s %-8s %9.3f %8.2f %7.0f%% %10s %9s\n' "$net" "$order" "$precision" "$r" \
        "$("$python" -c "print($r / $base)")" "$("$python" -c "print(100 * $r / ${small[$precision]})")" \
        "$band" "$seconds"
    done
  done
done
echo "ER N = 10^4, degree $degree, 1 thread: float64 ${small[float64]}, float32 ${small[float32]} Gnnz*steps/s"
