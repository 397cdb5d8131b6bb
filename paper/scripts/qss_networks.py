"""The water-bag QSS on networks (beyond the paper): the start of qss_lifetime
(sigma0^2 = 0.38, K lambda / N = 1) on random regular graphs (RR), ER and the complete graph K_N.
Left: the life against N at d = 20 (RR, ER) and at d = N - 1 (K_N). Middle: the life against the
mean degree at fixed N, K_N as d = N - 1, with K_N's fitted law at N = d + 1 (dotted). Right: the
replica mean R(t) of the d sweep on RR (block means), with R_th (dotted) and the lives (dashed).
From verification_qss_networks."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata

NAMES = {0: "random regular", 1: "ER", 2: "K_N (d = N - 1)"}
MARKERS = {0: "o", 1: "s", 2: "^"}


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "qss_networks")
    lives = r.table("lives")
    plan = r.table("plan")
    sweep_n, sweep_d = float(plan["N of the d sweep"]), float(plan["d of the N sweep"])
    fam, n, d = lives["family (0 RR, 1 ER, 2 K_N)"], lives["N"], lives["d"]
    hmfdata.style()
    fig, axes = plt.subplots(1, 3, figsize=(13.5, 4.0))
    for f in (0, 1, 2):
        on_n = (fam == f) & ((d == sweep_d) | (f == 2))
        order = np.argsort(n[on_n])
        axes[0].errorbar(n[on_n][order], lives["life"][on_n][order],
                         yerr=lives["life se"][on_n][order], fmt=MARKERS[f] + "-", capsize=3,
                         color=f"C{f}", label=NAMES[f] + ("" if f == 2 else f", d = {sweep_d:.0f}"))
        on_d = (fam == f) & (n == sweep_n)
        order = np.argsort(lives["mean degree"][on_d])
        axes[1].errorbar(lives["mean degree"][on_d][order], lives["life"][on_d][order],
                         yerr=lives["life se"][on_d][order], fmt=MARKERS[f] + "-", capsize=3,
                         color=f"C{f}", label=NAMES[f])
    fit = r.table("exponents")
    grid = np.geomspace(lives["mean degree"].min() * 0.8, sweep_n, 40)
    prefactor, slope = float(fit["K_N log prefactor"][0]), float(fit["K_N vs N"][0])
    law = np.exp(prefactor + slope * np.log(grid + 1))
    axes[1].plot(grid, law, ":", color="C2", lw=1, label=f"K_N's law at N = d + 1: N^{slope:.2f}")
    axes[0].set(xscale="log", yscale="log", xlabel="N", ylabel="QSS life (half-way passage)",
                title="life against N")
    axes[1].set(xscale="log", yscale="log", xlabel="mean degree",
                title=f"life against d at N = {sweep_n:.0f}")
    for ax in axes[:2]:
        ax.legend(fontsize=7)
    shown = [(i, 0) for i in np.flatnonzero((fam == 0) & (n == sweep_n))]
    shown += [(i, 2) for i in np.flatnonzero((fam == 2) & (n == sweep_n))]
    for colour, (i, f) in enumerate(sorted(shown, key=lambda s: d[s[0]])):
        prefix = "RR" if f == 0 else "KN"
        s = r.table(f"{prefix}_N{int(n[i])}_d{int(d[i])}")
        axes[2].plot(s["t"], s["R replica mean"], "-", lw=0.8, color=f"C{colour + 3}",
                     label=f"{'RR' if f == 0 else 'K_N'} d = {int(d[i])}")
        axes[2].axvline(lives["life"][i], color=f"C{colour + 3}", lw=0.8, ls="--")
        axes[2].axhline(lives["R_th"][i], color=f"C{colour + 3}", lw=0.5, ls=":")
    axes[2].set(xscale="log", xlabel="t", ylabel="replica mean R",
                title=f"R(t) at N = {sweep_n:.0f}")
    axes[2].legend(fontsize=7)
    fig.suptitle("Water-bag quasi-stationary state on networks (sigma0^2 = 0.38, K lambda / N = 1)")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "qss_networks", r.scale)


if __name__ == "__main__":
    main()
