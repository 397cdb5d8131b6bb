#!/usr/bin/env bash
# `hmfnet generate complete`: K_N stored in O(1) space and read by spectrum, theory and simulate,
# which give what the same graph stored as rows (a Matrix Market file written here) gives:
# lambda to 1e-12, theory R and sigma^2 to 1e-12 (both solved to a residual of 1e-13), and a short
# simulation's <R>_t to 1e-12 (the stored graph's rank-one force, found by detect_rank_one, is the
# implicit graph's force on the same rows: the same bits; the sparse kernel sums the same terms
# in another order). Then N = 10^6 (10^12 stored entries) in a file of a few kB, its spectrum and
# theory exact, and a short simulation; and the refusals: --force sparse, float32, rewire.
# Usage: complete_graph.sh HMFNET OUTDIR
set -euo pipefail
hmfnet=$1 out=$2/complete_graph
rm -rf "$out"
mkdir -p "$out"

"$hmfnet" generate complete --n 300 -o "$out/k300.h5" 2>/dev/null
python3 - "$out/k300.mtx" <<'PY'
import sys
n = 300
with open(sys.argv[1], "w") as f:
    f.write("%%%%MatrixMarket matrix coordinate pattern symmetric\n%d %d %d\n" % (n, n, n * (n - 1) // 2))
    for i in range(n):
        for j in range(i + 1, n):
            f.write("%d %d\n" % (j + 1, i + 1))
PY

theory_args=(--sigma0 0.35 --K-over-Kc 0.5,1.2,1.5,3 --tolerance 1e-13 --json)
# K itself, not K / K_c: the stored graph's lambda comes from the eigensolver (299 to round-off),
# and the claim is that the two forces give the same run at the same K, bit for bit.
sim_args=(--seed 3 --K 0.1229,0.4916 --T 20 --transient 10 --threads 1 --json --quiet)
python3 - "$("$hmfnet" spectrum "$out/k300.h5" --json)" "$("$hmfnet" spectrum "$out/k300.mtx" --json)" \
  "$("$hmfnet" theory "$out/k300.h5" "${theory_args[@]}")" \
  "$("$hmfnet" theory "$out/k300.mtx" "${theory_args[@]}")" \
  "$("$hmfnet" simulate "$out/k300.h5" "${sim_args[@]}")" \
  "$("$hmfnet" simulate "$out/k300.mtx" "${sim_args[@]}")" \
  "$("$hmfnet" simulate "$out/k300.mtx" "${sim_args[@]}" --force sparse)" <<'PY'
import json, sys
si, ss, ti, ts, mi, ms, mp = (json.loads(x) for x in sys.argv[1:8])
rel = lambda a, b: abs(a - b) / abs(b)
for key in ("n", "edges", "nnz", "self_loops", "components", "bipartite", "mean_degree", "warnings"):
    assert si[key] == ss[key], (key, si[key], ss[key])
assert si["lambda"] == 299.0 and rel(si["lambda"], ss["lambda"]) <= 1e-12, (si["lambda"], ss["lambda"])
assert rel(si["G"], ss["G"]) <= 1e-12 and rel(si["rho"], ss["rho"]) <= 1e-12
assert ti["lambda"] == 299.0 and rel(ti["Kc"], ts["Kc"]) <= 1e-12
assert len(ti["points"]) == len(ts["points"]) == 4
assert len(mi["points"]) == len(ms["points"]) == len(mp["points"]) == 2
for a, b in zip(ti["points"], ts["points"]):
    assert a["status"] == b["status"], (a, b)
    if b["status"] == "converged":
        assert rel(a["R"], b["R"]) <= 1e-12 and rel(a["sigma2"], b["sigma2"]) <= 1e-12, (a, b)
assert rel(ti["R_hat_iteration"], ts["R_hat_iteration"]) <= 1e-12
assert mi["force"] == "rank-one" and ms["force"] == "rank-one" and mp["force"] == "sparse"
assert mi["nnz"] == ms["nnz"] == 89700
for a, b, c in zip(mi["points"], ms["points"], mp["points"]):
    assert a["R_mean"] == b["R_mean"], (a, b)
    assert abs(a["R_mean"] - c["R_mean"]) <= 1e-12, (a, c)
print("K_300 implicit = stored: lambda %.17g, theory R %s, simulated <R> %s"
      % (si["lambda"], [p["R"] for p in ti["points"]], [p["R_mean"] for p in mi["points"]]))
PY

# N = 10^6: the file holds no rows; the spectrum and theory are exact and instant; a run of
# 0.3 time units (30 steps) integrates all 10^6 rotors.
"$hmfnet" generate complete --n 1000000 --self-loops -o "$out/k1e6.h5" 2>/dev/null
size=$(stat -c %s "$out/k1e6.h5")
[ "$size" -lt 16384 ] || { echo "K_10^6 file is $size bytes, not O(1)" >&2; exit 1; }
python3 - "$("$hmfnet" spectrum "$out/k1e6.h5" --json)" \
  "$("$hmfnet" theory "$out/k1e6.h5" --sigma0 0.35 --K-over-Kc 2 --json)" \
  "$("$hmfnet" simulate "$out/k1e6.h5" --seed 1 --K-over-Kc 2 --T 0.3 --transient 0.1 --h 0.01 \
       --json --quiet)" "$size" <<'PY'
import json, sys
s, t, m = (json.loads(x) for x in sys.argv[1:4])
assert s["n"] == 10**6 and s["lambda"] == 1e6 and s["nnz"] == 10**12 and s["self_loops"] == 10**6
assert t["lambda"] == 1e6 and t["points"][0]["status"] == "converged"
assert m["n"] == 10**6 and m["force"] == "rank-one" and m["steps"] == 30, m
p = m["points"][0]
assert 0 < p["R_mean"] < 0.01 and p["energy_rel_error_max"] < 1e-10, p
print("K_10^6: %d-byte file, lambda %g, theory R(2 K_c) %.6f, 30 steps <R> %.2e"
      % (int(sys.argv[4]), s["lambda"], t["points"][0]["R"], p["R_mean"]))
PY

# The largest N: spectrum and theory stay O(1) (no vector of N entries anywhere).
"$hmfnet" generate complete --n 2147483647 -o "$out/kmax.h5" 2>/dev/null
python3 - "$("$hmfnet" spectrum "$out/kmax.h5" --json)" \
  "$("$hmfnet" theory "$out/kmax.h5" --sigma0 0.35 --K-over-Kc 3 --json)" <<'PY'
import json, sys
s, t = (json.loads(x) for x in sys.argv[1:3])
assert s["n"] == 2**31 - 1 and s["lambda"] == 2**31 - 2 and s["nnz"] == (2**31 - 1) * (2**31 - 2)
assert "second_mode_ratio" in s and s["lambda2"] == -1.0
assert t["points"][0]["status"] == "converged"
print("K_(2^31-1): spectrum and theory in O(1)")
PY

# Refusals: no rows for the sparse kernel, float32 or rewiring; nothing written.
expect_refusal() {
  local text=$1; shift
  if "$@" > "$out/refused.out" 2> "$out/refused.err"; then
    echo "accepted: $*" >&2; exit 1
  fi
  grep -qF -- "$text" "$out/refused.err" || { cat "$out/refused.err" >&2; exit 1; }
}
expect_refusal "--force: sparse on the complete graph stored implicitly" \
  "$hmfnet" simulate "$out/k300.h5" --seed 1 --K 1 --T 1 --transient 0 --force sparse
expect_refusal "--precision: float32 on the complete graph stored implicitly" \
  "$hmfnet" simulate "$out/k300.h5" --seed 1 --K 1 --T 1 --transient 0 --precision float32
expect_refusal "the complete graph of 300 nodes is stored implicitly, not as rows" \
  "$hmfnet" rewire "$out/k300.h5" --target-rho 1.1 --seed 1 -o "$out/rewired.h5"
[ ! -e "$out/rewired.h5" ] || { echo "rewire left a file" >&2; exit 1; }
echo "complete graph: refusals as promised"
