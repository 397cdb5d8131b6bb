"""Fig. ERstdP: <R>_t on one ER network against K (a) and K / sigma0^2 (b) for several sigma0.

Reads onset_sigma0.h5 (verification/onset_sigma0.cpp). Error bars: the larger of the replica
spread and the batch-means SEM of the time average, over sqrt(replicas). Dashed: the
self-consistent theory (eq:rSigmaBesselMain); dotted: the same theory at the sweep's own energy
and momentum at each K (onset_sweep.hpp); thin vertical lines: the measured onsets; dotted:
K_c / sigma0^2 = 2 N / lambda (eq:criticalKFirstOrder).
"""
import matplotlib.pyplot as plt

import hmfdata

args = hmfdata.arguments(__doc__)
hmfdata.style()
r = hmfdata.load(args.data, "onset_sigma0")
protocol = r.note_json("protocol")
K, R, err = r.series("er_K"), r.series("er_R"), r.series("er_R_err")
theory, lam, x_on = r.series("er_R_theory"), r.series("er_lambda"), r.series("er_x_on")
theory_ep = r.data.get("er_R_theory_ep")  # the theory at the sweep's own (E, P), dotted
sigma0 = r.series("er_sigma0")
labels = r.note_json("er_labels")
ref = 2 * protocol["N"] / lam[0]  # K_c / sigma0^2

fig, (a, b) = plt.subplots(1, 2)
for i, label in enumerate(labels):
    color = f"C{i}"
    s2 = sigma0[i] ** 2
    a.errorbar(K[i], R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8, color=color, label=label)
    b.errorbar(K[i] / s2, R[i], yerr=err[i], fmt="o-", ms=3, lw=0.8, color=color, label=label)
    b.plot(K[i] / s2, theory[i], "--", lw=0.7, color=color)
    if theory_ep is not None:
        b.plot(K[i] / s2, theory_ep[i], ":", lw=0.9, color=color)
    b.axvline(x_on[i] * ref, color=color, lw=0.5, alpha=0.6)
b.axvline(ref, color="k", lw=0.8, ls=":", label="$K_c/\\sigma_0^2 = 2N/\\lambda$")
a.set(xlabel="$K$", ylabel="$\\langle R\\rangle_t$", title="(a) vs $K$")
a.legend(loc="upper left")
b.set(xlabel="$K/\\sigma_0^2$", ylabel="$\\langle R\\rangle_t$",
      title="(b) vs $K/\\sigma_0^2$")
b.legend(loc="upper left")
fig.suptitle(f"Fig. ERstdP: ER N = {protocol['N']}, q = {protocol['q']}, "
             f"$\\lambda$ = {lam[0]:.1f}, $\\Omega$ = {protocol['omega']}")
fig.tight_layout()
hmfdata.save_figure(fig, args.out, "fig03_erstdp", r.scale)
