"""Fig. maxSynchrony: the K -> infinity order parameter R_hat of scale-free networks against alpha.

Reads max_synchrony_alpha.h5 (verification/max_synchrony_alpha.cpp: eq:KtoInfinity and eq:rd,
N = 10^4, seed means) and large_k_simulation.h5 (verification/large_k_simulation.cpp: <R>_t at
K = N from the incoherent state, network seed 1). Red triangles: the iteration of eq:KtoInfinity;
blue circles: simulated <R>_t with the batch-means SEM as error bars; dashed: eq:rd. Right panel:
the same simulations relative to R_hat of their own networks, beside the paper's "about 1% below"
and the finite-K theory eq:rSigmaBesselMain at the simulated K (the checked reference).
"""
import matplotlib.pyplot as plt

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    theory = hmfdata.load(args.data, "max_synchrony_alpha")
    sim = hmfdata.load(args.data, "large_k_simulation")
    alpha, R_hat, rd = theory.series("alpha"), theory.series("R_hat"), theory.series("rd")
    p = sim.table("points")
    a_sim, R_sim, sem, R_hat_sim, R_K = (p[c] for c in ("alpha", "R_sim", "R_sim SEM", "R_hat",
                                                        "R(K) (E, P)"))
    ratio = p["K"] / p["K_c"]
    network = sim.notes.get("network", "")

    fig, (left, right) = plt.subplots(1, 2)
    left.plot(alpha, rd, "k--", lw=1.0, label="degree approximation, eq. (42)")
    left.plot(alpha, R_hat, "^", color="tab:red", ms=7, label="R_hat, eq. (39) (N = 10^4)")
    left.errorbar(a_sim, R_sim, yerr=sem, fmt="o", color="tab:blue", mfc="none", capsize=3,
                  label=f"<R>_t, K/K_c = {ratio.min():.0f}-{ratio.max():.0f}")
    left.set_xlabel("alpha")
    left.set_ylabel("R_hat, <R>_t")
    left.set_ylim(0.5, 0.75)
    left.set_title("R_hat nearly independent of alpha")
    left.legend(loc="upper right")

    right.axhline(0.0, color="0.5", lw=0.8)
    right.axhline(-1.0, color="tab:red", lw=0.8, ls=":", label="paper: about 1% below")
    right.errorbar(a_sim, 100 * (R_sim / R_hat_sim - 1), yerr=100 * sem / R_hat_sim, fmt="o",
                   color="tab:blue", mfc="none", capsize=3, label="<R>_t")
    right.plot(a_sim, 100 * (R_K / R_hat_sim - 1), "x", color="k", ms=6,
               label="theory eq. (33) at K (run's E, P)")
    right.set_xlabel("alpha")
    right.set_ylabel("100 (R / R_hat - 1)  [%]")
    right.set_title("relative to R_hat of the simulated network")
    right.legend(loc="lower right")
    fig.suptitle(f"Fig. maxSynchrony ({network})", fontsize=8)
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "fig10_max_synchrony", sim.scale)


if __name__ == "__main__":
    main()
