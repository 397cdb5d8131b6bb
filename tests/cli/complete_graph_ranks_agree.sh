#!/usr/bin/env bash
# The complete graph stored implicitly under MPI: `spectrum` and `theory` print the same JSON on
# 2 ranks as on 1 (closed forms and the one-node quotient: no rank-dependent arithmetic), and a
# `simulate` run on 2 ranks equals the 1-rank run to round-off. The rank-one force sums
# Z = sum_m e^{i theta_m} by blocks and reduces the two partial sums over the ranks, another order
# of the same terms; over the run's 2,000 steps the chaotic dynamics amplify the ~1e-16
# differences by at most e^(lambda_max T), lambda_max of order 1 per time unit, hence 1e-10
# relative (as simulate_ranks_agree.sh). With 8 replicas the steps run the rank-one force's fused
# pass (dynamics/rank_one_fused.hpp), each rank's rows offset into a.
# Usage: complete_graph_ranks_agree.sh HMFNET OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 out=$2/complete_graph_ranks mpiexec=$3
shift 3
rm -rf "$out"
mkdir -p "$out"
net="$out/k300.h5"
"$hmfnet" generate complete --n 300 -o "$net" 2>/dev/null
spectrum=("$hmfnet" spectrum "$net" --json --sigma0 0.35)
theory=("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 0.5,1.5,3 --json)
sim=("$hmfnet" simulate "$net" --seed 3 --K-over-Kc 0.5,2 --T 20 --transient 10 --threads 1
     --json --quiet)
one_s=$("${spectrum[@]}") two_s=$("$mpiexec" "$@" -np 2 "${spectrum[@]}")
one_t=$("${theory[@]}") two_t=$("$mpiexec" "$@" -np 2 "${theory[@]}")
one_m=$("${sim[@]}") two_m=$("$mpiexec" "$@" -np 2 "${sim[@]}")
one_8=$("${sim[@]}" --replicas 8) two_8=$("$mpiexec" "$@" -np 2 "${sim[@]}" --replicas 8)
python3 - "$one_s" "$two_s" "$one_t" "$two_t" "$one_m" "$two_m" "$one_8" "$two_8" <<'PY'
import json, sys
s1, s2, t1, t2, m1, m2, e1, e2 = (json.loads(x) for x in sys.argv[1:9])
for a, b in ((s1, s2), (t1, t2)):
    for run_fact in ("eigensolver_seconds", "ranks", "peak_rss_mb_per_rank"):
        a.pop(run_fact, None); b.pop(run_fact, None)
    assert a == b, (a, b)
for one, two in ((m1, m2), (e1, e2)):
    assert len(one["points"]) == len(two["points"]) == 2
    for a, b in zip(one["points"], two["points"]):
        assert abs(a["R_mean"] - b["R_mean"]) <= 1e-10 * abs(a["R_mean"]), (a, b)
print("K_300 on 2 ranks: spectrum and theory identical, <R>_t",
      [p["R_mean"] for p in m2["points"]], "vs", [p["R_mean"] for p in m1["points"]],
      "(8 replicas:", [p["R_mean"] for p in e2["points"]], "vs",
      [p["R_mean"] for p in e1["points"]], ")")
PY
