#!/usr/bin/env bash
# `hmfnet simulate` of two builds, alternated in each round on one network and the same
# arguments: the median ns per rotor and step (integration_seconds / (steps N), all replicas
# together), old / new with each round's ratio, and whether the two runs' results (every field
# of --json but timings, memory and version) are the same. For changes that the benchmarks'
# single step() does not see (what a whole run forms, samples or skips). Idle machine only.
# Usage: bench/simulate_before_after.sh OLD_HMFNET NEW_HMFNET ROUNDS NETWORK SIMULATE_ARGS...
#   e.g. bench/simulate_before_after.sh /tmp/old/hmfnet build/bin/hmfnet 3 kn400.h5
#          --replicas 16 --K-over-Kc 1.5 --h 0.1 --T 3000 --transient 2980 --seed 1 --threads 1
set -euo pipefail
old=$1 new=$2 rounds=$3 net=$4
shift 4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for round in $(seq "$rounds"); do
  for label in old new; do
    env -u OMP_WAIT_POLICY "${!label}" simulate "$net" "$@" --record-stride 1000000 --json \
      --quiet >"$tmp/$label.$round.json"
  done
done
python3 - "$tmp" "$rounds" <<'PY'
import json, statistics, sys
tmp, rounds = sys.argv[1], int(sys.argv[2])
def ns(label, r):
    d = json.load(open("%s/%s.%d.json" % (tmp, label, r)))
    return d["integration_seconds"] / (d["steps"] * d["n"]) * 1e9
def results(label):
    # Everything a run computes: drop what measures the run itself.
    skip = ("seconds", "per_second", "rss", "version", "commit", "host", "threads", "thread_rule")
    def strip(v):
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items() if not any(s in k for s in skip)}
        return [strip(x) for x in v] if isinstance(v, list) else v
    return strip(json.load(open("%s/%s.1.json" % (tmp, label))))
old = [ns("old", r) for r in range(1, rounds + 1)]
new = [ns("new", r) for r in range(1, rounds + 1)]
print("ns per rotor-step: old %.3f new %.3f  old / new %.2fx  rounds %s  results %s" % (
    statistics.median(old), statistics.median(new), statistics.median(old) / statistics.median(new),
    " / ".join("%.2f" % (a / b) for a, b in zip(old, new)),
    "the same" if results("old") == results("new") else "DIFFER"))
PY
