"""A picture of any run: ``python3 -m hmfnet.plot RUN.h5 -o FIG.png [--network FILE]``.

Top panel: <R>_t against K/K_c (the run's K_c: the linear threshold of its momenta), the mean
over replicas with error bars of the combined batch-means SEM (the CLI's R_sem) and, with more
than one replica, the replicas' spread as a second, wider cap; beside it the self-consistent
theory R(K) at the run's sigma0 (the paper's eq. (33), eq:rSigmaBesselMain in docs/equations.md)
and the near-onset law G sqrt(K/K_c - 1) (eq. (38), eq:globalOrderRInDeltaK), from
`hmfnet.theory` on the run's network. Bottom panel: the largest relative energy error of each K
(over replicas), on a log scale, with the run's --energy-tolerance.

The network is the one the run recorded as its input (a file path), or ``--network FILE``; a run
whose network cannot be found (a Python network, a moved file) is drawn without the theory, and
the title says so. The figure is written to a temporary file and renamed.
"""
import argparse
import os
import sys
import tempfile

import numpy as np

from . import read_network, theory
from .run_file import read_run


def _network_of(run, network):
    """A Network, a path, or the run's recorded input if that is a readable file."""
    if network is not None and not isinstance(network, (str, os.PathLike)):
        return network
    path = network if network is not None else run.get("parameters", {}).get("input")
    if path is None or not os.path.isfile(path):
        if network is not None:
            raise FileNotFoundError(f"{network}: no such network file")
        return None
    return read_network(path)


def plot_data(path, network=None, points=120):
    """What the figure draws, as arrays: K_over_Kc, R (mean over replicas), R_sem, R_spread,
    energy_error; and theory_K_over_Kc, theory_R, theory_R_onset when the network is known."""
    run = read_run(path)
    p = run["points"]
    if len(p.get("K", [])) == 0:
        raise ValueError(f"{path}: the run has no completed K")
    R = np.atleast_2d(p["R_mean"])
    sem = np.atleast_2d(p["R_sem"])
    B = R.shape[1]
    data = {
        "K_over_Kc": np.asarray(p["K_over_Kc"]),
        "R": R.mean(axis=1),
        "R_sem": np.sqrt((sem**2).sum(axis=1)) / B,  # as `simulate --json` combines them
        "R_spread": R.std(axis=1, ddof=1) if B > 1 else np.zeros(R.shape[0]),
        "energy_error": np.atleast_2d(p["energy_rel_error_max"]).max(axis=1),
        "energy_tolerance": run["parameters"].get("energy_tolerance"),
        "title": os.path.basename(str(path)),
    }
    Kc = run["network"]["Kc"]
    net = _network_of(run, network)
    replica = run["parameters"]["replicas"][0]
    if net is None:
        data["title"] += " (network not found: no theory)"
        return data
    if net.n != run["network"]["n"]:
        # The run file does not record the read options (--index-base, --nodes): a file read
        # otherwise than the run read it is not the run's network.
        data["title"] += f" (network file has N = {net.n}, the run N = {run['network']['n']}: " \
                         "no theory)"
        return data
    x_max = max(1.5, 1.1 * float(data["K_over_Kc"].max()))
    grid = np.linspace(x_max / points, x_max, points)
    th = theory(net, sigma0=replica["sigma0"], K=list(grid * Kc), momenta=replica["momenta"])
    data.update(theory_K_over_Kc=grid, theory_R=th["R"], theory_R_onset=th["R_onset"])
    data["title"] += f" (N = {run['network']['n']}, sigma0 = {replica['sigma0']:g}, " \
                     f"{replica['momenta']} momenta, {B} replica{'s' if B > 1 else ''})"
    return data


def plot_run(path, output, network=None):
    """Draws `path` (a `simulate -o` results file) into `output` (any matplotlib format) and
    returns the arrays it drew (plot_data)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d = plot_data(path, network)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1.3]})
    if "theory_R" in d:
        top.plot(d["theory_K_over_Kc"], d["theory_R"], "k-", lw=1.2,
                 label="self-consistent theory, paper eq. (33)")
        top.plot(d["theory_K_over_Kc"], d["theory_R_onset"], "r--", lw=1.0,
                 label="near onset: G sqrt(K/K_c - 1), eq. (38)")
    if np.any(d["R_spread"] > 0):
        top.errorbar(d["K_over_Kc"], d["R"], yerr=d["R_spread"], fmt="none", color="tab:blue",
                     capsize=6, lw=0.8, label="replica sd")
    top.errorbar(d["K_over_Kc"], d["R"], yerr=d["R_sem"], fmt="o", color="navy", capsize=3,
                 label="<R>_t (SEM)")
    top.axvline(1.0, color="0.6", lw=0.8, ls=":")
    top.set_ylabel("<R>_t")
    top.set_ylim(0, 1)
    top.legend(loc="upper left", fontsize=8)
    top.set_title(d["title"], fontsize=9)
    bottom.semilogy(d["K_over_Kc"], np.maximum(d["energy_error"], 1e-17), "s", color="tab:red")
    if d["energy_tolerance"]:
        bottom.axhline(d["energy_tolerance"], color="tab:red", lw=0.8, ls=":",
                       label="energy tolerance")
        bottom.legend(loc="lower right", fontsize=8)
    bottom.set_xlabel("K / K_c")
    bottom.set_ylabel("max |dE/E|")
    fig.tight_layout()
    directory = os.path.dirname(os.path.abspath(output))
    suffix = os.path.splitext(output)[1] or ".png"
    fd, tmp = tempfile.mkstemp(suffix=suffix, dir=directory, prefix=".plot-")
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=120)
        os.replace(tmp, output)
    except BaseException:
        os.unlink(tmp)
        raise
    finally:
        plt.close(fig)
    return d


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m hmfnet.plot", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="results file of `hmfnet simulate -o`")
    parser.add_argument("-o", "--output", required=True, help="figure file (.png, .pdf, .svg)")
    parser.add_argument("--network", help="the run's network file (default: its recorded input)")
    args = parser.parse_args(argv)
    try:
        plot_run(args.run, args.output, args.network)
    except (OSError, ValueError, KeyError, RuntimeError) as e:  # RuntimeError: ConvergenceError
        print(f"hmfnet.plot: error: {e}", file=sys.stderr)
        return 1
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
