"""Fig. histPsinMinusPsi1: histogram of psi_n(t) - psi_1(t) over all n, sampled once per time unit
(Assumption 1, common phase), normalised as a probability density on [-pi, pi).

Reads assumptions_locked_state.h5 (verification/assumptions_locked_state.cpp): phase_histogram,
the counts in equal bins over [-pi, pi) (ER N = 10^3, q = 0.01, K = 3 K_c; psi_1 is node 0).
Left: linear density; right: the same on a log scale, where the tails (phase slips) show.
"""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    result = hmfdata.load(args.data, "assumptions_locked_state")
    counts = result.series("phase_histogram")
    edges = np.linspace(-np.pi, np.pi, counts.size + 1)
    width = edges[1] - edges[0]
    density = counts / (counts.sum() * width)
    centres = 0.5 * (edges[1:] + edges[:-1])
    resultant = abs(np.sum(counts * np.exp(1j * centres))) / counts.sum()
    fig, (left, right) = plt.subplots(1, 2)
    for ax, log in ((left, False), (right, True)):
        ax.stairs(density, edges, fill=True, color="tab:blue", alpha=0.8,
                  label=f"{counts.sum():.3g} samples, {counts.size} bins")
        ax.axhline(1.0 / (2.0 * np.pi), color="k", ls=":", lw=1.0, label="uniform 1/(2 pi)")
        ax.set_xlim(-np.pi, np.pi)
        ax.set_xlabel("psi_n - psi_1  [rad]")
        ax.set_ylabel("probability density")
        if log:
            ax.set_yscale("log")
            ax.set_title("log scale: tails are phase slips")
        else:
            ax.set_title(f"mean resultant length {resultant:.3f}")
        ax.legend(loc="upper left")
    fig.suptitle("Fig. histPsinMinusPsi1: psi_n - psi_1, sampled every time unit")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "fig08_hist_psin", result.scale)


if __name__ == "__main__":
    main()
