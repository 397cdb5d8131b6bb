#!/usr/bin/env bash
# Determinism of whole `hmfnet simulate` runs (the same seed and parameters):
#   1. two runs on 1 rank, 1 thread: every dataset bit for bit equal;
#   2. 1 rank with 1 thread against 1 rank with 2 threads: bit for bit equal (the threaded force
#      and the reductions have a fixed order, independent of the thread count);
#   3. 1 rank against 2 MPI ranks: every integer equal, the floating-point data equal to
#      round-off. The distributed lambda, force and sums add the same terms in another order
#      (relative differences ~1e-16 per operation); over these 1,000 steps the chaotic dynamics
#      amplify them by at most e^(lambda_max T) with lambda_max of order 1 per time unit, so the
#      bound is 1e-10 relative (measured: 3e-15 for R and the energy). The energy error and
#      momentum drift, round-off-sized themselves, are compared absolutely (bound 1e-12).
# Usage: simulate_ranks_agree.sh HMFNET PYTHON OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 python=$2 out=$3 mpiexec=$4
shift 4
net="$out/ranks_sim_er.h5"
"$hmfnet" generate er --n 2000 --mean-degree 20 --seed 5 -o "$net" 2>/dev/null
run=("$hmfnet" simulate "$net" --K-over-Kc 0.5,2 --seed 3 --T 10 --transient 2 --quiet)
rm -f "$out"/ranks_sim_{a,b,c,d}.h5
OMP_NUM_THREADS=1 "${run[@]}" --threads 1 -o "$out/ranks_sim_a.h5"
OMP_NUM_THREADS=1 "${run[@]}" --threads 1 -o "$out/ranks_sim_b.h5"
OMP_NUM_THREADS=2 "${run[@]}" --threads 2 -o "$out/ranks_sim_c.h5"
OMP_NUM_THREADS=1 "$mpiexec" "$@" -np 2 "${run[@]}" --threads 1 -o "$out/ranks_sim_d.h5"
"$python" - "$out" <<'PY'
import sys
import h5py
import numpy as np

out = sys.argv[1]


def datasets(path):
    found = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: found.__setitem__(name, np.asarray(obj[()]))
                     if isinstance(obj, h5py.Dataset) else None)
    return found


a, b, c, d = (datasets(f"{out}/ranks_sim_{x}.h5") for x in "abcd")
assert a and set(a) == set(b) == set(c) == set(d), "the runs wrote different datasets"
failures = 0
for name, x in sorted(a.items()):
    for label, y in (("run again", b[name]), ("2 threads", c[name])):
        if x.shape != y.shape or not np.array_equal(x, y, equal_nan=x.dtype.kind == "f"):
            print(f"FAIL {name}: {label} differs from the first run (bit for bit expected)")
            failures += 1
    y = d[name]
    if x.dtype.kind != "f":
        ok = np.array_equal(x, y)
        detail = "equal" if ok else "integers differ"
    elif "error" in name or "drift" in name:
        # Relative energy error and momentum drift are themselves round-off-sized (1e-9 and
        # 1e-15): compare them in their own unit (relative to E and P), absolutely.
        diff = float(np.max(np.abs(x - y))) if x.size else 0.0
        ok = x.shape == y.shape and diff <= 1e-12
        detail = f"max |1 rank - 2 ranks| = {diff:.1e} (a relative error itself)"
    else:
        scale = max(np.max(np.abs(x)), 1e-300) if x.size else 1.0
        rel = float(np.max(np.abs(x - y)) / scale) if x.size else 0.0
        ok = x.shape == y.shape and rel <= 1e-10
        detail = f"max |1 rank - 2 ranks| / max|x| = {rel:.1e}"
    print(f"{name}: {detail}")
    failures += 0 if ok else 1
print(f"{len(a)} datasets compared: {failures} failures")
sys.exit(1 if failures else 0)
PY
