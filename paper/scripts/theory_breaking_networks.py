"""Simulation against the self-consistent theory on networks that break its assumptions (not a
figure of the paper; where each method fails): <R>_t (bars, with SEM) and
eq:rSigmaBesselMain at each run's conserved energy and momentum (markers) at K/K_c = 1.5 and 3,
for an ER control, two weakly linked communities, two disconnected communities and a star.
From verification_theory_breaking_networks."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "theory_breaking_networks")
    names = r.note_json("networks")
    rows = r.table("gaps")
    per = len(rows) // len(names)
    hmfdata.style()
    fig, ax = plt.subplots(figsize=(8.0, 3.8))
    width = 0.8 / per
    for j in range(per):
        # rows: per network (in the order of names) and K
        R, sem = rows["<R>_t"][j::per], rows["SEM"][j::per]
        theory, ratio = rows["theory at the runs' (E, P)"][j::per], rows["K/K_c"][j::per]
        x = np.arange(len(names)) + (j - (per - 1) / 2) * width
        ax.bar(x, R, width, yerr=sem, color=f"C{j}", alpha=0.6,
               label=f"simulation, K/K_c = {ratio[0]:g}")
        ax.plot(x, theory, "k_", ms=14, mew=2,
                label="theory at the run's (E, P)" if j == 0 else None)
        for xi, sim, th in zip(x, R, theory):
            ax.annotate(f"{100 * (sim - th) / th:+.0f}%", (xi, max(sim, th) + 0.01),
                        ha="center", fontsize=6)
    ax.set_xticks(np.arange(len(names)))
    ax.set_xticklabels([n.replace(" (", "\n(") for n in names], fontsize=7)
    ax.set_ylabel("$\\langle R\\rangle_t$")
    ax.set_title("Simulation vs the theory, eq. (33), where its assumptions fail "
                 "(labels: relative gap)", fontsize=8)
    ax.legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "theory_breaking_networks", r.scale)


if __name__ == "__main__":
    main()
