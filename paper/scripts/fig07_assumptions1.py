"""Fig. Assumptions1: (a) the local-field frequencies Omega_n of Assumption 1 relative to the
frame frequency Omega, with the rotor frequencies as a contrast; (b) the fluctuation ratio
Re<z_n e^{-i theta_bar_n}>_t / ||<r_n cos theta_bar_n>_t|| of Assumption 3 per node.

Reads assumptions_locked_state.h5 (verification/assumptions_locked_state.cpp): omega_relative
((Omega_n - Omega)/Omega of the local phases psi_n), rotor_omega_relative (the same for the rotor
phases theta_n), fluctuation_ratio, constants = {Omega, T1, T2, K}. (a) marks the driver's bound
2 pi / ((T2 - T1) Omega) (one phase slip per window) and the paper's 0.5%; the inset shows both
distributions on the rotors' scale. (b) marks 0.1 and the paper's maximum 0.16 (N = 10^4).
"""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def frequencies(ax, result):
    constants = result.table("constants")
    omega, t1, t2 = constants["Omega"], constants["T1"], constants["T2"]
    rel = 100.0 * result.series("omega_relative")
    rotor = 100.0 * result.series("rotor_omega_relative")
    bound = 100.0 * 2.0 * np.pi / ((t2 - t1) * omega)
    span = max(0.6, 1.2 * np.max(np.abs(rel)))
    ax.hist(rel, bins=np.linspace(-span, span, 301), color="tab:blue",
            label=f"local fields psi_n (N = {rel.size})")
    for sign in (-1, 1):
        ax.axvline(sign * bound, color="k", ls="--", lw=0.8,
                   label="bound 2 pi / ((T2 - T1) Omega)" if sign > 0 else None)
        ax.axvline(sign * 0.5, color="tab:red", ls=":", lw=1.0,
                   label="paper: 'of order 0.5%'" if sign > 0 else None)
    ax.set_xlabel("(Omega_n - Omega) / Omega  [%]")
    ax.set_ylabel("nodes")
    ax.set_title(f"(a) Omega = {omega:.4f}, window [{t1:g}, {t2:g}]")
    ax.legend(loc="upper left")
    inset = ax.inset_axes([0.62, 0.55, 0.36, 0.4])
    wide = np.linspace(rotor.min(), rotor.max(), 41)
    inset.hist(rotor, bins=wide, color="0.6", label="rotors theta_n")
    inset.hist(rel, bins=wide, color="tab:blue", histtype="step", lw=1.2, label="psi_n")
    inset.set_yscale("log")
    inset.tick_params(labelsize=6)
    inset.set_title("rotors theta_n (grey) vs psi_n", fontsize=6)


def fluctuations(ax, result):
    ratio = result.series("fluctuation_ratio")
    nodes = np.arange(ratio.size)
    ax.plot(nodes, ratio, ".", ms=2, color="tab:blue", label="Re<z_n e^{-i theta_bar_n}> / ||sync||")
    for level, style, label in ((0.1, "--", "0.1"), (0.16, ":", "paper's max 0.16")):
        ax.axhline(level, color="k" if level == 0.1 else "tab:red", ls=style, lw=1.0, label=label)
        ax.axhline(-level, color="k" if level == 0.1 else "tab:red", ls=style, lw=1.0)
    above = np.count_nonzero(np.abs(ratio) > 0.1)
    ax.set_xlabel("node n")
    ax.set_ylabel("fluctuation ratio")
    ax.set_title(f"(b) {above} of {ratio.size} nodes above 0.1, max |ratio| "
                 f"{np.max(np.abs(ratio)):.3f}")
    ax.legend(loc="upper right")


def main():
    args = hmfdata.arguments(__doc__)
    hmfdata.style()
    result = hmfdata.load(args.data, "assumptions_locked_state")
    fig, (left, right) = plt.subplots(1, 2)
    frequencies(left, result)
    fluctuations(right, result)
    fig.suptitle(f"Fig. Assumptions1: ER, K = {result.table('constants')['K']:.4g} = 3 K_c")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "fig07_assumptions1", result.scale)


if __name__ == "__main__":
    main()
