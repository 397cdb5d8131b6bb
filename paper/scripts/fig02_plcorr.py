"""Fig. PLcorr: <R>_t against K (a) and lambda K (b) for a scale-free network (alpha = 2.5) and
two rewired versions of higher degree correlation rho (eq:rhodef).

Reads onset_rewired.h5 (verification/onset_rewired.cpp). Error bars: the larger of the replica
spread and the batch-means SEM of the time average, over sqrt(replicas). Dashed: the
self-consistent theory (eq:rSigmaBesselMain) of each network; dash-dotted: the same theory at the
energy and momentum the sweep had at each K (onset_sweep.hpp); thin vertical lines: the measured
onsets; dotted: lambda K_c = 2 sigma0^2 N (eq:criticalKFirstOrder).
"""
import matplotlib.pyplot as plt

import hmfdata

args = hmfdata.arguments(__doc__)
hmfdata.style()
r = hmfdata.load(args.data, "onset_rewired")
protocol = r.note_json("protocol")
scale_ref = 2 * protocol["sigma0"] ** 2 * protocol["N"]
K, R, err = r.series("sf_K"), r.series("sf_R"), r.series("sf_R_err")
theory, lam, x_on = r.series("sf_R_theory"), r.series("sf_lambda"), r.series("sf_x_on")
theory_ep = r.data.get("sf_R_theory_ep")  # the theory at the sweep's own (E, P), dotted
labels = r.note_json("sf_labels")

fig, (a, b) = plt.subplots(1, 2)
for i, label in enumerate(labels):
    color = f"C{i}"
    a.errorbar(K[i], R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8, color=color, label=label)
    b.errorbar(lam[i] * K[i], R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8, color=color,
               label=f"{label}, $\\lambda$ = {lam[i]:.1f}")
    b.plot(lam[i] * K[i], theory[i], "--", lw=0.7, color=color)
    if theory_ep is not None:
        b.plot(lam[i] * K[i], theory_ep[i], "-.", lw=0.8, color=color)
    b.axvline(x_on[i] * scale_ref, color=color, lw=0.5, alpha=0.6)
b.axvline(scale_ref, color="k", lw=0.8, ls=":", label="$\\lambda K_c = 2\\sigma_0^2 N$")
a.set(xlabel="$K$", ylabel="$\\langle R\\rangle_t$", title="(a) vs $K$")
a.legend(loc="upper left")
b.set(xlabel="$\\lambda K$", ylabel="$\\langle R\\rangle_t$", title="(b) vs $\\lambda K$")
b.legend(loc="upper left")
fig.suptitle(f"Fig. PLcorr: rewired scale-free, N = {protocol['N']}, "
             f"$\\sigma_0$ = {protocol['sigma0']}")
fig.tight_layout()
hmfdata.save_figure(fig, args.out, "fig02_plcorr", r.scale)
