#!/usr/bin/env bash
# `hmfnet theory --json` on 1 rank and on 2 MPI ranks must agree: the solvers run replicated on
# every rank with the products shared out (parallel/distributed_product.hpp, bit for bit equal
# to one rank's), so what differs comes only from lambda and u, which the eigensolver's
# distributed products sum in another order (lambda to ~1e-15 relative); R, sigma^2 and R_hat
# to 1e-12 relative (the solver tolerance is 1e-10: a larger difference would be a real one),
# the same iteration counts and statuses.
# Usage: theory_ranks_agree.sh HMFNET OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 out=$2 mpiexec=$3
shift 3
net="$out/theory_ranks_sf.h5"
"$hmfnet" generate sf --n 3000 --alpha 2.5 --mean-degree 20 --seed 7 -o "$net" 2>/dev/null
args=(theory "$net" --sigma0 1 --K-over-Kc 1.1,1.5,3 --json)
one=$("$hmfnet" "${args[@]}")
two=$("$mpiexec" "$@" -np 2 "$hmfnet" "${args[@]}")
python3 - "$one" "$two" <<'PY'
import json, sys
a, b = json.loads(sys.argv[1]), json.loads(sys.argv[2])
assert a["ranks"] == 1 and b["ranks"] == 2 and len(b["peak_rss_mb_per_rank"]) == 2
def close(x, y, what):
    rel = abs(x - y) / max(abs(x), 1e-300)
    print(f"{what}: 1 rank {x!r}, 2 ranks {y!r}, relative difference {rel:.2e}")
    assert rel <= 1e-12, what
for key in ("lambda", "Kc", "G", "R_hat_iteration"):
    close(a[key], b[key], key)
for p, q in zip(a["points"], b["points"]):
    assert p["status"] == q["status"] and p["iterations"] == q["iterations"], (p, q)
    close(p["R"], q["R"], "R at K/K_c = %.2f" % p["K_over_Kc"])
    close(p["sigma2"], q["sigma2"], "sigma2 at K/K_c = %.2f" % p["K_over_Kc"])
print("theory: 1 and 2 ranks agree")
PY
