#!/usr/bin/env bash
# Reproduce the near-onset remainder (docs/near_onset.md): at full scale (near_onset_gap, T = 10^4)
# ER with degree 100 at 1.5 K_c stops moving by t ~ 4000 at 2.4-2.8% below eq:rSigmaBesselMain,
# at every N. Is that remainder the theory's own error on a sparse network (eq:bkApprox, which
# should shrink with the degree, like 1 / d if it is the first correction) or a lag set by the
# degree (the QSS lives longer at larger d: qss_networks)? This runs the same scene at three
# degrees and compares <R>_t per window with the theory at each replica's own conserved energy
# and momentum (mu0 = 2E/N - (P/N)^2, as docs/scripts/er_long_window.sh does).
#
# Usage: docs/scripts/er_degree_remainder.sh HMFNET_BINARY   (KEEP=1 keeps the temporary folder)
# Scene: ER N = 3000 (seed 1), mean degree 30, 100, 300; Gaussian momenta, sigma0 = 0.34641016
# (sqrt(0.12) to 8 digits), K = 1.5 K_c from the incoherent start, T = 10^4, leap-frog h = 0.16
# (near_onset_gap's method), 8 replicas (seeds 1-8). Printed per degree: <R>_t over
# [2000, 4000), [4000, 6000), [6000, 8000), [8000, 10000), the theory, the gap and gap x d (a
# constant gap x d over the degrees, flat in time, says a 1 / d error of the theory; a gap that
# still shrinks with time says a lag). About 4 min at 2 threads. Output (defaults;
# docs/near_onset.md): gap over the four windows, d = 30: -0.0244, -0.0222, -0.0239, -0.0235;
# d = 100: -0.0151, -0.0134, -0.0137, -0.0093; d = 300: -0.0260, -0.0152, -0.0088, -0.0085
# (se 0.0010-0.0036): not 1 / d (gap x d -0.70 against -2.55), closer to 1 / sqrt(d).
# Needs python3 with h5py and numpy (Debian's /usr/bin/python3, ci/install-deps.sh).
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
script_binary "$0 HMFNET_BINARY" "${1:-}"

script_tmp er_degree_remainder

for d in 30 100 300; do
  "$HMF" generate er --n 3000 --mean-degree "$d" --seed 1 -o "$TMP/er$d.h5" >&2
  "$HMF" simulate "$TMP/er$d.h5" --sigma0 0.34641016 --K-over-Kc 1.5 --T 10000 --transient 0 \
    --h 0.16 --seed 1 --replicas 8 --record-stride 25 --quiet --json -o "$TMP/run$d.h5" \
    > "$TMP/run$d.json"
done

"$PY" - "$HMF" "$TMP" <<'PYEOF'
import json, subprocess, sys
import h5py, numpy as np

hmf, folder = sys.argv[1], sys.argv[2]
windows = [(2000, 4000), (4000, 6000), (6000, 8000), (8000, 10000)]
print("| d | window | <R>_t (mean of replicas) | theory at each replica's (E, P) | gap | gap x d |")
print("|---|---|---|---|---|---|")
for d in (30, 100, 300):
    with h5py.File(f"{folder}/run{d}.h5", "r") as f:
        t, K = f["timeseries/t"][:], f["timeseries/K"][:]
        R, E, P = f["timeseries/R"][:], f["timeseries/energy"][:], f["timeseries/momentum"][:]
    run = json.load(open(f"{folder}/run{d}.json"))
    n, mean_degree = run["n"], run.get("mean_degree", d)
    k = float(np.unique(K)[0])
    mu0 = 2.0 * E[-1] / n - (P[-1] / n) ** 2  # per replica
    theory = []
    for s in np.sqrt(mu0):
        out = subprocess.run([hmf, "theory", f"{folder}/er{d}.h5", "--sigma0", repr(float(s)), "--K",
                              repr(k), "--json"], check=True, capture_output=True, text=True)
        theory.append(json.loads(out.stdout)["points"][0]["R"])
    theory = np.array(theory)
    for a, b in windows:
        w = (t >= a) & (t < b)
        gap = R[w].mean(axis=0) - theory
        se = gap.std(ddof=1) / np.sqrt(len(gap))
        print(f"| {d} | [{a}, {b}) | {R[w].mean():.4f} | {theory.mean():.4f} | "
              f"{gap.mean():+.4f} +- {se:.4f} | {gap.mean() * d:+.2f} +- {se * d:.2f} |")
PYEOF
