#!/usr/bin/env bash
# Faults during a run of `hmfnet simulate`, at the process level:
#  1. SIGKILL part-way, then --resume: the results equal those of an uninterrupted run exactly;
#  2. SIGTERM part-way: exit code 143, a final checkpoint, no results file; --resume: identical;
#  3. a checkpoint with a byte changed is refused with an error naming it, exit code 1.
# Usage: faults_during_run.sh HMFNET OUTDIR
set -euo pipefail
hmfnet=$1 out=$2/faults
rm -rf "$out" && mkdir -p "$out"
"$hmfnet" generate er --n 2000 --mean-degree 40 --seed 3 -o "$out/net.h5" > /dev/null
args=(simulate "$out/net.h5" --K-over-Kc 0.5,1.5,3 --h 0.01 --T 40 --transient 10 --seed 7
      --json --quiet --threads 1)
"$hmfnet" "${args[@]}" > "$out/whole.json"

# Starts a checkpointed run in the background (a child of this shell, so `wait` gets its exit
# code; its pid in $pid) and waits until it has written its first checkpoint and run on a little.
start_run() {
  "$hmfnet" "${args[@]}" --checkpoint "$out/$1.ckpt.h5" --resume -o "$out/$1.h5" \
    > "$out/$1.json" 2> "$out/$1.err" &
  pid=$!
  for _ in $(seq 1 300); do
    [ -f "$out/$1.ckpt.h5" ] && break
    sleep 0.05
  done
  sleep 0.3
  kill -0 "$pid" 2> /dev/null || { echo "$1: run finished before the fault; make it longer"; exit 1; }
}

same_points() {
  /usr/bin/python3 - "$out/whole.json" "$1" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ra = [(p["R_mean"], p["R_sem"], p["energy_rel_error_max"]) for p in a["points"]]
rb = [(p["R_mean"], p["R_sem"], p["energy_rel_error_max"]) for p in b["points"]]
assert ra == rb, f"resumed run differs:\n{ra}\n{rb}"
assert b["resumed"], "the second run did not resume"
PY
}

# 1. SIGKILL: nothing can be cleaned up; the last periodic or per-K checkpoint must suffice.
start_run kill
kill -KILL "$pid"; wait "$pid" 2> /dev/null || true
[ ! -e "$out/kill.h5" ] || { echo "SIGKILL: a results file appeared"; exit 1; }
"$hmfnet" "${args[@]}" --checkpoint "$out/kill.ckpt.h5" --resume > "$out/kill.resumed.json"
same_points "$out/kill.resumed.json"
echo "SIGKILL then --resume: identical"

# 2. SIGTERM: a final checkpoint, a clear message, exit 128 + 15.
start_run term
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
[ "$status" -eq 143 ] || { echo "SIGTERM: exit code $status, expected 143"; cat "$out/term.err"; exit 1; }
grep -q "hmfnet: interrupted: SIGTERM" "$out/term.err" || { cat "$out/term.err"; exit 1; }
grep -q "rerun with --resume" "$out/term.err" || { cat "$out/term.err"; exit 1; }
[ ! -e "$out/term.h5" ] || { echo "SIGTERM: a results file appeared"; exit 1; }
"$hmfnet" "${args[@]}" --checkpoint "$out/term.ckpt.h5" --resume > "$out/term.resumed.json"
same_points "$out/term.resumed.json"
echo "SIGTERM then --resume: identical ($(cat "$out/term.err"))"

# 3. A corrupted checkpoint: flip one byte in the second half of the file (the state arrays).
cp "$out/term.ckpt.h5" "$out/bad.ckpt.h5"
/usr/bin/python3 - "$out/bad.ckpt.h5" <<'PY'
import sys
path = sys.argv[1]
data = bytearray(open(path, "rb").read())
data[len(data) * 3 // 4] ^= 0x55
open(path, "wb").write(bytes(data))
PY
status=0
"$hmfnet" "${args[@]}" --checkpoint "$out/bad.ckpt.h5" --resume > /dev/null 2> "$out/bad.err" || status=$?
[ "$status" -eq 1 ] || { echo "corrupted checkpoint: exit code $status, expected 1"; exit 1; }
grep -q "hmfnet: error: $out/bad.ckpt.h5" "$out/bad.err" || { cat "$out/bad.err"; exit 1; }
echo "corrupted checkpoint refused: $(cat "$out/bad.err")"
