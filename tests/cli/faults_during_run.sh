#!/usr/bin/env bash
# Faults during a run of `hmfnet simulate`, at the process level:
#  1. SIGKILL part-way, then --resume: the results equal those of an uninterrupted run exactly;
#  2. SIGTERM part-way: exit code 143, a final checkpoint, no results file; --resume: identical;
#  3. a checkpoint with one stored value changed, in each of its datasets and in each count and
#     real field in turn, is refused by the checksum with an error naming it, exit code 1.
# Usage: faults_during_run.sh HMFNET OUTDIR
# FAULT_AT (environment, default 0): the signals of cases 1 and 2 are sent FAULT_AT x (the time
# of one K) after the first checkpoint appears, 0 <= FAULT_AT < 1. The first checkpoint is
# written when the second of the three K starts (earlier only if the first K takes over the 5 s
# periodic interval), so any FAULT_AT lands the signal with at least one K still to run; vary
# it to land the signals at other steps: the results must not depend on where they land.
set -euo pipefail
hmfnet=$1 out=$2/faults
fault_at=${FAULT_AT:-0}
/usr/bin/python3 -c 'import sys; assert 0 <= float(sys.argv[1]) < 1' "$fault_at" 2> /dev/null ||
  { echo "FAULT_AT=$fault_at: expected 0 <= FAULT_AT < 1"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
"$hmfnet" generate er --n 2000 --mean-degree 40 --seed 3 -o "$out/net.h5" > /dev/null
# Three K of 6000 steps each (about a second each with --node-data): a signal sent in the
# second K leaves the third to run, so it never finds the run finished even on a machine twice
# as fast as the one that timed `whole`. --node-data with no transient: every accumulator a
# checkpoint can hold is started from the first step, so case 3 finds every dataset non-empty
# wherever the signal lands.
args=(simulate "$out/net.h5" --K-over-Kc 0.5,1.5,3 --h 0.01 --T 60 --transient 0 --node-data
      --seed 7 --json --quiet --threads 1)
"$hmfnet" "${args[@]}" -o "$out/whole.h5" > "$out/whole.json"
# The delay is a fraction of this machine's own time per K, so it means the same step range on
# a fast and a slow machine.
delay=$(/usr/bin/python3 -c '
import json, sys
w = json.load(open(sys.argv[1]))
print("%.3f" % (float(sys.argv[2]) * w["integration_seconds"] / len(w["points"])))
' "$out/whole.json" "$fault_at")

# Starts a checkpointed run in the background (a child of this shell, so `wait` gets its exit
# code; its pid in $pid) and returns $delay seconds after its first checkpoint appears. A
# checkpoint is renamed into place whole, so once the file exists a resume can use it.
start_run() {
  "$hmfnet" "${args[@]}" --checkpoint "$out/$1.ckpt.h5" --resume -o "$out/$1.h5" \
    > "$out/$1.json" 2> "$out/$1.err" &
  pid=$!
  until [ -f "$out/$1.ckpt.h5" ]; do
    kill -0 "$pid" 2> /dev/null ||
      { echo "$1: run ended before its first checkpoint"; cat "$out/$1.err"; exit 1; }
    sleep 0.01
  done
  sleep "$delay"
  kill -0 "$pid" 2> /dev/null ||
    { echo "$1: run finished before the fault (FAULT_AT=$fault_at)"; exit 1; }
}

# Where the checkpoint stands: the step a resume continues from.
position() {
  /usr/bin/python3 - "$1" <<'PY'
import h5py, sys
with h5py.File(sys.argv[1], "r") as f:
    print(f"K index {f.attrs['k_index']}, step {f.attrs['segment_step']} of it, "
          f"{f.attrs['steps_total']} steps in all")
PY
}

# The resumed run ($1: its JSON and results file) equals the uninterrupted one: the JSON's
# points, and every dataset of the results file bit for bit (the per-node data included).
same_results() {
  /usr/bin/python3 - "$out/whole.json" "$1.json" "$out/whole.h5" "$1.h5" <<'PY'
import h5py, json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ra = [(p["R_mean"], p["R_sem"], p["energy_rel_error_max"]) for p in a["points"]]
rb = [(p["R_mean"], p["R_sem"], p["energy_rel_error_max"]) for p in b["points"]]
assert ra == rb, f"resumed run differs:\n{ra}\n{rb}"
assert b["resumed"], "the second run did not resume"

def datasets(path):
    with h5py.File(path, "r") as f:
        found = {}
        f.visititems(lambda n, o: found.update({n: o[()]}) if isinstance(o, h5py.Dataset)
                     else None)
        return found
wa, wb = datasets(sys.argv[3]), datasets(sys.argv[4])
assert wa.keys() == wb.keys(), f"datasets differ: {sorted(wa.keys() ^ wb.keys())}"
differ = [n for n in wa if wa[n].dtype != wb[n].dtype or wa[n].shape != wb[n].shape
          or wa[n].tobytes() != wb[n].tobytes()]
assert not differ, f"resumed results differ in {differ}"
PY
}

echo "signals sent ${delay} s (FAULT_AT=$fault_at of a K) after the first checkpoint"

# 1. SIGKILL: nothing can be cleaned up; the last periodic or per-K checkpoint must suffice.
start_run kill
kill -KILL "$pid"; wait "$pid" 2> /dev/null || true
[ ! -e "$out/kill.h5" ] || { echo "SIGKILL: a results file appeared"; exit 1; }
at=$(position "$out/kill.ckpt.h5")
"$hmfnet" "${args[@]}" --checkpoint "$out/kill.ckpt.h5" --resume -o "$out/kill.resumed.h5" \
  > "$out/kill.resumed.json"
same_results "$out/kill.resumed"
echo "SIGKILL then --resume from $at: identical"

# 2. SIGTERM: a final checkpoint, a clear message, exit 128 + 15.
start_run term
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
[ "$status" -eq 143 ] || { echo "SIGTERM: exit code $status, expected 143"; cat "$out/term.err"; exit 1; }
grep -q "hmfnet: interrupted: SIGTERM" "$out/term.err" || { cat "$out/term.err"; exit 1; }
grep -q "rerun with --resume" "$out/term.err" || { cat "$out/term.err"; exit 1; }
[ ! -e "$out/term.h5" ] || { echo "SIGTERM: a results file appeared"; exit 1; }
# The resume below rewrites the checkpoint; case 3 corrupts the one SIGTERM left.
cp "$out/term.ckpt.h5" "$out/sigterm.ckpt.h5"
at=$(position "$out/term.ckpt.h5")
"$hmfnet" "${args[@]}" --checkpoint "$out/term.ckpt.h5" --resume -o "$out/term.resumed.h5" \
  > "$out/term.resumed.json"
same_results "$out/term.resumed"
echo "SIGTERM then --resume from $at: identical ($(cat "$out/term.err"))"

# 3. Corrupted checkpoints. A byte at a file offset may fall in free space or metadata that no
# read touches, depending on the layout; a changed value is what a resume would silently use.
# The datasets are those found in the file (the format may gain fields), the results groups'
# included; the count and real fields are the root attributes that count_fields and real_fields
# name. One copy per value changed: the lowest bit of element 0 of a float or an integer, the
# first character of a string. An empty dataset has no value to change and is skipped.
/usr/bin/python3 - "$out/sigterm.ckpt.h5" "$out" > "$out/corrupted.list" <<'PY'
import h5py, numpy as np, shutil, sys

source, out = sys.argv[1:3]

def changed(a):
    """a (numpy array) with element 0 changed in a way a checksum of its bytes must notice."""
    flat = a.reshape(-1)
    if a.dtype.kind == "f":
        bits = flat.view(np.dtype(f"u{a.dtype.itemsize}"))
        bits[0] ^= bits.dtype.type(1)
    elif a.dtype.kind in "iu":
        flat[0] ^= a.dtype.type(1)
    elif a.dtype.kind == "S" or (a.dtype.kind == "O" and isinstance(flat[0], bytes)):
        flat[0] = bytes([flat[0][0] ^ 1]) + flat[0][1:] if flat[0] else b"x"
    elif a.dtype.kind == "O" and isinstance(flat[0], str):
        flat[0] = chr(ord(flat[0][0]) ^ 1) + flat[0][1:] if flat[0] else "x"
    else:
        sys.exit(f"{source}: no rule to change a value of dtype {a.dtype}: extend this test")
    return a

with h5py.File(source, "r") as f:
    datasets = []
    f.visititems(lambda name, o: datasets.append(name) if isinstance(o, h5py.Dataset) else None)
    fields = [n for key in ("count_fields", "real_fields")
              for n in f.attrs[key].decode().split("\n") if n]
    sizes = {name: f[name].size for name in datasets}
assert datasets and fields, f"{source}: no datasets or no count/real fields found"
for k, name in enumerate(datasets + fields):
    if name in sizes and sizes[name] == 0:
        print(f"skipped: dataset {name} is empty", file=sys.stderr)
        continue
    copy = f"{out}/bad{k}.ckpt.h5"
    shutil.copyfile(source, copy)
    with h5py.File(copy, "r+") as g:
        if name in sizes:
            g[name][...] = changed(g[name][()].copy())
            kind = "dataset"
        else:
            value = np.array(g.attrs[name])
            g.attrs.modify(name, changed(value.reshape(1)).reshape(value.shape))
            kind = "field"
    print(f"{copy}\t{kind} {name}")
PY
failures=()
while IFS=$'\t' read -r copy what; do
  status=0
  "$hmfnet" "${args[@]}" --checkpoint "$copy" --resume > /dev/null 2> "$copy.err" || status=$?
  first=$(head -n 1 "$copy.err")
  if [ "$status" -ne 1 ] || [[ "$first" != "hmfnet: error: $copy: checksum mismatch"* ]]; then
    failures+=("$what changed: exit code $status (expected 1), stderr: ${first:-(empty)}")
  fi
done < "$out/corrupted.list"
if [ ${#failures[@]} -gt 0 ]; then
  echo "corrupted checkpoints not refused by the checksum:"
  printf '  %s\n' "${failures[@]}"
  exit 1
fi
echo "corrupted checkpoints refused ($(wc -l < "$out/corrupted.list") values, one per copy):" \
     "$(head -n 1 "$(head -n 1 "$out/corrupted.list" | cut -f 1).err")"
