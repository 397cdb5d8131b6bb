#!/usr/bin/env bash
# The complete graph's rank-one step against numpy (docs/performance.md "The complete graph
# against numpy"): ns per rotor, replica and step of `hmfnet simulate` on K_N (no self-loops),
# 16 replicas, water-bag momenta, h = 0.1, K = 1.5 K_c, with --threads 1, --threads 2 and the
# default thread rule, against bench/rank_one_numpy.py's leap-frog of the same system. BEFORE,
# when given, is an hmfnet binary of an earlier commit, run alternately with AFTER in every
# round (rounds: 3; the table gives each one's median). integration_seconds / (steps N B).
# Every step of those runs is sampled (--transient 0: R formed at every step); numpy forms no
# observable, so the rows "-1-unsampled" (1 thread) run the same work as numpy: all but the last
# 20 steps in the transient, where no record reads the sums and the force forms g alone
# (coupling_force.hpp: ForceOutputs; 99.9% of the steps at N = 400, 90% at N = 10^5, whose T
# is doubled for them).
# Usage: bench/rank_one_table.sh AFTER_HMFNET [BEFORE_HMFNET]  (PYTHON: a python3 with numpy)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
after=$1
before=${2:-}
python=${PYTHON:-python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ns() {  # hmfnet, network, T, transient, extra args... -> "ns_per_cell_step threads"
  local bin=$1 net=$2 T=$3 transient=$4
  shift 4
  env -u OMP_WAIT_POLICY -u OMP_NUM_THREADS "$bin" simulate "$net" --replicas 16 \
    --momenta waterbag --h 0.1 --K-over-Kc 1.5 --T "$T" --transient "$transient" --seed 1 \
    --record-stride 1000000 --json --quiet "$@" |
    "$python" -c "import json,sys; d=json.load(sys.stdin); print(d['integration_seconds'] / (d['steps'] * d['n'] * 16) * 1e9, d['threads'])"
}

median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

lscpu | sed -n 's/^Model name: *//p'
printf "%-10s %-22s %10s %8s %14s\n" N run "ns/cell" threads "numpy / this"
# N, T (steps = T / h): ~10^8 rotor-replica steps per run.
for spec in "400 2000 2000" "100000 10 20"; do
  read -r n T T_unsampled <<<"$spec"
  net="$tmp/complete_$n.h5"
  "$after" generate complete --n "$n" -o "$net" >/dev/null
  steps=$("$python" -c "print(round($T / 0.1))")
  : >"$tmp/rows"
  for round in 1 2 3; do
    "$python" "$root/bench/rank_one_numpy.py" --n "$n" --replicas 16 --h 0.1 --steps "$steps" \
      --repeats 1 | "$python" -c "import json,sys; print('numpy', json.load(sys.stdin)['ns_per_rotor_replica_step'], 1)" >>"$tmp/rows"
    for label in before after; do
      bin=${!label}
      [[ -z $bin ]] && continue
      for threads in 1 2 default; do
        args=()
        [[ $threads != default ]] && args=(--threads "$threads")
        echo "$label-$threads $(ns "$bin" "$net" "$T" 0 "${args[@]}")" >>"$tmp/rows"
      done
      echo "$label-1-unsampled $(ns "$bin" "$net" "$T_unsampled" "$((T_unsampled - 2))" \
        --threads 1)" >>"$tmp/rows"
    done
  done
  numpy=$(awk '$1 == "numpy" {print $2}' "$tmp/rows" | median)
  for label in numpy before-1 before-2 before-default before-1-unsampled after-1 after-2 \
    after-default after-1-unsampled; do
    grep -q "^$label " "$tmp/rows" || continue
    m=$(awk -v l="$label" '$1 == l {print $2}' "$tmp/rows" | median)
    t=$(awk -v l="$label" '$1 == l {print $3}' "$tmp/rows" | tail -1)
    printf "%-10s %-22s %10.2f %8s %14.2f\n" "$n" "$label" "$m" "$t" \
      "$(awk -v a="$numpy" -v b="$m" 'BEGIN {print a / b}')"
  done
done
