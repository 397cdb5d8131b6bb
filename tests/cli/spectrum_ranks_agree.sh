#!/usr/bin/env bash
# `hmfnet spectrum --json` on 1 rank and on 2 MPI ranks must agree: the same integers, and lambda
# and G to 1e-12 relative (the distributed product sums the same terms in another order; the
# eigen-residual tolerance is 1e-10, whose square bounds the eigenvalue error).
# Usage: spectrum_ranks_agree.sh HMFNET OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 out=$2 mpiexec=$3
shift 3
net="$out/ranks_er.h5"
"$hmfnet" generate er --n 3000 --mean-degree 20 --seed 5 -o "$net" 2>/dev/null
one=$("$hmfnet" spectrum "$net" --json)
two=$("$mpiexec" "$@" -np 2 "$hmfnet" spectrum "$net" --json)
python3 - "$one" "$two" <<'PY'
import json, sys
a, b = json.loads(sys.argv[1]), json.loads(sys.argv[2])
for key in ("n", "edges", "nnz", "self_loops", "components", "bipartite"):
    assert a[key] == b[key], (key, a[key], b[key])
for key in ("lambda", "lambda2", "G", "rho", "mean_degree"):
    rel = abs(a[key] - b[key]) / abs(a[key])
    print(f"{key}: 1 rank {a[key]!r}, 2 ranks {b[key]!r}, relative difference {rel:.2e}")
    assert rel <= 1e-12, key
print("1 and 2 ranks agree")
PY
