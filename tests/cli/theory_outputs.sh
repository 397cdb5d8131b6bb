#!/usr/bin/env bash
# `hmfnet theory --json` on a small ER network prints one JSON object with the promised keys:
# lambda, Kc, G, R_hat_iteration, R_hat_degree_approx, gamma (one entry per K above K_c) and
# points {K, K_over_Kc, R, sigma2, iterations, residual}; R = 0 below K_c, rising above, and
# R_hat between R(2 K_c) and 1. The text form names every K too. With `--momenta waterbag`:
# K_c is the water-bag's linear threshold 6 sigma0^2 N / lambda = 3 Kc_equilibrium, gamma =
# sqrt(3) sigma0 sqrt(K / K_c - 1), and the equilibrium R is the Gaussian run's at the same K
# (it depends on g only through sigma0); points below K_c are marked linearly stable.
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
gauss=$("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 1,1.5,2.4 --json)
bag=$("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 0.5,0.8,1.2 --momenta waterbag --json)
python3 - "$gauss" "$bag" <<'PY'
import json, math, sys
g, w = (json.loads(x) for x in sys.argv[1:3])
assert g["momenta"] == "gaussian" and g["Kc"] == g["Kc_equilibrium"], (g["Kc"], g["Kc_equilibrium"])
assert w["momenta"] == "waterbag"
assert abs(w["Kc"] - 3 * w["Kc_equilibrium"]) <= 1e-12 * w["Kc"], (w["Kc"], w["Kc_equilibrium"])
assert [p["linearly_stable"] for p in w["points"]] == [True, True, False], w["points"]
# The same K (1.5 and 2.4 Kc_equilibrium) under both: the same equilibrium, to the solves'
# tolerance (relative residual 1e-10; the sweeps warm-start from different K).
for a, b in zip(g["points"][1:], w["points"][:2]):
    assert abs(a["K"] - b["K"]) <= 1e-12 * a["K"], (a["K"], b["K"])
    assert abs(a["R"] - b["R"]) <= 1e-8, (a["R"], b["R"])
[gw] = w["gamma"]
assert abs(gw["gamma"] - math.sqrt(3) * 0.35 * math.sqrt(1.2 - 1)) <= 1e-12, gw
print("theory --momenta waterbag: K_c = 3 Kc_equilibrium, gamma closed form, linear stability")
PY
text=$("$hmfnet" theory "$net" --sigma0 0.35 --K-over-Kc 2)
grep -q "R_hat (K -> inf)" <<<"$text"
grep -q "converged" <<<"$text"
echo "theory text output: ok"
