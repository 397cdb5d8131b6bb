#!/usr/bin/env bash
# The networks users start with: N = 1 (a self-loop), 2, 3 (path and triangle), 4 (path), the
# complete graphs K_2..K_4 stored implicitly, and Zachary's karate club. Every command that reads a
# network either works or refuses in one line (never a library's raw exception):
#  - spectrum's lambda and lambda_2 equal the dense eigenvalues that numpy computes from the same
#    file, to 1e-12 relative (spectral/perron.hpp solves networks this small densely; both
#    symmetric QR solvers are backward stable, so they differ by a few N eps lambda, below 1e-13
#    for N <= 34);
#  - theory and simulate answer (simulate's energy error below its tolerance);
#  - convert writes an HDF5 file whose spectrum is the same;
#  - rewire (one rank) either writes a network or refuses in one line.
# Usage: small_networks.sh HMFNET DATA_DIR OUTDIR [MPIRUN...]
set -euo pipefail
hmfnet=$1 data=$2 out=$3/small_networks
shift 3
launcher=("$@")  # e.g. mpirun -np 2: the same answers on two ranks
rm -rf "$out" && mkdir -p "$out"
python=/usr/bin/python3

mtx() {  # name n entries (pairs "i j", 1-based)
  local name=$1 n=$2
  shift 2
  { echo "%%MatrixMarket matrix coordinate pattern symmetric"; echo "$n $n $#"
    for e in "$@"; do echo "$e"; done; } > "$out/$name.mtx"
}
mtx one 1 "1 1"
mtx two 2 "2 1"
mtx path3 3 "2 1" "3 2"
mtx triangle 3 "2 1" "3 1" "3 2"
mtx path4 4 "2 1" "3 2" "4 3"
cp "$data/karate.mtx" "$out/karate.mtx"
for n in 2 3 4; do "$hmfnet" generate complete --n "$n" -o "$out/K$n.h5" 2> /dev/null; done

run() { "${launcher[@]}" "$hmfnet" "$@"; }

for name in one two path3 triangle path4 karate K2 K3 K4; do
  file="$out/$name.mtx"
  [[ -e "$file" ]] || file="$out/$name.h5"
  run spectrum "$file" --json > "$out/$name.spectrum.json"
  run theory "$file" --sigma0 0.35 --K-over-Kc 2 --json > "$out/$name.theory.json"
  run simulate "$file" --K-over-Kc 2 --seed 1 --T 10 --transient 1 --json --quiet \
    > "$out/$name.simulate.json"
  if [[ "$file" == *.mtx ]]; then
    run convert "$file" -o "$out/$name.h5" 2> /dev/null
    run spectrum "$out/$name.h5" --json > "$out/$name.converted.json"
    status=0
    # rewire works on the whole network on one rank: not run under the launcher.
    "$hmfnet" rewire "$file" --target-rho 1.1 --seed 1 --max-attempts 100 -o "$out/$name.rewired.mtx" \
      2> "$out/$name.rewire.err" || status=$?
    if [[ $status -ne 0 ]]; then
      [[ $status -lt 128 && $(wc -l < "$out/$name.rewire.err") -eq 1 ]] ||
        { echo "$name: rewire did not refuse in one line (exit $status):"; cat "$out/$name.rewire.err"; exit 1; }
    fi
  fi
  "$python" - "$out" "$name" <<'PY'
import json, sys
import numpy as np
out, name = sys.argv[1:3]
spectrum = json.load(open(f"{out}/{name}.spectrum.json"))
n = spectrum["n"]
if name.startswith("K"):
    A = np.ones((n, n)) - np.eye(n)
else:
    A = np.zeros((n, n))
    lines = [l for l in open(f"{out}/{name}.mtx") if not l.startswith("%")][1:]
    for line in lines:
        i, j = (int(x) - 1 for x in line.split())
        A[i, j] = A[j, i] = 1.0
eig = np.linalg.eigvalsh(A)
assert abs(spectrum["lambda"] - eig[-1]) <= 1e-12 * eig[-1], (name, spectrum["lambda"], eig[-1])
if n >= 2:
    assert abs(spectrum["lambda2"] - eig[-2]) <= 1e-12 * eig[-1], (name, spectrum["lambda2"], eig[-2])
theory = json.load(open(f"{out}/{name}.theory.json"))
assert theory["points"][0]["status"] == "converged", theory["points"]
sim = json.load(open(f"{out}/{name}.simulate.json"))
assert sim["n"] == n and sim["points"][0]["energy_rel_error_max"] < 1e-2, sim["points"]
try:
    converted = json.load(open(f"{out}/{name}.converted.json"))
    assert converted["lambda"] == spectrum["lambda"], (converted["lambda"], spectrum["lambda"])
except FileNotFoundError:
    pass
print(f"{name}: N = {n}, lambda = {spectrum['lambda']:.15g} (numpy {eig[-1]:.15g}), "
      f"R = {sim['points'][0]['R_mean']:.4f}")
PY
done
