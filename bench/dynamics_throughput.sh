#!/usr/bin/env bash
# Throughput of `hmfnet simulate` (nnz * steps per second of the integration loop, as the CLI
# reports it) for 1 and 2 threads, 1 and 2 MPI ranks, B = 1, 4, 8 replicas and the float32
# kernel (1 thread), on the benchmark's networks, and a step's fixed cost on a small network; all
# in one run so the ratios are comparable. Run on an idle machine (OpenMP's
# default active waiting is the fast choice there). Throughput counts every replica's work.
# Usage: bench/dynamics_throughput.sh [BUILD_DIR (default build)] [--large]
#   --large adds ER N = 25,000, degree 5,000 (1.25e8 nnz; ~6 GB with the Tpetra copy).
set -euo pipefail
build=${1:-build}
hmfnet="$build/bin/hmfnet"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpi=(mpirun --allow-run-as-root --oversubscribe)

networks=("10000 100")
[[ "${2:-}" == "--large" ]] && networks+=("25000 5000")

measure() {  # label, command...
  local label=$1
  shift
  "$@" --json --quiet 2>/dev/null |
    python3 -c "import json,sys; d=json.load(sys.stdin); print(f\"%-34s %8.3f Gnnz*steps/s\" % ('$label', d['nnz_steps_per_second']/1e9))"
}

# A step's fixed cost (everything but the gathers: the schedule, the records, the force's
# preparation), on a network too small for the kernel to hide it: microseconds a step, 1 thread.
small="$tmp/er_1000_4.h5"
"$hmfnet" generate er --n 1000 --mean-degree 4 --seed 1 -o "$small" 2>/dev/null
"$hmfnet" simulate "$small" --K-over-Kc 1.5 --T 1000 --transient 0 --seed 1 --threads 1 \
  --record-stride 1000000 --json --quiet 2>/dev/null |
  python3 -c "import json,sys; d=json.load(sys.stdin); print('%-34s %8.2f us a step' % ('ER N = 1000, degree 4, 1 thread', d['integration_seconds'] / d['steps'] * 1e6))"

for spec in "${networks[@]}"; do
  read -r n d <<<"$spec"
  net="$tmp/er_${n}_${d}.h5"
  "$hmfnet" generate er --n "$n" --mean-degree "$d" --seed 1 -o "$net" 2>/dev/null
  steps_T=$([[ $n -gt 20000 ]] && echo 0.5 || echo 5)
  run=("$hmfnet" simulate "$net" --K-over-Kc 1.5 --T "$steps_T" --transient 0 --seed 1
       --record-stride 1000000)
  echo "ER N = $n, mean degree $d (T = $steps_T, h = 0.01)"
  for b in 1 4 8; do
    measure "1 rank, 1 thread, B = $b" "${run[@]}" --threads 1 --replicas "$b"
    measure "1 rank, 2 threads, B = $b" "${run[@]}" --threads 2 --replicas "$b"
    measure "2 ranks x 1 thread, B = $b" "${mpi[@]}" -np 2 "${run[@]}" --threads 1 --replicas "$b"
    measure "1 rank, 1 thread, B = $b, float32" "${run[@]}" --threads 1 --replicas "$b" \
      --precision float32
  done
done
