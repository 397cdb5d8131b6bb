#!/usr/bin/env bash
# Peak resident memory of `hmfnet simulate` where the sparse kernel cuts its columns into
# segments (docs/performance.md, "16-bit segment indices" and "Carried sums in four panels"):
# ER N (default 10^6), mean degree 100, read from an HDF5 file, 20 leap-frog steps on 1 thread
# with B = 1 and B = 8 replicas, by two hmfnet binaries (OLD and NEW: two commits), each run's
# `peak_rss_mb_per_rank` from its --json; then every float dataset of the two binaries' results
# files compared bit for bit (the kernels must not change the bits). The network itself is
# 4 bytes per stored entry + 8 per row (408 MB at N = 10^6, degree 100).
# Usage: bench/segment_memory.sh OLD_HMFNET NEW_HMFNET [N (default 1000000)]
# PYTHON: a python3 with h5py (default /usr/bin/python3, Debian's).
set -euo pipefail
old=$1 new=$2 n=${3:-1000000}
python=${PYTHON:-/usr/bin/python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$new" generate er --n "$n" --mean-degree 100 --seed 7 -o "$tmp/er.h5" > /dev/null
printf '%-9s %3s %14s %14s %10s\n' N B "old RSS (MB)" "new RSS (MB)" "same bits"
for b in 1 8; do
  for which in old new; do
    bin=$old
    [ "$which" = new ] && bin=$new
    "$bin" simulate "$tmp/er.h5" --K 1 --h 0.1 --T 2 --transient 0 --seed 1 --replicas "$b" \
      --threads 1 --quiet --json -o "$tmp/$which.h5" > "$tmp/$which.json"
  done
  "$python" - "$tmp" "$n" "$b" <<'PY'
import json, sys
import h5py
tmp, n, b = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rss = {w: max(json.load(open(f"{tmp}/{w}.json"))["peak_rss_mb_per_rank"]) for w in ("old", "new")}
same = True
with h5py.File(f"{tmp}/old.h5") as a, h5py.File(f"{tmp}/new.h5") as c:
    def visit(name, obj):
        global same
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
            same = same and name in c and obj[()].tobytes() == c[name][()].tobytes()
    a.visititems(visit)
print("%-9d %3d %14.0f %14.0f %10s" % (n, b, rss["old"], rss["new"], "yes" if same else "NO"))
PY
done
