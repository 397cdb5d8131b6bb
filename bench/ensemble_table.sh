#!/usr/bin/env bash
# The kernel's whole table in one run (docs/performance.md, goals 1-5): hmfnet's leap-frog step
# (LeapFrogStep) beside the plain OpenMP CSR yardstick (YardstickStep) and the step's bound, at
# N = 10^4 and 10^6 (ER, mean degree 100), 1 and 2 threads, B = 1, 4, 8 replicas, float64 and
# float32; then the sincos per angle and the L1/L2/L3/memory gather ladder.
#
# The bound ("A bound that bounds", docs/performance.md): a step takes at least its sincos pass
# (one angle per rotor and replica, the kernel's own sincos at its measured rate: SincosFloor)
# plus its rows pass, and the rows pass at least the largest of
#   index:  the kernel's index bytes (4 B per stored entry unblocked, 2 B in 16-bit segments,
#           plus a byte a row and segment of run lengths) read in order from where an array of
#           that size lives (StreamRead at that size and thread count: bench_peak_rates.cpp),
#   L1:     per stored entry, one load and one add of each of the ceil(record / w) pieces of its
#           gathered record of 2B values (plus the index's own 4 B), at the most (load, add) pairs
#           a second of the widest w this CPU has (L1LoadAdd),
#   L2->L1: the bytes the kernel's access stream must bring into the cores' L1 (AccessLines,
#           bench_access_lines.cpp: records' lines under optimal replacement, the index and run
#           streams, the carried sums) at the best rate lines come from L2 (StreamRead, 256 KiB),
#   L3->L2: the same into L2 (L1 and L2 of a core together), at the best rate from beyond them
#           (StreamRead at 4 MB and 16 MiB, of those whose share a thread exceeds them),
# each measured at its best case, so no code runs above it; a row above 100% proves the bound
# wrong. The gather bound of the old "floor" (GatherBound: a random-order microbenchmark) is
# printed beside it: it is not a bound (the segmented kernel beats it at N = 10^6).
# Rates are stored entries x replicas x steps per second. Ratios are within this one run (these
# machines are noisy); run on an idle machine. Needs a build with -DHMFNET_BUILD_BENCH=ON.
# Usage: bench/ensemble_table.sh [BUILD_DIR (default build)] [MIN_TIME_SECONDS (default 0.5)]
#        [JSON: keep the raw measurements there; where it exists, print the table from it]
set -euo pipefail
build=${1:-build}
min_time=${2:-0.5}
json=${3:-}
if [[ -z $json ]]; then
  json=$(mktemp)
  trap 'rm -f "$json"' EXIT
fi
if [[ ! -s $json ]]; then
  # Into a temporary file first: a run cut short leaves no JSON to be read as a whole one.
  "$build/bin/hmfnet_bench" \
    --benchmark_filter='^(LeapFrogStep|GatherBound|SincosFloor|SincosLibc|AccessLines)/[0-9]+/100/|^YardstickStep/|^GatherLadder/|^L1LoadAdd/|^StreamRead/' \
    --benchmark_min_time="$min_time" --benchmark_format=json >"$json.part" 2>/dev/null
  mv "$json.part" "$json"
fi
python3 - "$json" <<'PY'
import json, re, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
rate, ladder, angle_ns, lines, lowest = {}, {}, {}, {}, {}
for r in runs:
    if r.get("error_occurred") or r.get("run_type") == "aggregate":
        continue
    name = re.sub(r"/[a-z_]+:[0-9.]+|/real_time", "", r["name"]).split("/")
    kind, args = name[0], tuple(int(a) for a in name[1:])
    # The ceilings run in repetitions (bench_peak_rates.cpp): the best of them.
    if kind == "GatherLadder":
        ladder[args] = r["gathers_per_s"]
    elif kind == "L1LoadAdd":
        rate[(kind,) + args] = max(r["pairs_per_s"], rate.get((kind,) + args, 0.0))
    elif kind == "StreamRead":
        rate[(kind,) + args] = max(r["bytes_per_s"], rate.get((kind,) + args, 0.0))
        lowest[(kind,) + args] = min(r["bytes_per_s"], lowest.get((kind,) + args, float("inf")))
    elif kind == "AccessLines":
        lines[args] = r
    else:
        rate[(kind,) + args] = r["nnz_steps_per_s"]
    if "ns_per_angle" in r:
        angle_ns[(kind,) + args] = r["ns_per_angle"]
G = 1e9
NNZ = {10000: 1e6, 1000000: 1e8}  # ER, mean degree 100: stored entries (to 0.1%)
needed = [("StreamRead", kib, t) for kib in (256, 3906, 16384, 390625) for t in (1, 2)]
missing = [k for k in needed if k not in rate]
if not lines or missing:
    sys.exit("ensemble_table.sh: %s has no %s" % (
        sys.argv[1], "AccessLines rows" if not lines else "/".join(map(str, missing[0]))))
cache = next(iter(lines.values()))


def beyond_l2(t):
    """The best sequential rate of an array that a core's L1 and L2 cannot hold."""
    reach = cache["l1_bytes"] + cache["l2_bytes"]
    return max(rate[("StreamRead", kib, t)] for kib in (3906, 16384) if kib * 1024 / t > reach)


def bound(n, t, b, prec):
    """The step's bound in stored entries x replicas x steps / s, and its limiting resource."""
    nnz = NNZ[n]
    record = 2 * b * (8 if prec == 0 else 4)
    trig = rate[("SincosFloor", n, 100, b, t)]
    t_sincos = nnz * b / trig  # SincosFloor counts per stored entry x replica
    stream = lines[(n, 100, b, t, prec)]
    t_rows = {
        "index stream": stream["index_bytes"] /
        rate[("StreamRead", {10000: 3906, 1000000: 390625}[n], t)],
        "L1 load+add": min(nnz * (-(-record // w) + 4 / w) / rate[("L1LoadAdd", w, t)]
                           for w in (16, 32, 64) if ("L1LoadAdd", w, t) in rate),
        "L2->L1 lines": stream["l1_fill_bytes"] / rate[("StreamRead", 256, t)],
        "L3->L2 lines": stream["l2_fill_bytes"] / beyond_l2(t),
    }
    limit = max(t_rows, key=t_rows.get)
    t_step = t_sincos + t_rows[limit]
    share = t_sincos / t_step
    return nnz * b / t_step, "%s (sincos %.0f%%)" % (limit, 100 * share)


print("%-9s %3s %2s %-7s %8s %8s %6s %8s %8s %7s %6s %6s %6s  %s" % (
    "N", "thr", "B", "prec", "hmfnet", "yardstk", "/yard", "old gath", "bound", "/bound",
    "/B=1", "L1 B/e", "L2 B/e", "bound's limit"))
for n in (10000, 1000000):
    for t in (1, 2):
        for prec in (0, 1):
            for b in (1, 4, 8):
                ours = rate.get(("LeapFrogStep", n, 100, b, t, prec))
                if ours is None:
                    continue
                if (n, 100, b, t, prec) not in lines:
                    sys.exit("ensemble_table.sh: no AccessLines/%d/100/%d/%d/%d" % (n, b, t, prec))
                yard = rate.get(("YardstickStep", n, 100, t))
                gather = rate.get(("GatherBound", n, 100, b, t, prec))
                top, limit = bound(n, t, b, prec)
                base = rate.get(("LeapFrogStep", n, 100, 1, t, 0))
                stream = lines[(n, 100, b, t, prec)]
                print("%-9d %3d %2d %-7s %8.3f %8.3f %6.2f %8.3f %8.3f %6.0f%% %6.2f %6.1f %6.1f  %s" % (
                    n, t, b, ("float32", "float64")[prec == 0], ours / G, yard / G,
                    ours / yard, gather / G, top / G, 100 * ours / top, ours / base,
                    stream["l1_fill_bytes"] / NNZ[n], stream["l2_fill_bytes"] / NNZ[n], limit))
print("\nGnnz*replicas*steps/s. yardstk: the plain OpenMP CSR loop (1 replica, same threads); "
      "old gath: the random-order gather microbenchmark of the same table (not a bound); "
      "bound: the step's least time from the measured ceilings (script header), /bound the "
      "fraction (above 100%: the bound is wrong); /B=1: aggregate rate / float64 B = 1 at the "
      "same N and threads; L1 B/e, L2 B/e: bytes a step must bring into the cores' L1 and L2 "
      "per stored entry (all replicas), from the kernel's own access stream (AccessLines).")
print("\nCeilings: L1 (load, add) pairs/s by width (1 | 2 threads): " + ", ".join(
    "%d B %.2f | %.2f G" % (w, rate.get(("L1LoadAdd", w, 1), 0) / G,
                             rate.get(("L1LoadAdd", w, 2), 0) / G) for w in (16, 32, 64)))
print("Ceilings: sequential reads GB/s (1 | 2 threads): " + ", ".join(
    "%s %.1f | %.1f" % (label, rate[("StreamRead", kib, 1)] / G, rate[("StreamRead", kib, 2)] / G)
    for kib, label in ((256, "256 KiB"), (3906, "4 MB"), (16384, "16 MiB"), (390625, "400 MB"))))
print("  (the best of each one's repetitions; the lowest, 1 | 2 threads: " + ", ".join(
    "%s %.1f | %.1f" % (label, lowest[("StreamRead", kib, 1)] / G,
                        lowest[("StreamRead", kib, 2)] / G)
    for kib, label in ((256, "256 KiB"), (3906, "4 MB"))) + ")")
print("Caches (AccessLines): L1d %d KiB, L2 %d KiB a core" % (cache["l1_bytes"] / 1024,
                                                           cache["l2_bytes"] / 1024))
print("\nLarge N: rate at N = 10^6 / rate at N = 10^4 (same threads, B, precision):")
for t in (1, 2):
    for prec in (0, 1):
        cells = []
        for b in (1, 4, 8):
            small = rate.get(("LeapFrogStep", 10000, 100, b, t, prec))
            large = rate.get(("LeapFrogStep", 1000000, 100, b, t, prec))
            if small and large:
                cells.append("B=%d %.0f%%" % (b, 100 * large / small))
        print("  %d thread(s), %s: %s" % (t, ("float32", "float64")[prec == 0], ", ".join(cells)))
print("\nsincos per angle (N = 10^4, B = 1; ns): threads  hmfnet's  glibc's  ratio")
for t in (1, 2):
    ours = angle_ns.get(("SincosFloor", 10000, 100, 1, t))
    libc = angle_ns.get(("SincosLibc", 10000, 100, 1, t))
    if ours and libc:
        print("  %d  %7.2f  %7.2f  %5.2fx" % (t, ours, libc, libc / ours))
print("\nGather ladder (random 16-byte records, G gathers/s): table  1 thread  2 threads")
for kib, level in ((16, "L1"), (256, "L2"), (8192, "L3"), (524288, "memory")):
    print("  %-6s %7d KiB  %6.3f  %6.3f" % (level, kib, ladder.get((kib, 1), 0) / G,
                                             ladder.get((kib, 2), 0) / G))
PY
