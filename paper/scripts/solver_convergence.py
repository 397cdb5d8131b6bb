"""Self-consistent solver near K_c (not a figure of the paper; where each method fails):
map evaluations to the relative residual 1e-10 against K/K_c - 1, for the accelerated solver
(solid) and the paper's plain fixed-point iteration (dashed; a missing point did not converge
within 4x the predicted count), on ER, SF and two-block networks (near-degenerate, disconnected,
bipartite). Dotted: the prediction ln(2 eps / tol) / (2 eps), eps = K/K_c - 1, of the plain
iteration's slow Perron mode (Jacobian eigenvalue 1 - 2 eps) from an O(1) error. From verification_solver_convergence."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "solver_convergence")
    names = r.note_json("networks")
    rows = r.table("counts")
    tol = r.table("constants")["tolerance"]
    per = len(rows) // len(names)
    hmfdata.style()
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 4.0))
    for i, name in enumerate(names):
        block = slice(i * per, (i + 1) * per)  # rows: per network, in the order of names

        def column(c):
            return rows[c][block]

        eps = column("eps = K/K_c - 1")
        axes[0].loglog(eps, column("accelerated evaluations"), "o-", ms=3, color=f"C{i}",
                       label=f"{name}: accelerated")
        axes[0].loglog(eps, column("plain evaluations"), "s--", ms=3, color=f"C{i}",
                       label=f"{name}: plain")
        axes[1].loglog(eps, column("accelerated seconds"), "o-", ms=3, color=f"C{i}")
        axes[1].loglog(eps, column("plain seconds"), "s--", ms=3, color=f"C{i}")
    grid = np.logspace(-4, 0, 50)
    axes[0].loglog(grid, np.log(2 * grid / tol) / (2 * grid), ":", color="k",
                   label="ln(2 eps / tol) / (2 eps)")
    axes[0].set(xlabel="$K/K_c - 1$", ylabel="map evaluations (sparse products)",
                title="iterations to residual 1e-10")
    axes[1].set(xlabel="$K/K_c - 1$", ylabel="wall seconds", title="time per solve")
    axes[0].legend(fontsize=6)
    fig.suptitle(f"Self-consistent solver near onset, N = {int(r.table('constants')['N'])}")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "solver_convergence", r.scale)


if __name__ == "__main__":
    main()
