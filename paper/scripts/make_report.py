"""Writes paper/REPORT.md: for every number the paper states that a verification driver checks,
the paper's value, ours, the difference and a verdict, with the figures inline.

Sections follow the paper's order (Tables I-II, Figs. 1-10). Each lists the claim, the figure,
and the records of the drivers behind it (verification/support/claim_check.cpp):
  check with a reference -> paper/reference value, ours, difference, reproduced / NOT reproduced;
  check without numbers  -> a qualitative claim (ordering, convergence), holds / does NOT hold;
  report                 -> a number printed beside the paper's without a verdict of its own
                            (the note says why it is not expected to match).
A driver found in the data directory but in no section is listed under "Other checks", so a new
driver is never silently left out.
"""
import argparse
import glob
import math
import os
import sys
import datetime

import hmfdata

# (title, paper claim, drivers, figures) in the paper's order.
SECTIONS = [
    ("Table I: Erdos-Renyi networks",
     "lambda = 101, 51.1, 31.1, 20.1, 11.1 for N = 10^4, ||d|| = 100 ... 10; 4999 for N = 2.5e4, "
     "||d|| = 5000.", ["table1_er_lambda"], ["table1"]),
    ("Table II: scale-free networks",
     "d_min = 33, 44, 52, 60, 64; lambda = 299, 243, 201, 162, 140; rho = 0.52, 0.81, 0.84, 0.93, "
     "0.99 for alpha = 2.5 ... 3.8; rewired rho 0.78, 0.97, 1.09 with lambda 282, 364, 459.",
     ["table2_scale_free"], ["table2"]),
    ("Fig. 1 (ERPLnet): onset at lambda K for ER and SF networks",
     "Plotted against lambda K the transitions of all networks line up (K_c = 2 sigma0^2 N / "
     "lambda, eq:criticalKFirstOrder) and the curves nearly collapse.",
     ["onset_er_sf"], ["fig01_erplnet"]),
    ("Fig. 2 (PLcorr): onset for rewired networks of different rho",
     "Rewiring raises rho and lambda; the onsets differ in K and align in lambda K.",
     ["onset_rewired"], ["fig02_plcorr"]),
    ("Fig. 3 (ERstdP): onset against K / sigma0^2",
     "For one ER network and several sigma0 the onsets collapse in K / sigma0^2.",
     ["onset_sigma0"], ["fig03_erstdp"]),
    ("Fig. 4 (ERerror): finite-size floor below onset",
     "At K = K_c / 2, <R>_t ~ (qN)^(-1/2): slopes -1/2 against N and against q.",
     ["finite_size_floor"], ["fig04_ererror"]),
    ("Fig. 5 (growthRate): linear growth rate",
     "log R(t) grows with the slope gamma of eq:gammaKKc; agreement improves with K / K_c.",
     ["growth_rate"], ["fig05_growth_rate"]),
    ("Fig. 6 (R_vs_K_theoretical): synchronized state",
     "Simulated <R>_t follows eq:rSigmaBesselMain above K_c; near onset R ~ G sqrt(dK / K_c) with "
     "G = 0.633 (ER) and 0.354 (SF).",
     ["simulation_vs_theory", "er_onset_amplitude", "onset_amplitude_networks",
      "theory_near_onset"], ["fig06_r_vs_k_theory"]),
    ("Figs. 7-8 (Assumptions1, histPsinMinusPsi1): Assumption 1",
     "Node frequencies within ~0.5% of Omega; fluctuation terms mostly < 0.1 of the synchronized "
     "ones (max 0.16; node averages 1.1e-5 vs 2.3e-3); psi_n - psi_1 concentrated at 0.",
     ["assumptions_locked_state"], ["fig07_assumptions1", "fig08_hist_psin"]),
    ("Fig. 9 (ergodicityAssumption): Assumption 2",
     "A single rotor's (theta_bar, p_bar) follows the Boltzmann density eq:gFunction "
     "(beta = 0.965, r_1 = 0.036).", ["boltzmann_single_rotor"], ["fig09_ergodicity"]),
    ("Fig. 10 (maxSynchrony): the large-K limit",
     "R_hat of eq:KtoInfinity is nearly independent of alpha; simulations at K = 10^4 lie about 1% "
     "below it; eq:rd is close.", ["max_synchrony_alpha", "large_k_simulation"],
     ["fig10_max_synchrony"]),
    ("Speed against accuracy (not in the paper)",
     "The paper integrates with leap-frog, h = 0.01. Which method and step give every figure "
     "at its statistical precision for the least work? Where does each method fail?",
     ["work_precision", "stability_limit"], ["work_precision"]),
    ("Solving the self-consistent equations (not in the paper)",
     "The paper solves eq:rSigmaBesselMain by plain fixed-point iteration, which converges slowly "
     "near K_c. How slowly, what acceleration buys, and on which networks does each fail?",
     ["solver_convergence"], ["solver_convergence"]),
    ("Networks that break the theory's assumptions (not in the paper)",
     "The theory assumes a simple Perron eigenvalue and many neighbours per rotor. Are networks "
     "that violate this flagged, and how far is the simulation from the theory on them?",
     ["theory_breaking_networks"], ["theory_breaking_networks"]),
    ("Beyond the paper: the Antoni-Ruffo caloric curve on the complete graph",
     "Not a claim of the paper: its all-to-all limit is the HMF of Antoni & Ruffo (1995), whose "
     "microcanonical runs relax to the canonical M = I1(M/T)/I0(M/T), U = T/2 + (1 - M^2)/2, "
     "U_c = 3/4 (eq:rSigmaBesselMain on K_N). The complete graph is stored in O(1) "
     "(`hmfnet generate complete`).", ["all_to_all_caloric_curve"], ["caloric_curve"]),
    ("Beyond the paper: water-bag momenta, threshold and growth",
     "Not a claim of the paper: eq:gDashPSGammaPlusOmega for water-bag momenta (uniform on "
     "Omega +- sqrt(3) sigma0) gives the threshold K_c^wb = 6 sigma0^2 N / lambda (three times "
     "the Gaussian's; Delta_c = 1/sqrt 2 in Antoni-Ruffo units) and gamma = sqrt(K lambda / 2N - "
     "D^2).", ["waterbag_threshold"], ["waterbag_threshold"]),
    ("Beyond the paper: the quasi-stationary state's life on the complete graph",
     "Not a claim of the paper: Yamaguchi, Barre, Bouchet, Dauxois & Ruffo (Physica A 337, 2004) "
     "find that the homogeneous water-bag at U = 0.69 stays quasi-stationary for a time ~ N^1.7 "
     "before relaxing to the synchronised equilibrium (fitted over N = 10^3 .. 2 10^4); Rocha "
     "Filho et al. (PRE 90, 2014) see the exponent rise toward 2 at large N. The second figure "
     "and its tables: the same start on a GPU over that range, 32 replicas a size, redrawn from "
     "the stored data of paper/full/beyond/data/qss_lifetime_gpu.h5 (docs/gpu.md).",
     ["qss_lifetime"], ["qss_lifetime", "qss_lifetime_gpu"]),
    ("Beyond the paper: the near-onset gap, a lag or the stationary state?",
     "Our open question, not the paper's: near K_c the simulation sits below eq:rSigmaBesselMain "
     "at the paper's T. Gaussian momenta at 1.1, 1.2 and 1.5 K_c on the complete graph and on ER "
     "(degree 100) for three N or more, to 2x (CI) or 10x (full) the paper's T: does the gap "
     "close with time, and how does the time it takes grow with N and the degree?",
     ["near_onset_gap"], ["near_onset_gap"]),
    ("Beyond the paper: the quasi-stationary state on networks",
     "No paper has this figure: the same water-bag start (K lambda / N = 1, sigma0^2 = 0.38) on "
     "random regular graphs (every degree d), ER and the complete graph. Does the QSS life follow "
     "the size N, or the number d of neighbours each rotor's field sums? Does the degree spread "
     "(ER against random regular) matter?", ["qss_networks"], ["qss_networks"]),
    ("Conservation laws",
     "H and the total momentum are conserved (eq:hamiltonianNetworkCase); the symplectic "
     "leap-frog's energy error stays bounded.", ["conservation"], []),
]


def fmt(x):
    if x is None:
        return ""
    if x == 0 or 1e-3 <= abs(x) < 1e5:
        return f"{x:.4g}"
    return f"{x:.3e}"


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def record_row(rec):
    ours, ref = rec["ours"], rec["reference"]
    if rec["kind"] == "report":
        diff = f"{100 * (ours - ref) / ref:+.2f}%" if ref else ""
        return (f"| {cell(rec['what'])} | {fmt(ref)} | {fmt(ours)} | {diff} | "
                f"reported: {cell(rec['detail'])} |")
    if ours is None:
        verdict = "holds" if rec["pass"] else "**does NOT hold**"
        return f"| {cell(rec['what'])} | | | | {verdict}: {cell(rec['detail'])} |"
    diff = f"{100 * (ours - ref) / ref:+.3g}%" if ref else fmt(ours - ref)
    verdict = "reproduced" if rec["pass"] else "**NOT reproduced**"
    return f"| {cell(rec['what'])} | {fmt(ref)} | {fmt(ours)} | {diff} | {verdict}: {cell(rec['detail'])} |"


def driver_block(result):
    lines = [f"**`verification_{result.driver}`** ({result.claim}): "
             f"{'all checks pass' if result.passed else '**some checks fail**'}, "
             f"{float(result.attrs.get('wall_seconds', math.nan)):.1f} s.", "",
             "| quantity | paper / reference | ours | difference | verdict |",
             "|---|---:|---:|---:|---|"]
    lines += [record_row(rec) for rec in result.checks]
    return lines + [""]


def section(title, claim, drivers, figures, results, figure_dir, out_dir):
    lines = [f"## {title}", "", f"*Paper:* {claim}", ""]
    for name in figures:
        png = os.path.join(figure_dir, f"{name}.png")
        if os.path.exists(png):
            rel = os.path.relpath(png, out_dir)
            lines += [f"![{name}]({rel})", ""]
        else:
            lines += [f"*Figure `{name}` was not produced.*", ""]
        table = os.path.join(figure_dir, f"{name}.md")
        if os.path.exists(table):
            lines += [open(table).read(), ""]
    for driver in drivers:
        if driver in results:
            lines += driver_block(results[driver])
        else:
            lines += [f"*No data from `verification_{driver}` (driver not built or not run).*", ""]
    return lines


# Which work-precision scene stands for which figures of the paper (same network family and
# coupling range); the step chosen for the scene is the step those figures need.
SCENE_FIGURES = {
    "ER 0.5 K_c": "Fig. 4 (ERerror: K = K_c / 2)",
    "ER 1.5 K_c": "Figs. 1-3 and 5 (onsets and growth, 1 < K/K_c <= 2)",
    "ER 3 K_c": "Figs. 6a, 7-8 (ER at 3 K_c)",
    "SF alpha 2.8 3 K_c": "Figs. 1c-d, 2, 6b (scale-free)",
}


def step_choices(result):
    """The chosen method and step per figure, with the speed-up over the paper's leap-frog
    h = 0.01 in force evaluations (from verification_work_precision)."""
    lines = ["### Step per figure", "",
             "The cheapest method and step whose error in <R>_t stays within half the statistical "
             "floor of the paper's averaging window (`docs/choosing_a_method.md`), per scene, and "
             "the figures that scene stands for:", "",
             "| figures | scene | method, h | force evaluations per unit time | speed-up over "
             "leap-frog h = 0.01 |", "|---|---|---|---:|---:|"]
    keys = sorted(k for k in result.notes if k.startswith("scene") and k[5:].isdigit())
    for key in keys:
        meta = result.note_json(key)
        paper = result.table(f"{key}_reference")["leap-frog h=0.01 evaluations per unit time"]
        cost = meta["evaluations_per_time"]
        lines.append(f"| {SCENE_FIGURES.get(meta['name'], '')} | {meta['name']} | "
                     f"{meta['choice']}, {meta['h']:g} | {cost:.4g} | {paper / cost:.1f}x |")
    return lines + [""]


def summary(results):
    checks = sum(1 for r in results.values() for c in r.checks if c["kind"] == "check")
    failed = sum(1 for r in results.values() for c in r.checks
                 if c["kind"] == "check" and not c["pass"])
    reports = sum(1 for r in results.values() for c in r.checks if c["kind"] == "report")
    wall = sum(float(r.attrs.get("wall_seconds", 0.0)) for r in results.values())
    lines = [f"{len(results)} drivers, {checks} checks ({failed} not reproduced), {reports} numbers "
             f"reported beside the paper's; drivers' wall time {wall:.0f} s in all.", "",
             "Work: the force evaluations each driver's simulations spent, and the speed-up over "
             "the paper's leap-frog h = 0.01 on the same simulated time (both counted by the "
             "driver, `verification/support/work_account.hpp`; work_precision and "
             "stability_limit chart the methods themselves and are not counted). Kernel: the "
             "stored entries (rows on K_N's rank-one force) times replica lanes over every force "
             "evaluation made, the stepping loops' share of the wall time, and their rate, "
             "to set beside the sparse kernel's measured floor (docs/performance.md, \"The kernel "
             "against the yardstick and the measured bound\": ~1.4 G/s on one thread and ~2.7 "
             "G/s on two at N = 10^4, degree 100); a driver on K_N counts rows, which cost a sin/cos "
             "each, so its rate is not comparable with that floor. Ranks x threads: the most "
             "threads per rank any run of the driver used.", "",
             "| driver | checks | not reproduced | wall time [s] | force evaluations | speed-up "
             "over leap-frog h = 0.01 | kernel work [G] | stepping share of wall | kernel rate "
             "[G/s] | ranks x threads |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    spent = paper = 0.0
    for name, r in results.items():
        n = sum(1 for c in r.checks if c["kind"] == "check")
        f = sum(1 for c in r.checks if c["kind"] == "check" and not c["pass"])
        wall_s = float(r.attrs.get("wall_seconds", 0.0))
        evals = float(r.attrs.get("force_evaluations", 0.0))
        ref = float(r.attrs.get("paper_evaluations", 0.0))
        work = f"{evals:.4g} | {ref / evals:.2f}x" if evals > 0 else " | "
        lines.append(f"| `{name}` | {n} | {f} | {wall_s:.1f} | {work} | {kernel(r, wall_s)} |")
        spent, paper = spent + evals, paper + ref
    if spent > 0:
        lines += ["", f"All simulations together: {spent:.4g} force evaluations against "
                      f"{paper:.4g} with leap-frog h = 0.01, a speed-up of {paper / spent:.2f}x."]
    return lines + [""]


def kernel(r, wall_s):
    """Kernel work [G], the stepping loops' share of the wall time, their rate (all ranks' work
    over the stepping time) and ranks x threads; blank cells for a driver whose simulations are
    not accounted (work_precision, stability_limit) or from before these were recorded."""
    work = float(r.attrs.get("kernel_work", 0.0))
    seconds = float(r.attrs.get("kernel_seconds", 0.0))
    if work <= 0.0 or seconds <= 0.0:
        return " | | | "
    share = f"{seconds / wall_s:.0%}" if wall_s > 0 else ""
    return (f"{work * 1e-9:.4g} | {share} | {work * 1e-9 / seconds:.3g} | "
            f"{int(r.attrs.get('ranks', 1))} x {int(r.attrs.get('threads', 0))}")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--data", required=True)
    parser.add_argument("--figures", required=True)
    parser.add_argument("--preset", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    results = {}
    for path in sorted(glob.glob(os.path.join(args.data, "*.h5"))):
        if not hmfdata.is_verification_output(path):
            print(f"make_report: {path}: not a driver's output, left to its own script",
                  file=sys.stderr)
            continue
        r = hmfdata.load(args.data, os.path.basename(path)[:-3])
        results[r.driver] = r
    commits = sorted({r.attrs.get("git_commit", "?") for r in results.values()})
    out_dir = os.path.dirname(os.path.abspath(args.out))
    lines = ["# hmfnet: the paper, reproduced", "",
             "Generated by `make paper-figures` (paper/scripts/make_report.py); do not edit by hand.",
             f"Preset **{args.preset}** (`quick` runs the verification drivers at CI scale, `full` at "
             "the paper's scale), code commit(s) " + ", ".join(f"`{c}`" for c in commits) +
             f", generated {datetime.date.today().isoformat()}.", "",
             "Every number below comes from a verification driver (`ctest -L verification` runs the "
             "same drivers and judges the same checks), except the GPU campaign's tables in the "
             "QSS section, drawn from its stored data; the tolerance and its source are written "
             "next to each verdict. Paper: Virkar, Restrepo & Meiss, *The Hamiltonian Mean Field "
             "model: effect of network structure on synchronization dynamics*.", "",
             "## Summary", ""] + summary(results)
    used, skipped = set(), []
    for title, claim, drivers, figures in SECTIONS:
        used.update(drivers)
        if not any(d in results for d in drivers):
            skipped.append(title)
            continue
        lines += section(title, claim, drivers, figures, results, args.figures, out_dir)
        if "work_precision" in drivers and "work_precision" in results:
            lines += step_choices(results["work_precision"])
    others = [d for d in results if d not in used]
    if others:
        lines += ["## Other checks", ""]
        for d in others:
            lines += driver_block(results[d])
    if skipped:
        lines += ["## Not in this run", "", "No driver of these sections ran in this preset: " +
                  "; ".join(skipped) + ".", ""]
    hmfdata.write_text(args.out, "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
