#!/usr/bin/env bash
# Reproduce the table "Scale-free onset and the leap-frog step" in docs/choosing_a_method.md:
# does leap-frog's step bias <R>_t near the onset on a scale-free network (the scene behind the
# scale-free rule of verification/support/pipeline_step.hpp)?
#
# Usage: docs/scripts/sf_step_near_onset.sh HMFNET_BINARY [STEPS (default "0.32 0.16")]
#   REPLICAS (default 48, at most 64) and SEED (default 101: replicas SEED..SEED+REPLICAS-1);
#   KEEP=1 keeps the temporary folder with the runs' JSON. The steps run concurrently, one
#   thread each.
# The scene of Fig. 1c-d: capped Chung-Lu, alpha = 2.8, N = 10^4, <d> = 100, targets capped at
# N - 1 (`hmfnet generate sf`, seed 2: lambda = 266.2; the alpha 2.8 network of
# verification/onset_er_sf.cpp comes from another generator call and has lambda = 264.1),
# sigma0 = 0.35, Omega = 6,
# K raised through x = K / K_c = 0, 0.5, 0.9, 1.1, 1.2, 1.35, 1.5, 2 with T2 = 300, T1 = 150 per K
# (the full-scale onset sweep's segment). Each step is rounded down to whole steps per T1 (as
# pipeline_step.hpp does). Prints <R>_t +- its replica standard error per x and step, and each
# step's difference from the smallest one. The test statistic is one number per replica: its
# <R>_t averaged over the near-onset points x = 1.1-1.5 (the onset fit's window); a replica's
# points are correlated (the state carries over), so per-x t values would overstate the
# evidence. Needs python3 (standard library).
# Cost per replica on one core: ~8 s at h = 0.32, 16 s at 0.16, 65 s at 0.04 (0.01: ~260 s).
# Output (defaults; docs/choosing_a_method.md): window x = 1.1-1.5 0.1632 +- 0.0014
# at h = 0.32 against 0.1642 +- 0.0016 at 0.16, difference -0.0010 +- 0.0022.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
script_binary "$0 HMFNET_BINARY [STEPS]" "${1:-}"
STEPS=${2:-"0.32 0.16"}
REPLICAS=${REPLICAS:-48}
SEED=${SEED:-101}

script_tmp sf_step_near_onset

"$HMF" generate sf --n 10000 --alpha 2.8 --mean-degree 100 --cutoff 9999 --seed 2 \
  -o "$TMP/sf.h5" >&2
pids=()
for h in $STEPS; do
  # Round down so that T1 = 150 is a whole number of steps (verification/support/pipeline_step.hpp).
  hw=$(python3 -c "import math; print(150 / math.ceil(150 / $h - 1e-9))")
  echo "# h = $h (used $hw), replicas $SEED..$((SEED + REPLICAS - 1))" >&2
  "$HMF" simulate "$TMP/sf.h5" --K-over-Kc 0,0.5,0.9,1.1,1.2,1.35,1.5,2 --T 300 --transient 150 \
    --h "$hw" --seed "$SEED" --replicas "$REPLICAS" --threads 1 --quiet --json \
    > "$TMP/h$h.json" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done  # set -e: a failed run stops the script

python3 - "$TMP" $STEPS <<'PY'
import json, math, statistics, sys
folder, steps = sys.argv[1], sys.argv[2:]
runs = {h: json.load(open(f"{folder}/h{h}.json"))["points"] for h in steps}
ref = min(steps, key=float)

def stats(point):
    r = point["R_mean_replicas"]
    return statistics.mean(r), statistics.stdev(r) / math.sqrt(len(r)), r

print("| x | " + " | ".join(f"h = {h}" for h in steps) + " |")
print("|---" * (len(steps) + 1) + "|")
for i, p in enumerate(runs[ref]):
    cells = [f"{m:.4f} +- {se:.4f}" for m, se, _ in (stats(runs[h][i]) for h in steps)]
    print(f"| {p['K_over_Kc']:.2f} | " + " | ".join(cells) + " |")
print(f"\nDifference from h = {ref} at each x, and of the per-replica mean over x = 1.1-1.5:")

def window(points):
    sel = [p for p in points if 1.05 < p["K_over_Kc"] < 1.55]
    B = len(sel[0]["R_mean_replicas"])
    w = [statistics.mean(p["R_mean_replicas"][b] for p in sel) for b in range(B)]
    return statistics.mean(w), statistics.stdev(w) / math.sqrt(B)

w0, s0 = window(runs[ref])
for h in steps:
    if h == ref:
        continue
    row = []
    for i, p in enumerate(runs[ref]):
        row.append(f"x {p['K_over_Kc']:.2f}: {stats(runs[h][i])[0] - stats(p)[0]:+.4f}")
    w, s = window(runs[h])
    print(f"h = {h}: " + "; ".join(row))
    d, sd = w - w0, math.hypot(s, s0)
    print(f"  window x = 1.1-1.5: {w:.4f} +- {s:.4f} against {w0:.4f} +- {s0:.4f}: "
          f"difference {d:+.4f} +- {sd:.4f} (t = {d / sd:+.1f})")
PY
