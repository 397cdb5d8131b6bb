#!/usr/bin/env bash
# The kernel's whole table in one run (docs/performance.md, goals 1-5): hmfnet's leap-frog step
# (LeapFrogStep) beside the plain OpenMP CSR yardstick (YardstickStep), the measured gather bound
# of the same table
# (GatherBound) and the floor it makes with the kernel's one sincos per rotor (SincosFloor;
# glibc's scalar sincos, which it replaced, in SincosLibc; all in bench_gather_bound.cpp), at
# N = 10^4 and 10^6 (ER, mean degree 100), 1 and 2 threads, B = 1, 4, 8 replicas, float64 and
# float32; then the sincos per angle and the L1/L2/L3/memory gather ladder.
# Rates are stored entries x replicas x steps per second. Ratios are within this one run (these
# machines are noisy); run on an idle machine. Needs a build with -DHMFNET_BUILD_BENCH=ON.
# Usage: bench/ensemble_table.sh [BUILD_DIR (default build)] [MIN_TIME_SECONDS (default 0.5)]
set -euo pipefail
build=${1:-build}
min_time=${2:-0.5}
json=$(mktemp)
trap 'rm -f "$json"' EXIT
"$build/bin/hmfnet_bench" \
  --benchmark_filter='^(LeapFrogStep|GatherBound|SincosFloor|SincosLibc)/[0-9]+/100/|^YardstickStep/|^GatherLadder/' \
  --benchmark_min_time="$min_time" --benchmark_format=json >"$json" 2>/dev/null
python3 - "$json" <<'PY'
import json, re, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
rate, ladder, angle_ns = {}, {}, {}
for r in runs:
    name = re.sub(r"/real_time$", "", r["name"]).split("/")
    kind, args = name[0], tuple(int(a) for a in name[1:])
    if kind == "GatherLadder":
        ladder[args] = r["gathers_per_s"]
    else:
        rate[(kind,) + args] = r["nnz_steps_per_s"]
    if "ns_per_angle" in r:
        angle_ns[(kind,) + args] = r["ns_per_angle"]
G = 1e9
print("%-9s %3s %2s %-7s %8s %8s %6s %8s %8s %7s %6s" % (
    "N", "thr", "B", "prec", "hmfnet", "yardstk", "/yard", "gather", "floor", "/floor", "/B=1"))
for n in (10000, 1000000):
    for t in (1, 2):
        for prec in (0, 1):
            for b in (1, 4, 8):
                ours = rate.get(("LeapFrogStep", n, 100, b, t, prec))
                if ours is None:
                    continue
                yard = rate.get(("YardstickStep", n, 100, t))
                bound = rate.get(("GatherBound", n, 100, b, t, prec))
                trig = rate.get(("SincosFloor", n, 100, b, t))
                floor = 1 / (1 / bound + 1 / trig)  # the two costs add per step
                base = rate.get(("LeapFrogStep", n, 100, 1, t, 0))
                print("%-9d %3d %2d %-7s %8.3f %8.3f %6.2f %8.3f %8.3f %6.0f%% %6.2f" % (
                    n, t, b, ("float32", "float64")[prec == 0], ours / G, yard / G,
                    ours / yard, bound / G, floor / G, 100 * ours / floor, ours / base))
print("\nGnnz*replicas*steps/s. yardstk: the plain OpenMP CSR loop (1 replica, same threads); "
      "gather: the gather bound of the same table and record width; floor: gather and one "
      "sincos per rotor and replica, 1 / (1 / gather + 1 / sincos); /B=1: aggregate rate / "
      "float64 B = 1 at the same N and threads.")
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
