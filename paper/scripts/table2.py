"""Table II (tab:booktabs2): scale-free networks (Chung-Lu, ||d|| = 100, N = 10^4): d_min,
lambda and rho against alpha, ours (mean +- seed sd) against the paper's, and the rewired networks
of Fig. PLcorr; from verification_table2_scale_free. Writes table2.md, .png, .pdf."""
import os

import matplotlib.pyplot as plt

import hmfdata


FAMILY = ("alpha", "d_min", "paper d_min", "realised mean degree", "lambda mean", "lambda seed sd",
          "paper lambda", "rho mean", "rho seed sd", "paper rho")


def markdown(rows, rewired):
    lines = ["| alpha | d_min (ours) | d_min (paper) | realised mean degree | lambda (ours) | "
             "lambda (paper) | rho (ours) | rho (paper) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for a, dmin, pdmin, md, lm, ls, pl, rm, rs, pr in zip(*(rows[c] for c in FAMILY)):
        lines.append(f"| {a:g} | {dmin:.2f} | {pdmin:g} | {md:.1f} | {lm:.1f} +- {ls:.1f} | "
                     f"{pl:g} | {rm:.3f} +- {rs:.3f} | {pr:g} |")
    lines += ["", "Rewired alpha = 2.5 network (Fig. PLcorr; paper: rho 0.78, 0.97, 1.09 with "
              "lambda 282, 364, 459):", "",
              "| network | rho (ours) | lambda (ours) |", "|---|---:|---:|"]
    for k, (rho, lam) in enumerate(zip(rewired["rho"], rewired["lambda"])):
        lines.append(f"| {'start' if k == 0 else f'rewired {k}'} | {rho:.3f} | {lam:.1f} |")
    return "\n".join(lines) + "\n"


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "table2_scale_free")
    rows, rewired = r.table("alpha_family"), r.table("rewired")
    hmfdata.write_text(os.path.join(args.out, "table2.md"), markdown(rows, rewired))
    hmfdata.style()
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(11, 3.6))
    alpha = rows["alpha"]
    for axis, quantity, label in ((a, "lambda", "lambda"), (b, "rho", "rho (eq. (17))")):
        axis.errorbar(alpha, rows[quantity + " mean"], yerr=rows[quantity + " seed sd"], fmt="o",
                      capsize=3, label="ours (seed sd)")
        axis.plot(alpha, rows["paper " + quantity], "x", ms=8, label="paper")
        axis.set_xlabel("alpha")
        axis.set_ylabel(label)
        axis.legend()
    c.plot(rewired["rho"], rewired["lambda"], "o-", label="ours: start and rewired")
    c.plot([0.78, 0.97, 1.09], [282, 364, 459], "x--", ms=8, label="paper")
    c.set_xlabel("rho")
    c.set_ylabel("lambda")
    c.legend()
    fig.suptitle("Table II: scale-free networks and the rewired networks of Fig. PLcorr")
    hmfdata.save_figure(fig, args.out, "table2", r.scale)


if __name__ == "__main__":
    main()
