#!/usr/bin/env bash
# The default thread count against the best one (docs/performance.md): `hmfnet simulate` on ER
# networks from 500 to 10^7 stored entries and on complete graphs (the rank-one force: no stored
# entries, only rows) with 1 to 16 replicas, with --threads 1, --threads 2 and the default
# (src/dynamics/thread_choice.hpp), under OMP_WAIT_POLICY unset, ACTIVE and PASSIVE; all in one
# run so the ratios are comparable. Prints the integration loop's rate (work * steps per second,
# as the CLI reports it: stored entries x replicas for ER, rows x replicas for K_N; G/s), the
# rule's work per step (gathers + k_row_work per row, x replicas), the threads the default chose,
# whether it chose them by timing its first steps (src/dynamics/step_trial.hpp; short runs and
# runs over several ranks keep the rule's count) and default / best; then one thread's step time
# (us), what a second thread adds to a step beyond half of it (us) and one thread's time per unit
# of the rule's work (ns).
# Run on an idle machine (all rows: ~15 min on the AMD EPYC, 25 on the Intel Xeon). Usage:
# bench/thread_rule.sh [BUILD_DIR (default build)] [NETWORKS: all (default), er or complete: only
# the ER or only the complete-graph rows]
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

rate() {  # policy, network, T, extra args... -> "rate threads work step_seconds tried"
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
  python3 -c "import json,sys; d=json.load(sys.stdin); print(d['nnz_steps_per_second']/1e9, d['threads'], d.get('thread_rule_work', 0), d['integration_seconds'] / d['steps'], 'yes' if '->' in d.get('thread_trial', '') else 'no')" <<<"$out"
}

row() {  # label, network, T, extra args...
  local label=$1 net=$2 T=$3
  shift 3
  for policy in unset ACTIVE PASSIVE; do
    read -r one _ _ t1 _ < <(rate "$policy" "$net" "$T" --threads 1 "$@")
    read -r two _ _ t2 _ < <(rate "$policy" "$net" "$T" --threads 2 "$@")
    read -r def chosen work _ tried < <(rate "$policy" "$net" "$T" "$@")
    # What the second thread adds to a step beyond half the work (its barriers and wakes),
    # t2 - t1 / 2, and one thread's time per unit of the rule's work, t1 / work: the rule's
    # threshold in units is the first over the second (docs/performance.md, "The thread rule
    # on the AMD EPYC").
    python3 -c "
one, two, d, t1, t2 = $one, $two, $def, $t1, $t2
print('%-24s %-8s %10d %9.3f %9.3f %9.3f %8d %5s %13.2f %9.1f %7.1f %8.2f' % ('$label', '$policy', $work, one, two, d, $chosen, '$tried', d / max(one, two), t1 * 1e6, (t2 - t1 / 2) * 1e6, t1 * 1e9 / max($work, 1)))"
  done
}

printf "%-24s %-8s %10s %9s %9s %9s %8s %5s %13s %9s %7s %8s\n" network policy "rule work" \
  "1 thread" "2 threads" default "chosen" "trial" "default/best" "step us" "+2nd us" "ns/unit"
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

# The cost of one barrier of a two-thread team under each policy (hmfnet_bench's TeamBarrier, the
# median of its repetitions): the part of "+2nd us" that no work hides.
bench="$build/bin/hmfnet_bench"
if [[ -x $bench ]]; then
  line="a two-thread barrier (TeamBarrier, median of 3):"
  for policy in unset ACTIVE PASSIVE; do
    env=(env -u OMP_WAIT_POLICY -u OMP_NUM_THREADS)
    [[ $policy != unset ]] && env+=(OMP_WAIT_POLICY="$policy")
    # A build older than TeamBarrier prints "?" (and the bench's messages) rather than ending
    # the script after its table.
    if ! us=$("${env[@]}" "$bench" --benchmark_filter='^TeamBarrier/' --benchmark_format=json \
      2>"$tmp/bench_stderr" | python3 -c "import json,sys; b=[x for x in json.load(sys.stdin)['benchmarks'] if x.get('aggregate_name') == 'median']; print('%.2f' % (b[0]['seconds_per_barrier'] * 1e6))"); then
      cat "$tmp/bench_stderr" >&2
      us="?"
    fi
    line+=" $policy $us us,"
  done
  echo "${line%,}"
else
  echo "(no $bench: the barrier costs need a build with -DHMFNET_BUILD_BENCH=ON)"
fi
