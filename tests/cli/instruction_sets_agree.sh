#!/usr/bin/env bash
# The vectorised kernels keep their bits across instruction sets (src/dynamics/sincos.hpp,
# rank_one_force.cpp): `hmfnet simulate` on K_N without self-loops (N = 2500: two of the 2048-row
# blocks the sums are cut into) with 16 replicas (two whole AVX-512 or AVX2 groups) and 13 (one
# whole, one partial), on a rank-one network with unequal a_n (--force rank-one: an error, not
# the sparse force, should its structure go undetected), and on an ER network (9 replicas: a
# group of 8 and a single replica in the wide sets, the baseline loop's run-time width under
# HMFNET_SINCOS_ISA=baseline; 8 in float64 and 4 in float32: the wide row loops of
# dynamics/wide_rows.hpp in AVX-512 and AVX2, and the baseline loop under
# HMFNET_SINCOS_ISA=baseline; the rank-one
# network's weights through the sparse force at 8 float32 and 2 float64 replicas), gives the same
# --json points and results file under the widest set this CPU runs and under
# HMFNET_SINCOS_ISA=baseline and avx2. On a CPU without AVX-512 the widest is one of the others,
# and the comparison still holds.
# Usage: instruction_sets_agree.sh HMFNET OUTDIR
set -euo pipefail
hmfnet=$1 out=$2/instruction_sets
rm -rf "$out" && mkdir -p "$out"
"$hmfnet" generate complete --n 2500 -o "$out/k.h5" > /dev/null
"$hmfnet" generate er --n 3000 --mean-degree 20 --seed 2 -o "$out/er.h5" > /dev/null
# A = a a^T with a_n from 0.5 to 1.5 (the diagonal a_n^2 stored: weighted rank-one networks keep
# it, rank_one_force.hpp): K_N's a_n = 1 makes every product by a_n exact, so only this network
# tells a fused multiply-add in the sum of Z from the separate operations.
/usr/bin/python3 - "$out/rank_one.mtx" <<'PY'
import sys
n = 300
a = [0.5 + k / (n - 1) for k in range(n)]
with open(sys.argv[1], "w") as f:
    f.write("%%MatrixMarket matrix coordinate real symmetric\n")
    f.write(f"{n} {n} {n * (n + 1) // 2}\n")
    for i in range(n):
        for j in range(i + 1):
            f.write(f"{i + 1} {j + 1} {a[i] * a[j]!r}\n")
PY
for case in "k.h5 16 auto" "k.h5 13 auto" "er.h5 9 auto" "er.h5 8 auto" "er.h5 4 auto float32" \
  "rank_one.mtx 16 rank-one" "rank_one.mtx 8 sparse float32" "rank_one.mtx 2 sparse"; do
  read -r net replicas force precision <<< "$case"
  for isa in widest baseline avx2; do
    env_isa=()
    [ "$isa" = widest ] || env_isa=(HMFNET_SINCOS_ISA="$isa")
    env "${env_isa[@]}" "$hmfnet" simulate "$out/$net" --replicas "$replicas" --force "$force" --momenta waterbag \
      --precision "${precision:-float64}" \
      --K-over-Kc 1.5,3 --h 0.1 --T 60 --transient 10 --seed 4 --threads 2 --record-stride 7 \
      --json --quiet -o "$out/$isa.h5" > "$out/$isa.json"
  done
  /usr/bin/python3 - "$out" "$net $replicas" <<'PY'
import json, sys
import h5py
out, case = sys.argv[1], sys.argv[2]
runs = {isa: json.load(open(f"{out}/{isa}.json")) for isa in ("widest", "baseline", "avx2")}
for isa in ("baseline", "avx2"):
    assert runs[isa]["points"] == runs["widest"]["points"], (case, isa, "points differ")
    with h5py.File(f"{out}/widest.h5") as a, h5py.File(f"{out}/{isa}.h5") as b:
        for name in ("R", "energy", "momentum"):
            x, y = a["timeseries"][name][()], b["timeseries"][name][()]
            assert x.tobytes() == y.tobytes(), (case, isa, name, "time series differ")
print("instruction sets agree:", case)
PY
done
