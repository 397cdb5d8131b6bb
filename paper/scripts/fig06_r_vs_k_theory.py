"""Fig. R_vs_K_theoretical: simulated <R>_t against eq:rSigmaBesselMain and eq:globalOrderRInDeltaK.

Reads simulation_vs_theory.h5 (verification/simulation_vs_theory.cpp). Panels (a) ER q = 0.01,
sigma0^2 = 0.12 and (b) scale-free alpha = 2.8 (Table II; the caption says 2.5), sigma0^2 = 1.
Circles: <R>_t from the incoherent start at each K, mean over replicas, error bars = replica sd
(larger than the batch-means SEM, which is drawn as the inner cap); squares: the paper's sweep (17 K
from 0 to 4.5 K_c, each continuing from the state the previous one left; plus signs: the theory
at each of its segments' E and P, which the swept state's lower energy lifts above the paper's
line); crosses: the theory at each run's own E and P (the checked reference);
solid line: eq:rSigmaBesselMain at the nominal sigma0 (the paper's line); dashed: G sqrt(dK/K_c).
"""
import matplotlib.pyplot as plt

import hmfdata


def panel(ax, result, name, title):
    points = result.table(f"{name}_points")
    curve = result.table(f"{name}_theory")
    ax.plot(curve["K/K_c"], curve["theory"], "k-", lw=1.2,
            label="self-consistent theory, eq. (33) (sigma0)")
    ax.plot(curve["K/K_c"], curve["G sqrt(dK/K_c)"], "r--", lw=1.0, label="G sqrt(dK/K_c)")
    x, R = points["K/K_c"], points["R"]
    ax.errorbar(x, R, yerr=points["replica sd"], fmt="o", color="tab:blue",
                capsize=3, label="simulation (replica sd)")
    ax.errorbar(x, R, yerr=points["SEM"], fmt="none", color="navy", capsize=6)
    sweep = result.table(f"{name}_sweep")
    ax.errorbar(sweep["K/K_c"], sweep["R"], yerr=sweep["replica sd"], fmt="s-", ms=4, lw=0.6,
                color="tab:orange", capsize=2,
                label="sweep, continued state (the paper's protocol)")
    swept = sweep["K/K_c"] > 1.0
    ax.plot(sweep["K/K_c"][swept], sweep["theory (E, P)"][swept], "+", color="k", ms=7,
            label="theory at the sweep's (E, P)")
    above = x > 1.0
    ax.plot(x[above], points["theory (E, P)"][above], "x", color="k", ms=6,
            label="theory at the run's (E, P)")
    ax.axvline(1.0, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("K / K_c")
    ax.set_ylabel("<R>_t")
    ax.set_ylim(0, 0.8)
    ax.set_xlim(-0.1, 4.7)
    ax.set_title(title)
    ax.legend(loc="upper left")


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    result = hmfdata.load(args.data, "simulation_vs_theory")
    fig, axes = plt.subplots(1, 2)
    panel(axes[0], result, "ER", "(a) Erdos-Renyi, q = 0.01, sigma0^2 = 0.12")
    panel(axes[1], result, "SF", "(b) scale-free, alpha = 2.8, sigma0^2 = 1")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "fig06_r_vs_k_theory", result.scale)


if __name__ == "__main__":
    main()
