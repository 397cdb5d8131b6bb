"""`python3 -m hmfnet.plot RUN.h5 -o FIG.png`: draws what the run file and the theory hold, and
refuses what is not a run file without leaving a figure behind."""
import os
import subprocess
import sys

import numpy as np
import pytest

import hmfnet
from hmfnet.plot import plot_data, plot_run


@pytest.fixture(scope="module")
def run_file(karate, run_cli, tmp_path_factory):
    _, network = karate
    out = tmp_path_factory.mktemp("plot") / "run.h5"
    cli = run_cli("simulate", network, "--json", "--K-over-Kc", "0.5,1.5,3", "--T", 20,
                  "--transient", 5, "--seed", 2, "--replicas", 3, "--threads", 1, "-o", out)
    return out, network, cli


def test_draws_the_run_and_the_theory(run_file, tmp_path):
    path, network, cli = run_file
    data = plot_run(path, str(tmp_path / "fig.png"))  # network from the run's recorded input
    assert (tmp_path / "fig.png").stat().st_size > 10_000
    run = hmfnet.read_run(path)
    # The points and error bars are the CLI's own mean and combined SEM over the replicas.
    np.testing.assert_allclose(data["R"], [p["R_mean"] for p in cli["points"]], rtol=1e-14)
    np.testing.assert_allclose(data["R_sem"], [p["R_sem"] for p in cli["points"]], rtol=1e-14)
    np.testing.assert_array_equal(data["K_over_Kc"], [0.5, 1.5, 3.0])
    assert np.all(data["R_spread"] > 0)
    # The curve is the theory of the run's network at the run's sigma0 (eq:rSigmaBesselMain),
    # the same warm-started sweep over the same K: equal to round-off.
    Kc = run["network"]["Kc"]
    th = hmfnet.theory(hmfnet.read_network(network), sigma0=0.35,
                       K=list(data["theory_K_over_Kc"] * Kc))
    np.testing.assert_allclose(data["theory_R"], th["R"], rtol=1e-12)
    assert np.all(data["theory_R"][data["theory_K_over_Kc"] < 0.99] < 1e-8)


def test_a_network_read_otherwise_than_the_run_gives_no_theory(run_file, tmp_path):
    path, network, _ = run_file
    edges = tmp_path / "edges.txt"
    hmfnet.read_network(network).save(str(edges))
    # Read 1-based, the same file has one node fewer than the run's network.
    one_based = tmp_path / "one.txt"
    one_based.write_text("".join(f"{int(a) + 1} {int(b) + 1}\n" for a, b in
                                 (line.split() for line in edges.read_text().splitlines()
                                  if line and not line.startswith("#"))))
    data = plot_data(path, network=str(one_based))  # read 0-based: N + 1 nodes
    assert "theory_R" not in data and "no theory" in data["title"]


def test_without_its_network_the_run_is_drawn_without_theory(karate, tmp_path):
    net, _ = karate
    path = tmp_path / "py.h5"
    hmfnet.simulate(net, K=[1.0, 2.0], T=10, transient=2, seed=1, threads=1, output=str(path))
    data = plot_run(path, str(tmp_path / "fig.png"))  # its input was "networkx graph"
    assert "theory_R" not in data and "no theory" in data["title"]
    assert (tmp_path / "fig.png").exists()
    with pytest.raises(FileNotFoundError, match="no-such.mtx"):
        plot_data(path, network=str(tmp_path / "no-such.mtx"))
    assert "theory_R" in plot_data(path, network=net)  # a Network object is accepted too


def test_command_line_refuses_a_file_that_is_not_a_run(tmp_path):
    network = tmp_path / "k.h5"
    hmfnet.generate.complete(10).save(str(network))
    figure = tmp_path / "fig.png"
    p = subprocess.run([sys.executable, "-m", "hmfnet.plot", str(network), "-o", str(figure)],
                       capture_output=True, text=True, env=os.environ.copy())
    assert p.returncode == 1
    assert "not an hmfnet results file" in p.stderr
    assert not figure.exists() and not list(tmp_path.glob(".plot-*"))
