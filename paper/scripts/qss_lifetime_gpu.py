"""QSS of the all-to-all HMF to the literature's sizes, on a GPU (beyond the paper): the
homogeneous water-bag at U = 0.69 on K_N, N = 10^3 .. 2 10^4, 32 replicas each, stepped by
verification/gpu/qss_lifetime_gpu.cpp (ci/device_check.sh). Two readings of the life:
  (a) qss_lifetime.cpp's rule: the replica mean R(t), smoothed over 50 time units, first passes
      half way from its initial level to the canonical M_eq; error from 200 bootstrap resamples
      of the replicas; a size whose mean never passes is censored (life > T), never fitted;
  (b) the literature's collapse (Yamaguchi et al. 2004): the alpha for which the relaxed
      fraction phi_N(t) = (R(t) - R_0) / (M_eq - R_0) of every N falls on one curve against
      t / N^alpha (least squares of the curves' spread on their common range; error from 50
      bootstrap resamples of the replicas).
Both are read globally (all N) and locally (successive pairs of N), so that a drift of the
exponent with N shows in either.

  python3 qss_lifetime_gpu.py --raw DIR[,DIR2...] --h5 F.h5 [--commit C] [--extend OLD.h5 [--replace]]
                                                                 # device output -> HDF5
Several DIRs are the calls of one run, each going on from the one before (--resume): a later
call's records of a size hold its whole run and are taken once the earlier call's are checked
equal to their start (bit for bit in float32); a size a call did not step stays as the earlier
call left it; the run's wall time is the calls' sum, its device the calls' cards.
  python3 qss_lifetime_gpu.py --data DIR --out FIGDIR            # HDF5 -> figure and tables
With --extend, the sizes of OLD.h5 are kept where the new run went less far; a size in both
keeps the longer run (the new one where they are equal), after its records over the common
stretch are checked equal (bit for bit in the float32 the file stores)
(the same seeds and the fixed-order sums of complete_graph_ensembles.cu give the same bits on
every card and cluster size: a run that differs is not the same experiment and is refused).
With --replace, a size the new run holds replaces the stored one without that check (a run
with another --lives: its records lie on another grid). Each size's group names the device,
commit and wall time of the run it comes from.
The second form reads DIR/qss_lifetime_gpu.h5 (and DIR/qss_lifetime.h5, the CPU's N = 200 ..
1600, when present), prints the tables the report cites and writes them beside the figure
(FIGDIR/qss_lifetime_gpu.md); `make paper-figures` runs it on paper/full/beyond/data.
"""
import argparse
import json
import os
import tempfile

import h5py
import numpy as np
from scipy.optimize import brentq
from scipy.special import i0e, i1e

SMOOTH = 50.0      # time units: the running mean and the initial window (support/qss_start.hpp)
BOOTSTRAP = 200    # resamples for a life's se (support/qss_start.hpp)
COLLAPSE_BOOT = 50
ALPHAS = np.arange(0.8, 2.6001, 0.005)


def m_eq(U):
    """Canonical M of the all-to-all HMF at energy U (K = 1), all_to_all.cpp's root with
    kappa = 1 / (2 (2U - 1)): R = I1(x) / I0(x), x = 2 kappa R / (1 + 2 kappa R^2)."""
    kappa = 1.0 / (2.0 * (2.0 * U - 1.0))
    if kappa <= 1.0:
        return 0.0

    def phi(R):
        x = 2.0 * kappa * R / (1.0 + 2.0 * kappa * R * R)
        return i1e(x) / i0e(x) - R

    return brentq(phi, 1e-9, 1.0 - 1e-12, xtol=1e-15)


RUN_KEYS = ("device", "budget_s", "wall_s", "lives")  # per size's group: its run's
SHARED_KEYS = ("h", "U", "K", "replicas", "seeds")


def read_raw(raw, commit):
    """The device check's qss_gpu.json and qss_gpu.f64 as {N: (group attrs, R, E)}."""
    meta = json.load(open(os.path.join(raw, "qss_gpu.json")))
    blob = np.fromfile(os.path.join(raw, "qss_gpu.f64"), dtype="<f8")
    B, records = meta["replicas"], meta["records"]
    expected = 2 * B * records * len(meta["sizes"])
    if blob.size != expected:
        raise SystemExit(f"{raw}/qss_gpu.f64 holds {blob.size} doubles, its JSON describes {expected}")
    sizes, at = {}, 0
    for s in meta["sizes"]:
        R = blob[at:at + B * records].reshape(B, records)
        E = blob[at + B * records:at + 2 * B * records].reshape(B, records)
        at += 2 * B * records
        w = s["records_written"]
        attrs = {k: s[k] for k in ("N", "record_every", "steps_planned", "steps_done", "records_written")}
        attrs.update({k: meta[k] for k in RUN_KEYS}, git_commit=commit)
        # float32 keeps R to 1e-7, far below its replica noise (~1e-2); the energy as its first
        # record (float64) and the relative change since (float32).
        drift = (E[:, :w] - E[:, :1]) / np.abs(E[:, :1])
        sizes[s["N"]] = (attrs, R[:, :w].astype("<f4"), E[:, 0], drift.astype("<f4"))
    return meta, sizes


def records_agree(a, b, m):
    """Whether two runs of a size, (group attrs, R, E0, drift) each, are one experiment over their
    first m records: the same record spacing, and R, the energy drift and the first energy equal
    bit for bit."""
    (attrs_a, R_a, E0_a, drift_a), (attrs_b, R_b, E0_b, drift_b) = a, b
    return (attrs_a["record_every"] == attrs_b["record_every"]
            and np.array_equal(R_a[:, :m], R_b[:, :m])
            and np.array_equal(drift_a[:, :m], drift_b[:, :m])
            and (m == 0 or np.array_equal(E0_a, E0_b)))


def read_chain(raws, commit):
    """read_raw of the calls of one run, each resumed from the one before: every size at its
    latest call (a later call holds the whole run of a size it stepped: its records are checked
    against the earlier call's; a size a call did not step stays as an earlier call left it, as
    qss_gpu_resume.bin carries it), with the calls' wall and budget summed and their cards named."""
    raws = [r for r in raws if r]
    if not raws:
        raise SystemExit("--raw names no folder")
    meta, sizes = read_raw(raws[0], commit)
    wall, budget, devices = meta["wall_s"], meta["budget_s"], [meta["device"]]
    for before, raw in zip(raws, raws[1:]):
        later, later_sizes = read_raw(raw, commit)
        if not later.get("resumed_from"):
            raise SystemExit(f"{raw}: its run did not resume another (qss_gpu.json's resumed_from)")
        for key in SHARED_KEYS + ("lives", "records"):
            if later[key] != meta[key]:
                raise SystemExit(f"{before} has {key} = {meta[key]}, {raw} {later[key]}: not one run")
        for n in set(sizes) & set(later_sizes):
            w = sizes[n][1].shape[1]
            if later_sizes[n][1].shape[1] < w or not records_agree(sizes[n], later_sizes[n], w):
                raise SystemExit(f"N = {n}: {raw}'s first {w} records differ from {before}'s: "
                                 "not the run it resumed")
        wall, budget = wall + later["wall_s"], budget + later["budget_s"]
        devices += [later["device"]] if later["device"] not in devices else []
        meta, sizes = later, {**sizes, **later_sizes}
    meta.update(wall_s=wall, budget_s=budget, device=" + ".join(devices))
    for attrs, *_ in sizes.values():
        attrs.update(wall_s=wall, budget_s=budget, device=meta["device"])
    return meta, sizes


def read_h5(path):
    """An earlier conversion as (shared attrs, {N: (group attrs, R, E0, drift)}); a file written
    before the groups named their run takes the run's attributes from the file's."""
    with h5py.File(path, "r") as f:
        top = dict(f.attrs)
        sizes = {}
        for k in f:
            g = f[k]
            attrs = dict(g.attrs)
            for key in RUN_KEYS + ("git_commit",):
                if key not in attrs:
                    attrs[key] = top[key]
            sizes[int(attrs["N"])] = (attrs, g["R_mean"][()], g["energy_first"][()],
                                      g["energy_drift"][()])
    return top, sizes


def merge(old, new, replace=False):
    """The sizes of both; a size in both keeps the new run unless the stored one has more steps,
    once the records the two share agree (records_agree; replace: the new run's, unchecked)."""
    merged = dict(old)
    for n, run in new.items():
        if n in old and not replace:
            m = min(old[n][1].shape[1], run[1].shape[1])
            if not records_agree(old[n], run, m):
                raise SystemExit(f"N = {n}: the new run's first {m} records differ from the "
                                 "stored run's; not the same experiment, not merged")
            # An equal run replaces the stored one: the calls of one run (read_chain), given
            # again with the first call stored, then carry one wall time, counted once.
            if run[0]["steps_done"] < old[n][0]["steps_done"]:
                continue
        merged[n] = run
    return merged


def convert(raw, out, commit, extend=None, replace=False):
    meta, sizes = read_chain(raw.split(","), commit)
    if extend:
        top, old = read_h5(extend)
        for key in SHARED_KEYS:
            if top[key] != meta[key]:
                raise SystemExit(f"{extend} has {key} = {top[key]}, {raw} {meta[key]}: not merged")
        sizes = merge(old, sizes, replace)
    tmp = tempfile.NamedTemporaryFile(dir=os.path.dirname(os.path.abspath(out)), suffix=".h5",
                                      delete=False).name
    try:
        with h5py.File(tmp, "w") as f:
            for key in SHARED_KEYS:
                f.attrs[key] = meta[key]
            runs = sorted({(str(a["device"]), str(a["git_commit"]), float(a["wall_s"]))
                           for a, *_ in sizes.values()})
            f.attrs["device"] = "; ".join(sorted({d for d, _, _ in runs}))
            f.attrs["git_commit"] = "; ".join(sorted({c for _, c, _ in runs}))
            f.attrs["wall_s"] = sum(w for _, _, w in runs)
            f.attrs["program"] = "verification/gpu/qss_lifetime_gpu.cpp via ci/device_check.sh"
            for n in sorted(sizes, reverse=True):
                attrs, R, E0, drift = sizes[n]
                g = f.create_group(f"N{n}")
                g.create_dataset("R_mean", data=R, compression="gzip", shuffle=True)
                g.create_dataset("energy_first", data=E0)
                g.create_dataset("energy_drift", data=drift, compression="gzip", shuffle=True)
                for key, value in attrs.items():
                    g.attrs[key] = value
        os.chmod(tmp, 0o644)
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def half_way(x, dt, width, target):
    """support/passage_time.hpp's half_way_passage with t0 = 0 (record i ends at (i + 1) dt)."""
    if len(x) <= width or width == 0:
        return np.nan
    start = x[:width].mean()
    half = 0.5 * (start + target)
    sign = 1.0 if target >= start else -1.0
    run = np.convolve(x, np.ones(width) / width, mode="valid")  # run[j] ends at record j + width - 1
    hit = np.nonzero(sign * (run[1:] - half) >= 0.0)[0]
    if hit.size == 0:
        return np.nan
    i = hit[0] + width  # the window's last record
    return dt * (i + 1.0 - 0.5 * width)


class Size:
    def __init__(self, g, h):
        self.N = int(g.attrs["N"])
        self.R = g["R_mean"][()].astype(float)
        E0 = g["energy_first"][()]
        self.dt = float(g.attrs["record_every"]) * h
        self.t = self.dt * np.arange(1, self.R.shape[1] + 1)
        self.T = float(g.attrs["steps_done"]) * h
        self.planned = float(g.attrs["steps_planned"]) * h
        # The smoothing window in whole records: 50 time units where a record is shorter (N <
        # 5000 here); beyond, one record, itself a mean over dt > 50 (up to 1101 at 2 10^4).
        self.width = max(1, int(round(SMOOTH / self.dt)))
        U = E0 / self.N + 0.5  # K = 1; the centre-of-mass term (P/N)^2/2 ~ 1e-4 left in
        self.U = U.mean()
        self.M_eq = m_eq(self.U)
        self.energy_error = float(np.max(np.abs(g["energy_drift"][()])))
        self.device = str(g.attrs.get("device", ""))

    def life(self, chosen=None):
        R = self.R if chosen is None else self.R[chosen]
        return half_way(R.mean(axis=0), self.dt, self.width, self.M_eq)

    def bootstrap(self, rng):
        B = self.R.shape[0]
        times = np.array([self.life(rng.integers(0, B, B)) for _ in range(BOOTSTRAP)])
        return times

    def phi(self, chosen=None):
        """The relaxed fraction of the replica mean smoothed over `width` records, at the
        centres of the smoothing windows: (t, phi)."""
        R = (self.R if chosen is None else self.R[chosen]).mean(axis=0)
        run = np.convolve(R, np.ones(self.width) / self.width, mode="valid")
        t = self.dt * (np.arange(run.size) + 0.5 * self.width)
        R0 = R[:self.width].mean()
        return t, (run - R0) / (self.M_eq - R0)


def power_law(ns, lives, ses):
    """support/passage_time.hpp's power_law_fit: weighted least squares of ln life on ln N."""
    ok = np.isfinite(lives) & (ses > 0)
    if ok.sum() < 2:
        return np.nan, np.nan, np.nan
    w = (lives[ok] / ses[ok]) ** 2
    x, y = np.log(ns[ok]), np.log(lives[ok])
    sw, sx, sy, sxx, sxy = w.sum(), (w * x).sum(), (w * y).sum(), (w * x * x).sum(), (w * x * y).sum()
    det = sw * sxx - sx * sx
    slope = (sw * sxy - sx * sy) / det
    return slope, np.sqrt(sw / det), (sy - slope * sx) / sw


def spread(curves, alpha):
    """Mean squared spread of phi_N against ln(t / N^alpha) over the range every curve covers
    (200 points evenly in ln s), after the initial window (t >= 50)."""
    logs = []
    for N, t, phi in curves:
        keep = t >= SMOOTH
        logs.append((np.log(t[keep]) - alpha * np.log(N), phi[keep]))
    lo = max(s[0] for s, _ in logs)
    hi = min(s[-1] for s, _ in logs)
    if not hi > lo:
        return np.inf
    grid = np.linspace(lo, hi, 200)
    values = np.array([np.interp(grid, s, phi) for s, phi in logs])
    return np.mean((values - values.mean(axis=0)) ** 2)


def collapse(sizes, rng=None):
    if len(sizes) < 2:
        return np.nan  # one curve collapses onto itself at every alpha
    curves = []
    for s in sizes:
        chosen = None if rng is None else rng.integers(0, s.R.shape[0], s.R.shape[0])
        curves.append((s.N, *s.phi(chosen)))
    d = np.array([spread(curves, a) for a in ALPHAS])
    return ALPHAS[np.argmin(d)] if np.isfinite(d).any() else np.nan


def collapse_with_error(sizes, seed):
    rng = np.random.default_rng(seed)
    best = collapse(sizes)
    boots = np.array([collapse(sizes, rng) for _ in range(COLLAPSE_BOOT)])
    return best, np.nanstd(boots, ddof=1)


def analyse(path):
    with h5py.File(path, "r") as f:
        h = float(f.attrs["h"])
        sizes = sorted((Size(f[k], h) for k in f if k.startswith("N")), key=lambda s: s.N)
        attrs = dict(f.attrs)
    rows = []
    for s in sizes:
        rng = np.random.default_rng(s.N)
        boots = s.bootstrap(rng)
        passed = np.isfinite(boots).sum()
        life = s.life()
        rows.append(dict(N=s.N, U=s.U, M_eq=s.M_eq, life=life,
                         se=np.nanstd(boots, ddof=1) if passed > 1 else np.nan,
                         passed=int(passed), T=s.T, planned=s.planned,
                         energy_error=s.energy_error, device=s.device.split(",")[0]))
    measured = [r for r in rows if np.isfinite(r["life"]) and r["passed"] == BOOTSTRAP]
    ns = np.array([r["N"] for r in measured], float)
    lives = np.array([r["life"] for r in measured])
    ses = np.array([r["se"] for r in measured])
    slope, slope_se, _ = power_law(ns, lives, ses)
    local = []
    for a, b in zip(measured, measured[1:]):
        k = np.log(b["life"] / a["life"]) / np.log(b["N"] / a["N"])
        e = np.hypot(a["se"] / a["life"], b["se"] / b["life"]) / np.log(b["N"] / a["N"])
        pair = [s for s in sizes if s.N in (a["N"], b["N"])]
        alpha, alpha_se = collapse_with_error(pair, a["N"] + b["N"])
        local.append(dict(N1=a["N"], N2=b["N"], exponent=k, se=e, alpha=alpha, alpha_se=alpha_se))
    # A size censored after the last measured one still bounds the local exponent from below:
    # its life exceeds its run's T.
    censored = []
    if measured:
        last = measured[-1]
        for r in rows:
            if r["N"] > last["N"] and not np.isfinite(r["life"]):
                span = np.log(r["N"] / last["N"])
                censored.append(dict(N1=last["N"], N2=r["N"], T=r["T"],
                                     exponent=np.log(r["T"] / last["life"]) / span,
                                     se=last["se"] / last["life"] / span))
    # The global collapse over the sizes whose life was measured: a censored curve ends before
    # its relaxation, and would restrict the common range to the early part of every curve.
    alpha, alpha_se = collapse_with_error([s for s in sizes if s.N in set(ns.astype(int))], 1)
    return dict(attrs=attrs, sizes=sizes, rows=rows, slope=slope, slope_se=slope_se,
                local=local, censored=censored, alpha=alpha, alpha_se=alpha_se)


def report(a):
    """The tables the report cites, as Markdown lines."""
    lines = [f"device: {a['attrs']['device']}; commit {a['attrs']['git_commit']}; "
             f"wall {a['attrs']['wall_s']:.0f} s; {a['attrs']['replicas']} replicas per N", "",
             "| N | U | M_eq | life (half-way) | se | resamples passed | T run / planned | max abs(dH/H) | run on |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in a["rows"]:
        life = f"{r['life']:.4g}" if np.isfinite(r["life"]) else f"> {r['T']:.4g} (censored)"
        se = f"{r['se']:.3g}" if np.isfinite(r["se"]) else "-"
        lines.append(f"| {r['N']} | {r['U']:.4f} | {r['M_eq']:.4f} | {life} | {se} | {r['passed']} "
                     f"of {BOOTSTRAP} | {r['T']:.4g} / {r['planned']:.4g} | "
                     f"{r['energy_error']:.1e} | {r['device']} |")
    lines += ["", f"half-way lives: N^({a['slope']:.3f} +- {a['slope_se']:.3f}) over the measured N; "
              f"collapse of phi_N(t / N^alpha) over the same N: alpha = {a['alpha']:.3f} +- "
              f"{a['alpha_se']:.3f}", "",
              "| N1 -> N2 | local exponent (half-way) | local collapse alpha |", "|---|---|---|"]
    for l in a["local"]:
        lines.append(f"| {l['N1']} -> {l['N2']} | {l['exponent']:.3f} +- {l['se']:.3f} | "
                     f"{l['alpha']:.3f} +- {l['alpha_se']:.3f} |")
    for c in a["censored"]:
        lines.append(f"| {c['N1']} -> {c['N2']} | > {c['exponent']:.3f} +- {c['se']:.3f} (life at "
                     f"{c['N2']} > T = {c['T']:.4g}) | - |")
    return lines


def write_tables(lines, out_dir):
    """FIGDIR/qss_lifetime_gpu.md, which make_report.py puts under the figure (temporary file,
    then rename)."""
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "qss_lifetime_gpu.md")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)


def figure(a, data_dir, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13.5, 4.0))
    for i, (s, r) in enumerate(zip(a["sizes"], a["rows"])):
        axes[0].plot(s.t, s.R.mean(axis=0), "-", lw=0.8, color=f"C{i}", label=f"N = {s.N}")
        if np.isfinite(r["life"]):
            axes[0].axvline(r["life"], color=f"C{i}", lw=0.8, ls="--")
        axes[0].axhline(r["M_eq"], color="k", lw=0.5, ls=":")
        tc, phi = s.phi()
        axes[2].plot(tc / s.N ** a["alpha"], phi, "-", lw=0.8, color=f"C{i}", label=f"N = {s.N}")
    axes[0].set(xscale="log", xlabel="t", ylabel="replica mean R (32 replicas)",
                title="water-bag U = 0.69 on K_N (GPU)")
    axes[0].legend(fontsize=7)
    rows = [r for r in a["rows"] if np.isfinite(r["life"]) and r["passed"] == BOOTSTRAP]
    n = np.array([r["N"] for r in rows], float)
    axes[1].errorbar(n, [r["life"] for r in rows], yerr=[r["se"] for r in rows], fmt="o",
                     capsize=3, color="C3", label="GPU: half-way life")
    for r in a["rows"]:
        if not np.isfinite(r["life"]):
            axes[1].plot([r["N"]], [r["T"]], "^", color="C3", mfc="none",
                         label=f"N = {r['N']}: censored (life > T)")
    cpu = os.path.join(data_dir, "qss_lifetime.h5")
    if os.path.exists(cpu):
        with h5py.File(cpu, "r") as f:
            d = f["data/lives"]
            cols = json.loads(d.attrs["columns"])
            v = d[()]
            axes[1].errorbar(v[:, cols.index("N")], v[:, cols.index("life")],
                             yerr=v[:, cols.index("life se")], fmt="s", capsize=3, color="C0",
                             label="CPU (qss_lifetime, 16 replicas)")
    grid = np.geomspace(150, 3e4, 30)
    if np.isfinite(a["slope"]):
        k = np.argmax(n)
        axes[1].plot(grid, rows[k]["life"] * (grid / n[k]) ** a["slope"], "-", color="C3", lw=1,
                     label=f"fit: N^({a['slope']:.2f} +- {a['slope_se']:.2f})")
        axes[1].plot(grid, rows[k]["life"] * (grid / n[k]) ** 1.7, "--", color="k", lw=1,
                     label="N^1.7 (Yamaguchi et al. 2004)")
    axes[1].set(xscale="log", yscale="log", xlabel="N", ylabel="life", title="QSS life")
    axes[1].legend(fontsize=7)
    axes[2].set(xscale="log", xlabel=f"t / N^{a['alpha']:.2f}", ylabel="relaxed fraction phi",
                title=f"collapse: alpha = {a['alpha']:.2f} +- {a['alpha_se']:.2f}")
    axes[2].legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, "qss_lifetime_gpu.png")
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=120)
    os.replace(tmp, path)
    print(f"figure: {path}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--raw")
    p.add_argument("--h5")
    p.add_argument("--commit", default="unknown")
    p.add_argument("--extend", help="an earlier HDF5 whose sizes the new run extends")
    p.add_argument("--replace", action="store_true",
                   help="with --extend: the new run's sizes replace the stored ones unchecked")
    p.add_argument("--data")
    p.add_argument("--out")
    args = p.parse_args()
    if args.raw:
        if not args.h5:
            p.error("--raw needs --h5")
        if args.replace and not args.extend:
            p.error("--replace needs --extend")
        convert(args.raw, args.h5, args.commit, args.extend, args.replace)
        return
    if not (args.data and args.out):
        p.error("give --raw DIR --h5 F, or --data DIR --out FIGDIR")
    a = analyse(os.path.join(args.data, "qss_lifetime_gpu.h5"))
    lines = report(a)
    print("\n".join(lines))
    write_tables(lines, args.out)
    figure(a, args.data, args.out)


if __name__ == "__main__":
    main()
