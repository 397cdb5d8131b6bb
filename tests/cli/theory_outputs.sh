#!/usr/bin/env bash
# `hmfnet theory --json` on a small ER network prints one JSON object with the promised keys:
# lambda, Kc, G, R_hat_iteration, R_hat_degree_approx, gamma (one entry per K above K_c) and
# points {K, K_over_Kc, R, sigma2, iterations, residual}; R = 0 below K_c, rising above, and
# R_hat between R(2 K_c) and 1. The text form names every K too.
# Usage: theory_outputs.sh HMFNET OUTDIR
set -euo pipefail
hmfnet=$1 out=$2
net="$out/theory_er.h5"
"$hmfnet" generate er --n 1000 --mean-degree 20 --seed 4 -o "$net" 2>/dev/null
json=$("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 0.5,1.05,2 --json)
python3 - "$json" <<'PY'
import json, math, sys
j = json.loads(sys.argv[1])
for key in ("lambda", "Kc", "G", "R_hat_iteration", "R_hat_degree_approx", "gamma", "points"):
    assert key in j, key
n = j["n"]
assert abs(j["Kc"] - 2 * 0.35**2 * n / j["lambda"]) <= 1e-12 * j["Kc"], "K_c = 2 sigma0^2 N / lambda"
points = j["points"]
assert len(points) == 3, points
for p in points:
    for key in ("K", "K_over_Kc", "R", "sigma2", "iterations", "residual"):
        assert key in p, key
assert points[0]["R"] == 0.0 and points[0]["status"] == "incoherent"
assert all(p["status"] == "converged" and p["residual"] <= 1e-10 for p in points[1:])
assert 0 < points[1]["R"] < points[2]["R"] < j["R_hat_iteration"] < 1
assert [round(g["K_over_Kc"], 9) for g in j["gamma"]] == [1.05, 2.0], j["gamma"]
assert all(g["gamma"] > 0 for g in j["gamma"])
print("theory --json: keys and values as promised:",
      {k: j[k] for k in ("lambda", "Kc", "G", "R_hat_iteration", "R_hat_degree_approx")})
PY
text=$("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 2)
grep -q "R_hat (K -> inf)" <<<"$text"
grep -q "converged" <<<"$text"
echo "theory text output: ok"
