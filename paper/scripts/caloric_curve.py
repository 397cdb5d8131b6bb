"""Antoni-Ruffo caloric curve on the complete graph (beyond the paper): the
long-time magnetisation <M>_t of microcanonical runs on K_N (A = 1 1^T, K = 1) from the incoherent
start, against the canonical M(U) (eq:rSigmaBesselMain on K_N: M = I1(M/T)/I0(M/T),
U = T/2 + (1 - M^2)/2, U_c = 3/4) and, above U_c, the finite-N floor
sqrt(pi T / (4 N (T - 1/2))), T = 2U - 1. Right: the deviations from the reference at each N
(below U_c: <M> - M_can; above: <M> / floor - 1). From verification_all_to_all_caloric_curve."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "all_to_all_caloric_curve")
    rows = r.table("deviations")
    curve = r.table("canonical")
    hmfdata.style()
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 4.0))
    axes[0].plot(curve["U"], curve["M"], "-", color="k", lw=1, label="canonical (N -> inf)")
    sizes = sorted(set(rows["N"]))
    grid = np.linspace(0.76, 1.0, 50)
    for i, n in enumerate(sizes):
        sel = rows["N"] == n
        axes[0].errorbar(rows["U"][sel], rows["M"][sel], yerr=rows["deviation se"][sel] *
                         np.where(rows["U"][sel] < 0.75, 1.0, rows["M reference"][sel]),
                         fmt="o", ms=4, capsize=2, color=f"C{i}", label=f"simulation N = {int(n)}")
        T = 2 * grid - 1
        axes[0].plot(grid, np.sqrt(np.pi * T / (4 * n * (T - 0.5))), "--", color=f"C{i}", lw=1,
                     label=f"finite-N floor N = {int(n)}")
        axes[1].errorbar(rows["U nominal"][sel] + 0.004 * (i - 0.5), rows["deviation"][sel],
                         yerr=rows["deviation se"][sel], fmt="o", ms=4, capsize=2, color=f"C{i}",
                         label=f"N = {int(n)}")
    axes[0].axvline(0.75, color="gray", lw=0.5)
    axes[0].set(xlabel="U (energy per rotor, Antoni-Ruffo units)", ylabel="M",
                title="caloric curve: <M>_t over the second half")
    axes[0].legend(fontsize=6)
    axes[1].axhline(0.0, color="k", lw=0.5)
    axes[1].axvline(0.75, color="gray", lw=0.5)
    axes[1].set(xlabel="U", ylabel="deviation",
                title="below U_c: <M> - M_can;  above: <M> / floor - 1")
    axes[1].legend(fontsize=7)
    fig.suptitle("All-to-all HMF on K_N: microcanonical runs against the canonical solution")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "caloric_curve", r.scale)


if __name__ == "__main__":
    main()
