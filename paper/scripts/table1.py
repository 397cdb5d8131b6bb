"""Table I (tab:booktabs): largest eigenvalue lambda of the Erdos-Renyi networks, ours against
the paper's; from verification_table1_er_lambda. Writes table1.md, table1.png and table1.pdf."""
import os

import matplotlib.pyplot as plt

import hmfdata


def markdown(table):
    lines = ["| N | mean degree | realised mean degree | lambda (ours) | lambda (paper) | diff |",
             "|---:|---:|---:|---:|---:|---:|"]
    for n, d, realised, ours, paper in zip(table["N"], table["mean degree"],
                                           table["realised mean degree"], table["lambda"],
                                           table["paper lambda"]):
        lines.append(f"| {n:.0f} | {d:g} | {realised:.2f} | {ours:.2f} | {paper:g} | "
                     f"{100 * (ours - paper) / paper:+.2f}% |")
    return "\n".join(lines) + "\n"


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "table1_er_lambda")
    table = r.table("table")
    hmfdata.write_text(os.path.join(args.out, "table1.md"), markdown(table))
    hmfdata.style()
    fig, (a, b) = plt.subplots(1, 2)
    d, ours, paper = table["mean degree"], table["lambda"], table["paper lambda"]
    a.loglog(d, ours, "o", label="ours (seed 2024)")
    a.loglog(d, paper, "x", ms=8, label="paper (Table I)")
    a.loglog(d, table["realised mean degree"] + 1, "-", lw=0.8, color="0.5",
             label="realised ||d|| + 1")
    a.set_xlabel("mean degree ||d||")
    a.set_ylabel("lambda")
    a.legend()
    b.semilogx(d, 100 * (ours - paper) / paper, "o")
    b.axhspan(-1, 1, color="C2", alpha=0.15, label="tolerance 1% (3 printed digits)")
    b.set_xlabel("mean degree ||d||")
    b.set_ylabel("(ours - paper) / paper  [%]")
    b.legend()
    fig.suptitle("Table I: lambda of Erdos-Renyi networks (degree 20: paper misprint, see report)")
    hmfdata.save_figure(fig, args.out, "table1", r.scale)


if __name__ == "__main__":
    main()
