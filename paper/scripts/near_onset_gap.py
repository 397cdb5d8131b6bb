"""The near-onset gap (beyond the paper). Gaussian momenta, sigma0^2 = 0.12, from the
incoherent start at 1.1, 1.2 and 1.5 K_c. Top row: the complete graph K_N; bottom row: ER with
degree 100. Columns 1-3: the replica mean R(t) for each N (log time) with eq:rSigmaBesselMain at
the runs' own E and P (dashed, same colour) and the paper's averaging window [500, 1000] (grey).
Column 4: the deficit R_th - <R> (replica mean +- se) in the paper's window (open) and over the
last fifth of the run (filled) against N: it grows with N on K_N and not on ER at fixed degree.
From verification_near_onset_gap."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "near_onset_gap")
    g = r.table("gaps")
    hmfdata.style()
    xs = sorted(set(np.round(g["K/K_c"], 6)))
    fig, axes = plt.subplots(2, 4, figsize=(14, 6.5))
    networks = [(1.0, "K_N", "KN"), (0.0, "ER, d = 100", "ER")]
    for row, (complete, label, prefix) in enumerate(networks):
        mine = g["complete"] == complete
        sizes = sorted(set(g["N"][mine]))
        for k, x in enumerate(xs):
            ax = axes[row, k]
            ax.axvspan(500, 1000, color="0.9")
            for i, n in enumerate(sizes):
                s = r.table(f"{prefix}_N{int(n)}_x{k}")
                ax.plot(s["t"], s["R replica mean"], "-", lw=0.8, color=f"C{i}",
                        label=f"N = {int(n)}")
                at = mine & (g["N"] == n) & (np.abs(g["K/K_c"] - x) < 1e-6)
                ax.axhline(g["R_th"][at][0], color=f"C{i}", lw=0.8, ls="--")
            ax.set(xscale="log", xlabel="t", ylabel="replica mean R",
                   title=f"{label}, K/K_c = {x:.2f}")
            ax.legend(fontsize=7)
        ax = axes[row, 3]
        for k, x in enumerate(xs):
            at = mine & (np.abs(g["K/K_c"] - x) < 1e-6)
            ax.errorbar(g["N"][at], -g["gap paper window"][at], yerr=g["gap paper window se"][at],
                        fmt="o--", capsize=3, color=f"C{k}", mfc="none",
                        label=f"{x:.2f} K_c, t in (500, 1000]")
            ax.errorbar(g["N"][at], -g["gap late"][at], yerr=g["gap late se"][at], fmt="o-",
                        capsize=3, color=f"C{k}", label=f"{x:.2f} K_c, last fifth")
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.set(xscale="log", xlabel="N", ylabel="R_th(E, P) - <R>",
               title=f"{label}: deficit below the theory")
        ax.legend(fontsize=6)
    fig.suptitle("Near onset: does <R> reach the self-consistent theory, eq. (33), and when?")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "near_onset_gap", r.scale)


if __name__ == "__main__":
    main()
