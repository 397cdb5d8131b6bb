#!/usr/bin/env bash
# The default thread count against the best one (docs/performance.md): `hmfnet simulate` on ER
# networks from 500 to 10^7 stored entries and on complete graphs (the rank-one force: no stored
# entries, only rows) with 1 to 16 replicas, with --threads 1, --threads 2 and the default
# (src/dynamics/thread_choice.hpp), under OMP_WAIT_POLICY unset, ACTIVE and PASSIVE; all in one
# run so the ratios are comparable. Prints the integration loop's rate (work * steps per second,
# as the CLI reports it: stored entries x replicas for ER, rows x replicas for K_N; G/s), the
# rule's work per step (gathers + k_row_work per row, x replicas), the threads the default chose,
# and default / best.
# Run on an idle machine (all rows: ~25 min). Usage: bench/thread_rule.sh [BUILD_DIR (default
# build)] [NETWORKS: all (default), er or complete: only the ER or only the complete-graph rows]
set -euo pipefail
build=${1:-build}
networks=${2:-all}
case $networks in
  all | er | complete) ;;
  *)
    echo "bench/thread_rule.sh: NETWORKS is all, er or complete, not '$networks'" >&2
    exit 2
    ;;
esac
hmfnet="$build/bin/hmfnet"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

rate() {  # policy, network, T, extra args... -> "rate threads work"
  local policy=$1 net=$2 T=$3
  shift 3
  local env=(env -u OMP_WAIT_POLICY -u OMP_NUM_THREADS)
  [[ $policy != unset ]] && env+=(OMP_WAIT_POLICY="$policy")
  local out
  # A failed run stops the script with hmfnet's own message (rate runs in a process
  # substitution: its exit ends that subshell, and the caller's read then fails under set -e).
  if ! out=$("${env[@]}" "$hmfnet" simulate "$net" --K-over-Kc 1.5 --T "$T" --transient 0 \
    --h 0.01 --seed 1 --record-stride 1000000 --json --quiet "$@" 2>"$tmp/stderr"); then
    echo "bench/thread_rule.sh: hmfnet simulate $net $* (OMP_WAIT_POLICY $policy) failed:" >&2
    cat "$tmp/stderr" >&2
    exit 1
  fi
  python3 -c "import json,sys; d=json.load(sys.stdin); print(d['nnz_steps_per_second']/1e9, d['threads'], d.get('thread_rule_work', 0))" <<<"$out"
}

row() {  # label, network, T, extra args...
  local label=$1 net=$2 T=$3
  shift 3
  for policy in unset ACTIVE PASSIVE; do
    read -r one _ _ < <(rate "$policy" "$net" "$T" --threads 1 "$@")
    read -r two _ _ < <(rate "$policy" "$net" "$T" --threads 2 "$@")
    read -r def chosen work < <(rate "$policy" "$net" "$T" "$@")
    python3 -c "
one, two, d = $one, $two, $def
print('%-24s %-8s %10d %9.3f %9.3f %9.3f %8d %13.2f' % ('$label', '$policy', $work, one, two, d, $chosen, d / max(one, two)))"
  done
}

printf "%-24s %-8s %10s %9s %9s %9s %8s %13s\n" network policy "rule work" "1 thread" \
  "2 threads" default "chosen" "default/best"
# N, mean degree, T: about 2e9 stored entries x steps per run (less for the two smallest,
# whose rate is set by the per-step costs, not the entries).
er_specs=("100 5 4000" "300 10 4000" "1000 10 2000" "1000 100 200" "10000 10 200"
  "10000 100 20" "100000 20 10" "100000 100 2")
[[ $networks == complete ]] && er_specs=()
for spec in ${er_specs[@]+"${er_specs[@]}"}; do
  read -r n d T <<<"$spec"
  net="$tmp/er_${n}_${d}.h5"
  "$hmfnet" generate er --n "$n" --mean-degree "$d" --seed 1 -o "$net" 2>"$tmp/stderr" ||
    { cat "$tmp/stderr" >&2; exit 1; }
  row "ER N=$n d=$d" "$net" "$T"
done
# The complete graph (O(N) rank-one force): N, replicas, T; about 2e8 rows x replicas x steps
# (the QSS drivers' scenes: N = 200 .. 1600 with 16 replicas; N = 10^4 with one replica, which
# an earlier rule ran on one thread at 0.76x of two: docs/performance.md "Ordered sums side by
# side").
complete_specs=("100 1 20000" "200 16 600" "1600 16 80" "1000 1 2000" "10000 1 200"
  "20000 1 100" "100000 1 20")
[[ $networks == er ]] && complete_specs=()
for spec in ${complete_specs[@]+"${complete_specs[@]}"}; do
  read -r n b T <<<"$spec"
  net="$tmp/complete_${n}.h5"
  [[ -f $net ]] || "$hmfnet" generate complete --n "$n" -o "$net" 2>"$tmp/stderr" ||
    { cat "$tmp/stderr" >&2; exit 1; }
  row "K_N N=$n B=$b" "$net" "$T" --replicas "$b"
done
