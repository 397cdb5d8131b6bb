"""Work-precision charts (not a figure of the paper; speed against accuracy): for each
scene, cost per unit of simulated time (force evaluations; wall time in a second row) against the
co-moving energy error and against the error of <R>_t with respect to a yoshida4 h = 0.005
reference, for every integrator and step h. The dashed line is the statistical floor of <R>_t
over the paper's averaging window (T2 - T1 = 500): accuracy below it is wasted work. From
verification_work_precision."""
import json

import matplotlib.pyplot as plt
import numpy as np

import hmfdata


def main():
    args = hmfdata.arguments(__doc__)
    r = hmfdata.load(args.data, "work_precision")
    methods = r.note_json("methods")
    scenes = sorted(k for k in r.data if k.startswith("scene") and not k.endswith("reference"))
    hmfdata.style()
    fig, axes = plt.subplots(3, len(scenes), figsize=(3.2 * len(scenes), 9.0), squeeze=False)
    for col, key in enumerate(scenes):
        rows, ref = r.table(key), r.table(f"{key}_reference")
        meta = json.loads(r.notes[key])
        floor, paper_cost = ref["paper-window floor"], \
            ref["leap-frog h=0.01 evaluations per unit time"]
        for m, name in enumerate(methods):
            sel = rows["method index"] == m
            h, sec, ev, de, dr = (rows[c][sel] for c in (
                "h", "seconds per unit time", "force evaluations per unit time",
                "max relative energy error", "|<R>_h - <R>_ref|"))
            ok = np.isfinite(ev)
            axes[0, col].loglog(ev[ok], de[ok], "o-", ms=3, label=name)
            axes[1, col].loglog(ev[ok], np.maximum(dr[ok], 1e-9), "o-", ms=3, label=name)
            axes[2, col].loglog(sec[ok], np.maximum(dr[ok], 1e-9), "o-", ms=3, label=name)
            for x, y, hh in zip(ev[ok], de[ok], h[ok]):
                if name == "leapfrog":
                    axes[0, col].annotate(f"h={hh:g}", (x, y), fontsize=5, color="0.4")
        for row in (1, 2):
            axes[row, col].axhline(floor, ls="--", color="k", lw=0.8,
                                   label="SEM over the paper's window")
        axes[0, col].axvline(paper_cost, ls=":", color="C3", lw=0.8, label="paper: leapfrog h=0.01")
        axes[1, col].axvline(paper_cost, ls=":", color="C3", lw=0.8)
        axes[0, col].set_title(f"{meta['name']}\nchoice: {meta['choice']} h={meta['h']:g}",
                               fontsize=8)
        axes[0, col].set_xlabel("force evaluations per unit time")
        axes[1, col].set_xlabel("force evaluations per unit time")
        axes[2, col].set_xlabel("wall seconds per unit time")
        axes[0, col].set_ylabel("max energy error (co-moving)")
        axes[1, col].set_ylabel("|<R>_h - <R>_ref|")
        axes[2, col].set_ylabel("|<R>_h - <R>_ref|")
    axes[0, 0].legend()
    axes[1, 0].legend()
    fig.suptitle("Work against precision of the integrators (points: h = 0.01 ... 0.32)")
    fig.tight_layout()
    hmfdata.save_figure(fig, args.out, "work_precision", r.scale)


if __name__ == "__main__":
    main()
