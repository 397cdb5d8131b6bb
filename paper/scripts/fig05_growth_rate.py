"""Fig. growthRate: log R(t) from the incoherent state against the slope gamma of eq:gammaKKc.

Reads growth_rate.h5 (verification/growth_rate.cpp). Left: R(t) of every replica for each K/K_c
(solid), the dashed lines have the slope gamma of eq:gammaKKc and pass through the middle of the
fitted window of replica 0 (marked bold). Right: fitted slope (mean over replicas, 3 SEM error
bars) and the theory against K/K_c.
"""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    result = hmfdata.load(args.data, "growth_rate")
    summary = result.table("summary")
    fig, (left, right) = plt.subplots(1, 2)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for x, gamma, color in zip(summary["K/K_c"], summary["gamma eq:gammaKKc"], colors):
        label = f"{x:g}"
        table = result.table(f"R_K{label}")
        times = table["t"]
        replicas = [c for c in table.columns if c.startswith("R replica ")]
        for b, column in enumerate(replicas):
            left.semilogy(times, table[column], color=color, lw=0.8, alpha=0.6,
                          label=f"K/K_c = {label}" if b == 0 else None)
        fit = result.table(f"fit_K{label}_r0")
        t1, t2 = fit["t1"], fit["t2"]
        R0 = table["R replica 0"]
        inside = (times >= t1) & (times <= t2)
        left.semilogy(times[inside], R0[inside], color=color, lw=2.2)
        tm = 0.5 * (t1 + t2)
        rm = np.interp(tm, times, R0)
        t = np.linspace(max(0.0, tm - 2.0 / gamma), tm + 1.5 / gamma, 50)
        left.semilogy(t, rm * np.exp(gamma * (t - tm)), "--", color=color, lw=1.0)
    left.set_xlabel("t")
    left.set_ylabel("R(t)")
    left.set_ylim(0.01, 1.0)
    left.legend(loc="lower right")
    left.set_title("R(t), thick: fit window (replica 0); dashed: slope gamma of eq. (14)")
    xs = summary["K/K_c"]
    right.plot(xs, summary["gamma eq:gammaKKc"], "k-s", ms=4, label="gamma, eq. (14)")
    right.plot(xs, summary["gamma eq:lambdaHat sample"], "k:",
               label="eq. (12), the sample's momenta")
    right.errorbar(xs, summary["slope mean"], yerr=3 * summary["slope SEM"], fmt="o",
                   color="tab:blue", capsize=3, label="fitted slope (3 SEM over seeds)")
    right.set_xlabel("K / K_c")
    right.set_ylabel("growth rate")
    right.legend(loc="upper left")
    right.set_title("fit of log sqrt(R^2 - R(0)^2), floor to R_sat/2")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "fig05_growth_rate", result.scale)


if __name__ == "__main__":
    main()
