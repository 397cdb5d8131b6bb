"""Water-bag momenta (beyond the paper). Left: the late R (mean over the last 30% of
60 time units) on the smaller and the larger of two networks whose finite-size floors differ by 2
(K_N at N and 4N; ER at mean degree d and 4d), below (0.8) and above (1.2) the water-bag's linear
threshold K_c^wb = 6 sigma0^2 N / lambda, and Gaussian momenta at the same K (2.4 Gaussian K_c).
A stable state's level halves, an unstable one's does not. Right: the fitted growth rate on K_N
against gamma = sqrt(K lambda / 2N - D^2). From verification_waterbag_threshold."""
import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "waterbag_threshold")
    th = r.table("threshold")
    gr = r.table("growth")
    hmfdata.style()
    fig, axes = plt.subplots(1, 2, figsize=(9.5, 4.0))
    labels = []
    for i in range(len(th["ratio"])):
        net = "ER" if th["ER"][i] else "K_N"
        mom = "Gauss" if th["gaussian"][i] else "wb"
        labels.append(f"{net} {mom} {th['K/K_c^wb'][i]:g}")
    x = np.arange(len(labels))
    axes[0].errorbar(x, th["ratio"], yerr=th["ratio se"], fmt="o", capsize=3, color="C0",
                     label="late R (larger) / late R (smaller)")
    axes[0].axhline(0.5, color="C1", ls="--", lw=1, label="1/2: stable, at the floor")
    axes[0].axhline(1.0, color="C2", ls="--", lw=1, label="1: unstable, O(1) level")
    axes[0].set_xticks(x)
    axes[0].set_xticklabels(labels, fontsize=7, rotation=30, ha="right")
    axes[0].set(ylabel="ratio of late R", title="threshold (x: network, momenta, K / K_c^wb)")
    axes[0].legend(fontsize=7)
    axes[1].plot(gr["K/K_c^wb"], gr["gamma closed form"], "-", color="k", lw=1,
                 label="sqrt(K lambda / 2N - D^2)")
    axes[1].errorbar(gr["K/K_c^wb"], gr["slope"], yerr=gr["slope se"], fmt="o", capsize=3,
                     color="C3", label="fitted on K_N")
    axes[1].plot(gr["K/K_c^wb"], gr["gamma samples"], "x", color="C4",
                 label="eq. (12), replicas' samples")
    axes[1].set(xlabel="K / K_c^wb", ylabel="growth rate", title="growth rate (K_N)")
    axes[1].legend(fontsize=7)
    fig.suptitle("Water-bag momenta: linear threshold 6 sigma0^2 N / lambda and growth rate")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "waterbag_threshold", r.scale)


if __name__ == "__main__":
    main()
