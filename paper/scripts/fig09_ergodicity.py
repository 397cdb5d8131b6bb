"""Fig. ergodicityAssumption: one rotor's phase-space distribution against the single-rotor
Boltzmann density eq:gFunction (Assumption 2).

Reads boltzmann_single_rotor.h5 (verification/boltzmann_single_rotor.cpp): samples (theta_bar,
p_bar) of node 0 every record in [T1, T2] (theta_bar = theta - Psi(t), Psi the phase of the global
order parameter; p_bar = p - P/N), the reference marginals theory_theta and theory_p (g is their
product, for the measured and the self-consistent r_0) and named constants.
(a) g(theta, p; r_0) with the self-consistent r_0 of eq:rSigmaBesselMain on the grid of (b), (b) the
2-D histogram of all samples as a density, both on one colour scale; (c, d) the marginals against
the reference, with the chi-square verdicts of the driver (thinned samples).
"""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def verdict(result, start):
    for c in result.checks:
        if c["what"].startswith(start):
            return c["detail"].split(" (reject")[0]
    return ""


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    result = hmfdata.load(args.data, "boltzmann_single_rotor")
    samples = result.table("samples")
    tt, tp = result.table("theory_theta"), result.table("theory_p")
    const = result.table("constants")
    K, beta, r0, x, beta_fit, r_field, x_field = (const[c] for c in (
        "K", "beta", "r_0 self-consistent", "x = K beta r_0", "beta from var(p_bar)",
        "r_0 measured", "x with the measured r_0"))
    t1, t2 = const["T1"], const["T2"]
    sd = 1.0 / np.sqrt(beta)
    theta_edges = np.linspace(-np.pi, np.pi, 101)  # the paper's bin: 2 pi / 100 = 0.0628
    p_edges = np.linspace(-4.0 * sd, 4.0 * sd, 81)
    theta_s, p_s = samples["theta_bar"], samples["p_bar"]
    hist, _, _ = np.histogram2d(theta_s, p_s, bins=(theta_edges, p_edges), density=True)
    tc = 0.5 * (theta_edges[1:] + theta_edges[:-1])
    pc = 0.5 * (p_edges[1:] + p_edges[:-1])
    g = np.outer(np.interp(tc, tt["theta_bar"], tt["density (self-consistent r_0)"]),
                 np.interp(pc, tp["p_bar"], tp["density"]))
    vmax = max(g.max(), hist.max())
    fig, axes = plt.subplots(2, 2, figsize=(9.5, 7.5), constrained_layout=True)
    for ax, z, title in ((axes[0, 0], g, f"(a) Boltzmann density eq. (24), beta = {beta:.4g}, "
                                         f"r_0 = {r0:.4g}"),
                         (axes[0, 1], hist, f"(b) node 0: {len(samples)} samples, t in "
                                            f"[{t1:g}, {t2:g}]")):
        ax.grid(False)
        mesh = ax.pcolormesh(theta_edges, p_edges, z.T, vmin=0.0, vmax=vmax, cmap="viridis")
        ax.set_xlabel("theta_bar")
        ax.set_ylabel("p_bar")
        ax.set_title(title, fontsize=8)
    fig.colorbar(mesh, ax=axes[0, :].tolist(), label="density")
    ax = axes[1, 0]
    ax.hist(theta_s, bins=theta_edges, density=True, color="tab:blue", alpha=0.6,
            histtype="stepfilled",
            label="samples")
    ax.plot(tt["theta_bar"], tt["density (measured r_0)"], "k-", lw=1.2,
            label=f"exp(x cos)/(2 pi I0(x)), measured r_0 = {r_field:.4g}: x = {x_field:.3g}")
    ax.plot(tt["theta_bar"], tt["density (self-consistent r_0)"], "r--", lw=1.0,
            label=f"self-consistent r_0 = {r0:.4g}: x = {x:.3g}")
    ax.set_xlabel("theta_bar")
    ax.set_ylabel("density")
    ax.set_title("(c) measured r_0: " + verdict(result, "theta_bar marginal"), fontsize=7)
    ax.legend(loc="upper left")
    ax = axes[1, 1]
    ax.hist(p_s, bins=p_edges, density=True, color="tab:blue", alpha=0.6,
            histtype="stepfilled",
            label=f"samples (1/var = {beta_fit:.4g})")
    ax.plot(tp["p_bar"], tp["density"], "k-", lw=1.2,
            label=f"Gaussian, variance 1/beta = {1 / beta:.4g}")
    ax.set_xlim(p_edges[0], p_edges[-1])
    ax.set_xlabel("p_bar")
    ax.set_ylabel("density")
    ax.set_title("(d) " + verdict(result, "p_bar marginal"), fontsize=7)
    ax.legend(loc="upper left")
    fig.suptitle(f"Fig. ergodicityAssumption: ER N = 100, <d> = 10, K = {K:.4g} = 50 K_c "
                 "(paper: beta = 0.965, r_1 = 0.036)", fontsize=9)
    hmfdata.save_figure(fig, args.out, "fig09_ergodicity", result.scale)


if __name__ == "__main__":
    main()
