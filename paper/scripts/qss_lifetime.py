"""QSS of the all-to-all HMF (beyond the paper): homogeneous water-bag at U = 0.69
on K_N. Left: the replica mean R(t) for each N, the half-way level between its start and the
canonical M_eq (dotted) and the measured life (vertical). Right: the life against N with the
fitted power law and the literature's N^1.7 (Yamaguchi et al. 2004) through the middle point.
From verification_qss_lifetime."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "qss_lifetime")
    lives = r.table("lives")
    hmfdata.style()
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 4.0))
    for i, n in enumerate(lives["N"]):
        s = r.table(f"R_N{int(n)}")
        axes[0].plot(s["t"], s["R replica mean"], "-", lw=0.8, color=f"C{i}", label=f"N = {int(n)}")
        axes[0].axvline(lives["life"][i], color=f"C{i}", lw=0.8, ls="--")
        axes[0].axhline(lives["M_eq"][i], color=f"C{i}", lw=0.5, ls=":")
    axes[0].set(xscale="log", xlabel="t", ylabel="replica mean R",
                title="water-bag at U = 0.69: QSS then relaxation")
    axes[0].legend(fontsize=7)
    n = lives["N"]
    axes[1].errorbar(n, lives["life"], yerr=lives["life se"], fmt="o", capsize=3, color="C3",
                     label="life (half-way passage)")
    fit = r.table("exponent")
    slope, slope_se = fit["exponent"], fit["exponent se"]
    # The driver's weighted fit, drawn through the weighted mean point of ln N, ln life.
    w = (lives["life"] / lives["life se"]) ** 2
    x0 = np.sum(w * np.log(n)) / np.sum(w)
    y0 = np.sum(w * np.log(lives["life"])) / np.sum(w)
    grid = np.geomspace(n.min() * 0.8, n.max() * 1.25, 20)
    axes[1].plot(grid, np.exp(y0 + slope * (np.log(grid) - x0)), "-", color="C3", lw=1,
                 label=f"fit: N^({slope:.2f} +- {slope_se:.2f})")
    mid = len(n) // 2
    axes[1].plot(grid, lives["life"][mid] * (grid / n[mid]) ** 1.7, "--", color="k", lw=1,
                 label="N^1.7 (Yamaguchi et al.)")
    axes[1].set(xscale="log", yscale="log", xlabel="N", ylabel="life", title="QSS life")
    axes[1].legend(fontsize=7)
    fig.suptitle("Quasi-stationary state of the all-to-all HMF (K_N, water-bag, U = 0.69)")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "qss_lifetime", r.scale)


if __name__ == "__main__":
    main()
