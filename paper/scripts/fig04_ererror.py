"""Fig. ERerror: <R>_t at K = K_c / 2 on ER networks against N at q = 0.01 (a) and against q at
fixed N (b), log-log.

Reads finite_size_floor.h5 (verification/finite_size_floor.cpp). Error bars: the larger of the
replica spread and the batch-means SEM, over sqrt(replicas). Solid: the weighted fit (slope +-
its standard error in the legend); dashed: slope -1/2 through the data's weighted centre, the
paper's (qN)^{-1/2}.
"""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import NullFormatter

import hmfdata

args = hmfdata.arguments(__doc__)
hmfdata.style()
r = hmfdata.load(args.data, "finite_size_floor")
protocol = r.note_json("protocol")

fig, axes = plt.subplots(1, 2)
for ax, key, xlabel, title in (
        (axes[0], "vs_N", "$N$", f"(a) q = {protocol['q']}"),
        (axes[1], "vs_q", "$q$", f"(b) N = {protocol['N']}")):
    x, R, err = r.series(f"{key}_x"), r.series(f"{key}_R"), r.series(f"{key}_R_err")
    fit = r.table(f"{key}_fit")
    slope, intercept, se, chi2 = (fit[c] for c in ("slope", "intercept", "slope se", "chi2/dof"))
    ax.errorbar(x, R, yerr=err, fmt="o", ms=4, color="C0", label="simulation")
    grid = np.geomspace(x.min(), x.max(), 50)
    ax.plot(grid, np.exp(intercept) * grid ** slope, "-", color="C0", lw=0.8,
            label=f"fit: slope {slope:.3f} $\\pm$ {se:.3f}")
    w = (R / err) ** 2
    centre = np.sum(w * (np.log(R) + 0.5 * np.log(x))) / np.sum(w)
    ax.plot(grid, np.exp(centre) * grid ** -0.5, "--", color="k", lw=0.8, label="slope $-1/2$")
    ax.set(xscale="log", yscale="log", xlabel=xlabel, ylabel="$\\langle R\\rangle_t$",
           title=title)
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.legend()
fig.suptitle("Fig. ERerror: finite-size floor at $K = K_c/2$")
fig.tight_layout()
hmfdata.save_figure(fig, args.out, "fig04_ererror", r.scale)
