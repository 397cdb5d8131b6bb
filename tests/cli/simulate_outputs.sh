#!/usr/bin/env bash
# `hmfnet simulate --json -o OUT.h5` prints the promised keys and writes a results file;
# `--resume` with no checkpoint present starts from the beginning and gives the same numbers;
# `--precision float32` runs the float32 sparse kernel (named in the output) and is refused
# with `--force rank-one` (that path has no float32 variant); `--K-across-replicas` gives the
# numbers of `--restart-each-K` (one pass for every K) and is refused with `--node-data`;
# `--momenta waterbag` reports K_c = 6 sigma0^2 N / lambda, three times the Gaussian's.
# `--device cuda` gives the CPU's numbers bit for bit where a CUDA device runs it (--json prints
# doubles to round-trip precision), and elsewhere is refused in one line naming why.
# Usage: simulate_outputs.sh HMFNET NETWORK OUTDIR
set -euo pipefail
hmfnet=$1 net=$2 out=$3
rm -f "$out/sim.h5" "$out/sim.ckpt.h5"
args=(simulate "$net" --K-sweep 0:40:20 --h 0.02 --T 4 --transient 1 --seed 7 --json --quiet)
plain=$("$hmfnet" "${args[@]}" -o "$out/sim.h5")
resumed=$("$hmfnet" "${args[@]}" --checkpoint "$out/sim.ckpt.h5" --resume)
single=$("$hmfnet" "${args[@]}" --precision float32)
waterbag=$("$hmfnet" "${args[@]}" --momenta waterbag)
restart=$("$hmfnet" "${args[@]}" --replicas 2 --restart-each-K)
across=$("$hmfnet" "${args[@]}" --replicas 2 --K-across-replicas)
if "$hmfnet" "${args[@]}" --K-across-replicas --node-data 2> "$out/refusal.txt"; then
  echo "--K-across-replicas --node-data was accepted"; exit 1
fi
grep -q "K across replicas (--K-across-replicas): with node_data (--node-data)" "$out/refusal.txt" \
  || { echo "unexpected refusal: $(cat "$out/refusal.txt")"; exit 1; }
if "$hmfnet" "${args[@]}" --precision float32 --force rank-one 2> "$out/refusal.txt"; then
  echo "--precision float32 --force rank-one was accepted"; exit 1
fi
grep -q -- "--precision: float32 (allowed: only for the sparse force" "$out/refusal.txt" \
  || { echo "unexpected refusal: $(cat "$out/refusal.txt")"; exit 1; }
if device=$("$hmfnet" "${args[@]}" --replicas 2 --integrator yoshida4 --device cuda \
    2> "$out/refusal.txt"); then
  echo "a CUDA device ran it: comparing with the CPU"
  cpu=$("$hmfnet" "${args[@]}" --replicas 2 --integrator yoshida4 --device cpu)
else
  grep -q -- "^hmfnet: error: --device cuda: .*; run it with --device cpu" "$out/refusal.txt" \
    || { echo "unexpected refusal: $(cat "$out/refusal.txt")"; exit 1; }
  test "$(wc -l < "$out/refusal.txt")" -eq 1 || { echo "refusal not one line"; exit 1; }
  device='{"device": "none"}' cpu='{"device": "none"}'
fi
test -s "$out/sim.h5" || { echo "no results file written"; exit 1; }
ls "$out"/sim.h5.tmp.* 2>/dev/null && { echo "temporary left behind"; exit 1; }
python3 - "$plain" "$resumed" "$single" "$restart" "$across" "$waterbag" "$device" "$cpu" <<'PY'
import json, sys
a, b, f, r, x, w, d, c = (json.loads(x) for x in sys.argv[1:9])
assert a["device"] == "cpu", a["device"]
if d["device"] != "none":
    assert d["device"] != "cpu" and c["device"] == "cpu", (d["device"], c["device"])
    assert d["points"] == c["points"], ("the device's numbers differ", d["points"], c["points"])
    assert d["steps"] == c["steps"], (d["steps"], c["steps"])
assert a["momenta"] == "gaussian" and w["momenta"] == "waterbag", (a["momenta"], w["momenta"])
assert abs(w["Kc"] - 3 * a["Kc"]) <= 1e-12 * a["Kc"], (w["Kc"], a["Kc"])
assert [p["R_mean"] for p in w["points"]] != [p["R_mean"] for p in a["points"]], "same momenta"
assert all(p["energy_rel_error_max"] < 1e-2 for p in w["points"]), w["points"]
assert r["points"] == x["points"], ("across replicas differs", r["points"], x["points"])
assert 3 * x["steps"] == r["steps"], (x["steps"], r["steps"])
assert a["force"] == "sparse" and f["force"] == "sparse-float32", (a["force"], f["force"])
assert [p["energy_rel_error_max"] < 1e-2 for p in f["points"]] == [True] * 3, f["points"]
for key in ("nnz", "nnz_steps_per_second", "points", "Kc", "lambda"):
    assert key in a, key
assert len(a["points"]) == 3, a["points"]
for p in a["points"]:
    for key in ("K", "K_over_Kc", "R_mean", "R_sem", "energy_rel_error_max", "momentum_drift"):
        assert key in p, key
    assert p["energy_rel_error_max"] < 1e-2 and p["momentum_drift"] < 1e-10, p
assert [p["R_mean"] for p in a["points"]] == [p["R_mean"] for p in b["points"]], "resume differs"
print("simulate outputs ok:", [round(p["R_mean"], 5) for p in a["points"]])
PY
