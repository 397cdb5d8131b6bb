"""Fig. ERPLnet: <R>_t against K and lambda K for ER (a, b) and scale-free (c, d) networks.

Reads onset_er_sf.h5 (verification/onset_er_sf.cpp). Error bars: the larger of the replica
spread and the batch-means SEM of the time average, over sqrt(replicas). Dashed: the
self-consistent theory (eq:rSigmaBesselMain) of each network; dotted: the same theory at the energy
and momentum the sweep actually had at each K (onset_sweep.hpp); thin vertical lines in (b), (d):
the measured onsets lambda K_on.
"""
import matplotlib.pyplot as plt

import hmfdata

args = hmfdata.arguments(__doc__)
hmfdata.style()
r = hmfdata.load(args.data, "onset_er_sf")
protocol = r.note_json("protocol")
scale_ref = 2 * protocol["sigma0"] ** 2 * protocol["N"]  # lambda K_c of eq:criticalKFirstOrder

fig, axes = plt.subplots(2, 2, figsize=(9.0, 7.0))
for row, family in enumerate(("er", "sf")):
    K, R, err = r.series(f"{family}_K"), r.series(f"{family}_R"), r.series(f"{family}_R_err")
    theory, lam = r.series(f"{family}_R_theory"), r.series(f"{family}_lambda")
    x_on = r.series(f"{family}_x_on")
    theory_ep = r.series(f"{family}_R_theory_ep") if f"{family}_R_theory_ep" in r.data else None
    labels = r.note_json(f"{family}_labels")
    for i, label in enumerate(labels):
        color = f"C{i}"
        axes[row, 0].errorbar(K[i], R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8, color=color,
                              label=label)
        axes[row, 1].errorbar(lam[i] * K[i], R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8,
                              color=color, label=f"{label}, $\\lambda$ = {lam[i]:.1f}")
        axes[row, 1].plot(lam[i] * K[i], theory[i], "--", lw=0.7, color=color)
        if theory_ep is not None:
            axes[row, 1].plot(lam[i] * K[i], theory_ep[i], ":", lw=0.9, color=color)
        axes[row, 1].axvline(x_on[i] * scale_ref, color=color, lw=0.5, alpha=0.6)
    axes[row, 1].axvline(scale_ref, color="k", lw=0.8, ls=":",
                         label="$\\lambda K_c = 2\\sigma_0^2 N$")
    name = "Erdos-Renyi" if family == "er" else "scale-free"
    axes[row, 0].set(xlabel="$K$", ylabel="$\\langle R\\rangle_t$", title=f"{name}: vs $K$")
    axes[row, 1].set(xlabel="$\\lambda K$", ylabel="$\\langle R\\rangle_t$",
                     title=f"{name}: vs $\\lambda K$ (dashed, dotted: theory; lines: onsets)")
    axes[row, 1].legend(loc="upper left")
fig.suptitle(f"Fig. ERPLnet: N = {protocol['N']}, $\\sigma_0$ = {protocol['sigma0']}, "
             f"$\\Omega$ = {protocol['omega']}")
fig.tight_layout()
hmfdata.save_figure(fig, args.out, "fig01_erplnet", r.scale)
