#!/usr/bin/env python3
"""Per-step compute and import time per rank against the rank count P for the row-distributed
force kernel (docs/scaling.md), from two measured inputs and one assumption:

  rate   stored entries per second per core of the force kernel with its [cos, sin] table out of
         cache (measured: 0.34-0.38 Gnnz*steps/s at N = 10^6, docs/performance.md; default 0.35e9)
  ghosts per rank of a row block: N (1 - 1/P) (1 - exp(-D/P)) for ER (a node outside the block
         is referenced unless none of the block's N/P rows links to it); measured 0.500 N and
         0.750 N at P = 2 and 4 (bench/scaling_bytes.sh, N = 10^5, D = 100), 0.505 N and 0.760 N
         for Chung-Lu alpha = 2.5 of the same mean degree
  bw     bytes per second one rank imports (assumed: 12.5e9, a 100 Gb/s link per node shared by
         its ranks is less; pass --bandwidth)
  alpha  seconds per message (assumed 1.5e-6, an MPI latency across nodes; pass --latency); an
         ER row block references nodes of every other rank, so a rank receives P - 1 messages

Each evaluation imports 16 bytes ([cos, sin] as doubles) per ghost and replica. Prints, for
N = 10^6 .. 10^9 and D = 100: compute and import seconds per step per rank, their ratio, and
the ghost table per rank in GB (what a rank must hold besides its rows).
Usage: bench/scaling_model.py [--rate R] [--bandwidth B] [--degree D]
"""
import argparse
import math


def ghosts(n, d, p):
    return n * (1 - 1 / p) * (1 - math.exp(-d / p))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rate", type=float, default=0.35e9)
    ap.add_argument("--bandwidth", type=float, default=12.5e9)
    ap.add_argument("--degree", type=float, default=100.0)
    ap.add_argument("--latency", type=float, default=1.5e-6)
    a = ap.parse_args()
    d = a.degree
    print("%-6s %6s %12s %12s %10s %14s" % ("N", "P", "compute s", "import s", "import/cmp",
                                           "table GB/rank"))
    for n in (1e6, 1e7, 1e8, 1e9):
        stops = None
        for p in (1, 2, 4, 16, 64, 256, 1024, 4096):
            compute = n * d / p / a.rate
            imported = 16 * ghosts(n, d, p) / a.bandwidth + (p - 1) * a.latency
            table = 16 * (n / p + ghosts(n, d, p)) / 1e9
            if stops is None and imported >= compute:
                stops = p
            print("%-6.0e %6d %12.4g %12.4g %10.3g %14.3g" % (n, p, compute, imported,
                                                             imported / compute, table))
        print("# N = %.0e: import (bytes + latency) %s" % (
            n, "reaches compute time by P = %d" % stops if stops else "stays below compute"))


if __name__ == "__main__":
    main()
