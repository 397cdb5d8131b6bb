#!/usr/bin/env bash
# `hmfnet simulate` of two builds, alternated in each round on one network with the same
# arguments: the median ns per rotor and step (integration_seconds / (steps N), all replicas
# together), old / new with each round's ratio, the threads each ran, and whether the two runs'
# results are the same: every dataset of the results files (the time series, each K's point,
# node data where asked) bit for bit, and the attributes steps and force_evaluations. For
# changes that the benchmarks' single step() does not see (what a whole run forms, samples or
# skips), and each run's peak resident memory and the trials that chose its thread count and
# column segments. Timing runs want few records (--record-stride 1000000); a results check,
# many. Idle machine only. PYTHON: a python3 with numpy and h5py (Debian's /usr/bin/python3 has them).
# Usage: bench/simulate_before_after.sh OLD_HMFNET NEW_HMFNET ROUNDS NETWORK SIMULATE_ARGS...
#   e.g. bench/simulate_before_after.sh /tmp/old/hmfnet build/bin/hmfnet 3 kn400.h5 --replicas 16
#          --K-over-Kc 1.5 --h 0.1 --T 3000 --transient 2980 --seed 1 --threads 1
#          --record-stride 1000000
set -euo pipefail
old=$1 new=$2 rounds=$3 net=$4
shift 4
python=${PYTHON:-python3}
if ((rounds < 1)); then
  echo "simulate_before_after.sh: ROUNDS must be at least 1, not $rounds" >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for round in $(seq "$rounds"); do
  for label in old new; do
    env -u OMP_WAIT_POLICY "${!label}" simulate "$net" "$@" --json --quiet \
      -o "$tmp/$label.$round.h5" >"$tmp/$label.$round.json"
  done
done
"$python" - "$tmp" "$rounds" <<'PY'
import json, statistics, sys
import h5py, numpy as np
tmp, rounds = sys.argv[1], int(sys.argv[2])
def run(label, r):
    return json.load(open("%s/%s.%d.json" % (tmp, label, r)))
def ns(d):
    return d["integration_seconds"] / (d["steps"] * d["n"]) * 1e9
def differences(r):
    """Datasets (and counts) of round r's results files that are not the same bits."""
    a, b = h5py.File("%s/old.%d.h5" % (tmp, r)), h5py.File("%s/new.%d.h5" % (tmp, r))
    names = []
    a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
    other = []
    b.visititems(lambda n, o: other.append(n) if isinstance(o, h5py.Dataset) else None)
    bad = sorted(set(names) ^ set(other))
    for n in set(names) & set(other):
        x, y = a[n][()], b[n][()]
        same = (x.shape == y.shape and (np.array_equal(x, y, equal_nan=True)
                if x.dtype.kind == "f" else np.array_equal(x, y)))
        if not same:
            bad.append(n)
    bad += [k for k in ("steps", "force_evaluations") if a.attrs.get(k) != b.attrs.get(k)]
    return sorted(bad)
old = [run("old", r) for r in range(1, rounds + 1)]
new = [run("new", r) for r in range(1, rounds + 1)]
t_old, t_new = [ns(d) for d in old], [ns(d) for d in new]
bad = sorted({n for r in range(1, rounds + 1) for n in differences(r)})
print("ns per rotor-step: old %.3f new %.3f  old / new %.2fx  rounds %s  threads %d / %d  "
      "results %s" % (statistics.median(t_old), statistics.median(t_new),
                      statistics.median(t_old) / statistics.median(t_new),
                      " / ".join("%.2f" % (a / b) for a, b in zip(t_old, t_new)),
                      old[0]["threads"], new[0]["threads"],
                      "the same" if not bad else "DIFFER: " + ", ".join(bad)))
for label, runs in (("old", old), ("new", new)):
    print("%s: peak RSS MB %s; trials %s" % (
        label, " / ".join("%.1f" % max(d["peak_rss_mb_per_rank"]) for d in runs),
        " / ".join("[threads: %s; segments: %s]" % (d.get("thread_trial") or "none",
                                                    d.get("segment_trial") or "none")
                   for d in runs)))
PY
