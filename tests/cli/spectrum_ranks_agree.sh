#!/usr/bin/env bash
# `hmfnet spectrum --json` on 1 rank and on 2 MPI ranks must agree: the same integers, and lambda
# and G to 1e-12 relative (the distributed product sums the same terms in another order; the
# eigen-residual tolerance is 1e-10, whose square bounds the eigenvalue error); with
# `--lambda2 bound` the same Lanczos steps and bounds on lambda_2 (to 1e-9 relative: round-off of
# the reductions, amplified over the steps of a Lanczos run without reorthogonalisation).
# Usage: spectrum_ranks_agree.sh HMFNET OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 out=$2 mpiexec=$3
shift 3
net="$out/ranks_er.h5"
"$hmfnet" generate er --n 3000 --mean-degree 20 --seed 5 -o "$net" 2>/dev/null
one=$("$hmfnet" spectrum "$net" --json)
two=$("$mpiexec" "$@" -np 2 "$hmfnet" spectrum "$net" --json)
one_b=$("$hmfnet" spectrum "$net" --json --lambda2 bound)
two_b=$("$mpiexec" "$@" -np 2 "$hmfnet" spectrum "$net" --json --lambda2 bound)
python3 - "$one" "$two" "$one_b" "$two_b" <<'PY'
import json, sys
a, b, ab, bb = (json.loads(x) for x in sys.argv[1:5])
assert "lambda2" not in ab and ab["lambda2_bound_steps"] == bb["lambda2_bound_steps"], (ab, bb)
lo, hi = ab["lambda2_bounds"]
assert lo <= a["lambda2"] * (1 + 1e-12) and hi >= a["lambda2"], (lo, hi, a["lambda2"])
for x, y in zip(ab["lambda2_bounds"], bb["lambda2_bounds"]):
    assert abs(x - y) <= 1e-9 * ab["lambda"], (ab["lambda2_bounds"], bb["lambda2_bounds"])
print("bounds on lambda_2, 1 rank", ab["lambda2_bounds"], "2 ranks", bb["lambda2_bounds"],
      "converged", a["lambda2"])
for key in ("n", "edges", "nnz", "self_loops", "components", "bipartite"):
    assert a[key] == b[key], (key, a[key], b[key])
for key in ("lambda", "lambda2", "G", "rho", "mean_degree"):
    rel = abs(a[key] - b[key]) / abs(a[key])
    print(f"{key}: 1 rank {a[key]!r}, 2 ranks {b[key]!r}, relative difference {rel:.2e}")
    assert rel <= 1e-12, key
print("1 and 2 ranks agree")
PY
