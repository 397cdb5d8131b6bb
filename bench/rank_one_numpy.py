#!/usr/bin/env python3
"""The yardstick for the complete graph's rank-one force (docs/performance.md "The complete
graph against numpy"): a plain numpy leap-frog of the HMF on K_N without self-loops, vectorised
over the replicas, the same system `hmfnet simulate` integrates there.

  theta' = p,  p' = K g,  g_n = (1/N) Im(Z e^{-i theta_n}) - (1/N) Im(e^{i theta_n} e^{-i theta_n})
  Z = sum_m e^{i theta_m}

(the self term is zero, so g_n = (Zs cos theta_n - Zc sin theta_n) / N), the kick-drift-kick
leap-frog of src/dynamics/integrator.cpp, water-bag momenta (uniform on omega +- sqrt(3) sigma0,
theta uniform on [0, 2 pi)) and K = K/K_c x 6 sigma0^2 N / lambda with lambda = N - 1. The arrays
are replicas x N, C order, so every sum runs along contiguous memory, and every update is in
place (no temporaries beyond sin and cos): what a careful numpy user writes.
Prints one JSON object: ns per rotor, replica and step (the best of --repeats timed runs).
Usage: bench/rank_one_numpy.py --n 400 --replicas 16 --h 0.1 --steps 2000 [--repeats 3]
"""
import argparse
import json
import time

import numpy as np


def leapfrog(theta, p, K, n, h, steps):
    c = np.empty_like(theta)
    s = np.empty_like(theta)
    g = np.empty_like(theta)
    tmp = np.empty_like(theta)

    def force():
        np.cos(theta, out=c)
        np.sin(theta, out=s)
        zc = c.sum(axis=1, keepdims=True)
        zs = s.sum(axis=1, keepdims=True)
        np.multiply(c, zs, out=g)
        np.multiply(s, zc, out=tmp)
        np.subtract(g, tmp, out=g)
        np.multiply(g, K / n, out=g)

    force()
    for _ in range(steps):
        np.multiply(g, 0.5 * h, out=tmp)
        p += tmp
        np.multiply(p, h, out=tmp)
        theta += tmp
        force()
        np.multiply(g, 0.5 * h, out=tmp)
        p += tmp


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, required=True)
    ap.add_argument("--replicas", type=int, default=16)
    ap.add_argument("--h", type=float, default=0.1)
    ap.add_argument("--steps", type=int, required=True)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--K-over-Kc", dest="k_over_kc", type=float, default=1.5)
    a = ap.parse_args()
    sigma0, omega = 0.35, 6.0
    K = a.k_over_kc * 6.0 * sigma0**2 * a.n / (a.n - 1)
    rng = np.random.default_rng(1)
    best = float("inf")
    for _ in range(a.repeats):
        theta = rng.uniform(0.0, 2.0 * np.pi, (a.replicas, a.n))
        p = omega + np.sqrt(3.0) * sigma0 * rng.uniform(-1.0, 1.0, (a.replicas, a.n))
        t0 = time.perf_counter()
        leapfrog(theta, p, K, a.n, a.h, a.steps)
        best = min(best, time.perf_counter() - t0)
    cells = a.n * a.replicas * a.steps
    print(json.dumps({"n": a.n, "replicas": a.replicas, "steps": a.steps, "seconds": best,
                      "ns_per_rotor_replica_step": best / cells * 1e9}))


if __name__ == "__main__":
    main()
