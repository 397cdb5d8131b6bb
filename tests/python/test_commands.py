"""spectrum, theory and simulate from Python against the CLI on the same network file and
parameters: the same services (src/app), so the numbers must agree to round-off (the network reaches the CLI through a file, rebuilt row by row: same matrix, same
order of operations; 1e-12 relative leaves room for nothing but that)."""
import json
import os
import shutil
import subprocess

import networkx as nx
import numpy as np
import pytest

import hmfnet

RTOL = 1e-12  # same code, same matrix: round-off only (see the module docstring)


def test_spectrum_equals_the_cli(karate, run_cli):
    net, path = karate
    py = hmfnet.spectrum(net, sigma0=0.35)
    cli = run_cli("spectrum", path, "--json", "--sigma0", 0.35)
    for key in ("lambda", "rho", "G", "Kc", "mean_degree", "lambda2"):
        assert py[key] == pytest.approx(cli[key], rel=RTOL), key
    for key in ("n", "nnz", "edges", "components", "bipartite", "warnings"):
        assert py[key] == cli[key], key
    # One list of fields (visit_spectrum_fields): the same keys, and the same values but the
    # clocks' and the memory's.
    assert set(py) == set(cli)
    for key in set(cli) - {"eigensolver_seconds", "peak_rss_mb_per_rank"}:
        assert py[key] == pytest.approx(cli[key], rel=RTOL), key


def test_theory_equals_the_cli(karate, run_cli):
    net, path = karate
    for momenta in ("gaussian", "waterbag"):
        py = hmfnet.theory(net, sigma0=0.35, K_over_Kc=[0.5, 1.5, 3.0], momenta=momenta)
        cli = run_cli("theory", path, "--json", "--sigma0", 0.35, "--K-over-Kc", "0.5,1.5,3",
                      "--momenta", momenta)
        for key in ("lambda", "Kc", "Kc_equilibrium", "G", "R_hat_iteration"):
            assert py[key] == pytest.approx(cli[key], rel=RTOL), key
        np.testing.assert_allclose(py["R"], [p["R"] for p in cli["points"]], rtol=RTOL)
        np.testing.assert_allclose(py["sigma2"], [p["sigma2"] for p in cli["points"]], rtol=RTOL)
        assert list(py["status"]) == [p["status"] for p in cli["points"]]
        assert py["R"].dtype == float and py["K"].shape == (3,)
        # One list of fields each (visit_theory_fields, visit_theory_point_fields,
        # visit_growth_fields): the CLI's keys at every level, with its values.
        assert set(cli) <= set(py)
        for key in set(cli) - {"points", "gamma", "peak_rss_mb_per_rank"}:
            assert py[key] == pytest.approx(cli[key], rel=RTOL), key
        assert [set(p) for p in py["points"]] == [set(p) for p in cli["points"]]
        assert py["gamma"] == pytest.approx(cli["gamma"], rel=RTOL)
        assert len(py["gamma"]) == 2  # K / K_c = 1.5 and 3 grow, 0.5 does not


def test_mpirun_started_from_a_python_session_runs_its_ranks(karate, cli):
    """The session's MPI start (a singleton) leaves nothing in the environment that a child
    inherits: Open MPI writes OMPI_MCA_ess=singleton and the like there, and an mpirun started
    with them gave its ranks a singleton's settings and failed (parallel_session.cpp)."""
    mpirun = shutil.which("mpirun")
    if mpirun is None:
        pytest.skip("no mpirun")
    net, path = karate
    py = hmfnet.spectrum(net, sigma0=0.35)  # MPI is running in this process by now
    flags = ["--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    # No env=: the child inherits this process's own environment, as a user's subprocess does.
    p = subprocess.run([mpirun, "-np", "2", *flags, cli, "spectrum", path, "--json",
                        "--sigma0", "0.35"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    ranks = json.loads(p.stdout)
    assert ranks["ranks"] == 2
    # 1e-10: the spectrum's default relative eigen-residual (`--tolerance`), which bounds how far
    # either run's lambda may be from the true one; measured on this network: the same bits.
    assert ranks["lambda"] == pytest.approx(py["lambda"], rel=1e-10)


def test_theory_on_the_complete_graph_needs_no_rows():
    th = hmfnet.theory(hmfnet.generate.complete(10**6), sigma0=0.35, K_over_Kc=[2.0])
    # eq:criticalKFirstOrder with lambda = N - 1 exactly.
    assert th["Kc"] == pytest.approx(2 * 0.35**2 * 10**6 / (10**6 - 1), rel=1e-15)
    assert 0.0 < th["R"][0] < 1.0


def test_simulate_equals_the_cli(karate, run_cli, tmp_path):
    net, path = karate
    args = dict(K_over_Kc=[1.5, 3.0], T=40, transient=10, seed=7, replicas=2, threads=1,
                record_stride=50)
    py = hmfnet.simulate(net, output=str(tmp_path / "py.h5"), **args)
    cli = run_cli("simulate", path, "--json", "--K-over-Kc", "1.5,3", "--T", 40, "--transient",
                  10, "--seed", 7, "--replicas", 2, "--threads", 1, "--record-stride", 50,
                  "-o", tmp_path / "cli.h5")
    # One code path and one thread: the integration is the same sequence of operations.
    np.testing.assert_array_equal(py["R_mean_replicas"],
                                  [p["R_mean_replicas"] for p in cli["points"]])
    np.testing.assert_array_equal(py["energy_rel_error_max"],
                                  [p["energy_rel_error_max"] for p in cli["points"]])
    assert py["steps"] == cli["steps"] == 2 * 4000
    assert py["R_mean_replicas"].shape == (2, 2)
    series = py["timeseries"]
    assert series["R"].shape == (len(series["t"]), 2) == series["energy"].shape
    # The results files of both hold the same numbers.
    a, b = hmfnet.read_run(tmp_path / "py.h5"), hmfnet.read_run(tmp_path / "cli.h5")
    for group in ("points", "timeseries"):
        for key in b[group]:
            np.testing.assert_array_equal(a[group][key], b[group][key], err_msg=key)
    np.testing.assert_array_equal(a["timeseries"]["R"], series["R"])
    # One list of fields each (app/simulate_service.hpp, dynamics/point_result.hpp): the dict has
    # every key of the CLI's JSON with its value, each point every key of the CLI's points, and
    # the time series every dataset of the results file's.
    assert set(cli) <= set(py)
    for key in cli:
        if key not in ("points", "integration_seconds", "nnz_steps_per_second",
                       "peak_rss_mb_per_rank"):
            assert py[key] == cli[key], key
    assert [set(p) for p in py["points"]] == [set(p) for p in cli["points"]]
    assert set(series) == set(b["timeseries"])


def test_simulate_on_the_device_is_the_cpu_run_or_refused(karate):
    # device="cuda": where a CUDA device runs it, the CPU's numbers bit for bit
    # (dynamics/device_stepper.hpp); elsewhere a ValueError naming why, in the CLI's words.
    net, _ = karate
    args = dict(K_over_Kc=[2.0], T=10, transient=2, seed=5, replicas=2, integrator="yoshida4")
    cpu = hmfnet.simulate(net, **args)
    assert cpu["device"] == "cpu"
    try:
        gpu = hmfnet.simulate(net, device="cuda", **args)
    except ValueError as e:
        assert str(e).startswith("--device cuda: ") and "run it with --device cpu" in str(e)
        return
    assert gpu["device"] != "cpu"
    np.testing.assert_array_equal(gpu["R_mean_replicas"], cpu["R_mean_replicas"])
    np.testing.assert_array_equal(gpu["timeseries"]["energy"], cpu["timeseries"]["energy"])


def test_read_run_round_trips_the_cli_file(karate, run_cli, tmp_path):
    _, path = karate
    out = tmp_path / "run.h5"
    cli = run_cli("simulate", path, "--json", "--K", "0.5,2", "--T", 20, "--transient", 5,
                  "--seed", 3, "--threads", 1, "-o", out)
    run = hmfnet.read_run(out)
    np.testing.assert_array_equal(run["points"]["K"], [0.5, 2.0])
    np.testing.assert_array_equal(run["points"]["R_mean"][:, 0],
                                  [p["R_mean"] for p in cli["points"]])
    assert run["parameters"]["replicas"][0]["seed"] == 3
    assert run["network"]["n"] == cli["n"] and run["network"]["lambda"] == cli["lambda"]
    assert run["attributes"]["steps"] == cli["steps"]
    assert list(run["points"]["integrator"]) == ["leapfrog", "leapfrog"]
    network_file = tmp_path / "k.h5"
    hmfnet.generate.complete(10).save(str(network_file))
    with pytest.raises(hmfnet.InputError, match="not an hmfnet results file"):
        hmfnet.read_run(network_file)
    garbage = tmp_path / "garbage.h5"
    garbage.write_bytes(b"not HDF5")
    with pytest.raises(hmfnet.InputError, match=f"^{garbage}: not an HDF5 file"):
        hmfnet.read_run(garbage)
    for missing in (tmp_path / "missing.h5", tmp_path):
        with pytest.raises(hmfnet.InputError, match=f"^{missing}: cannot open file for reading"):
            hmfnet.read_run(missing)


@pytest.mark.parametrize("call, message", [
    (lambda n: hmfnet.theory(n, sigma0=0.0, K=[1]), "--sigma0: value 0 is not allowed \\(allowed: > 0\\)"),
    (lambda n: hmfnet.theory(n, sigma0=0.3), "--K / --K-over-Kc"),
    (lambda n: hmfnet.theory(n, sigma0=0.3, K=[1], K_over_Kc=[1]), "excludes"),
    (lambda n: hmfnet.theory(n, sigma0=0.3, K=[1], momenta="lorentz"), "--momenta"),
    (lambda n: hmfnet.theory(n, sigma0=0.3, K=[1], tolerance=1.0), "--tolerance"),
    (lambda n: hmfnet.spectrum(n, lambda2="exact"), "--lambda2"),
    (lambda n: hmfnet.simulate(n, seed=1), "one of --K, --K-over-Kc or --K-sweep"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], h=-0.1), "--h: value -0.1"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], replicas=65), "--replicas"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], sigma0=float("nan")), "--sigma0"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], integrator="euler"), "euler"),
    (lambda n: hmfnet.simulate(n, seed=1, K_sweep="1:0:1"), "--K-sweep"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], resume=True), "--checkpoint"),
    (lambda n: hmfnet.simulate(n, seed=None, K=[1]), "--seed is required"),
    (lambda n: hmfnet.simulate(n, seed=-1, K=[1]), "--seed: value -1 is not allowed"),
    (lambda n: hmfnet.simulate(n, seed=2**64, K=[1]), "--seed: value 18446744073709551616"),
    (lambda n: hmfnet.simulate(n, seed=2**64 - 1, K=[1], replicas=2),
     "--seed: value 18446744073709551615 is not allowed \\(allowed: <= 2\\^64 - 2"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], force="dense"),
     "--force: dense not in \\{auto,sparse,rank-one\\}"),
])
def test_parameters_out_of_range_raise_value_error(karate, call, message):
    with pytest.raises(ValueError, match=message):
        call(karate[0])


def test_a_step_that_blows_up_raises(karate):
    with pytest.raises(hmfnet.SimulationBlowUp, match="energy"):
        hmfnet.simulate(karate[0], seed=1, K=[50.0], h=1.5, T=30, transient=0, threads=1)


@pytest.mark.parametrize("call, message", [
    # False is not "omit" for a number: it would run with the default T or sigma0.
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], T=False),
     "simulate: T=False: a bool is not a number \\(T takes a number\\)"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], sigma0=False), "simulate: sigma0=False"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], T=True), "simulate: T=True: a bool"),
    (lambda n: hmfnet.simulate(n, seed=True, K=[1]), "simulate: seed=True: a bool"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], transient=np.bool_(True)), "transient=True"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1, True]), "simulate: K=\\[1, True\\]"),
    (lambda n: hmfnet.simulate(n, seed=1, K=np.array([True])), "simulate: K=.*a bool"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], integrator=True),
     "integrator=True: a bool is not a string \\(integrator takes a string\\)"),
    (lambda n: hmfnet.simulate(n, seed=1, K=[1], node_data=1),
     "simulate: node_data=1: node_data is a flag"),
    (lambda n: hmfnet.spectrum(n, sigma0=True), "spectrum: sigma0=True"),
    (lambda n: hmfnet.theory(n, sigma0=0.3, K=[1], tolerance=False), "theory: tolerance=False"),
    (lambda n: hmfnet.read_network("x.mtx", nodes=True), "read_network: nodes=True"),
    (lambda n: hmfnet.generate.er(10, q=True, seed=1), "generate.er: q=True"),
    (lambda n: hmfnet.generate.regular(10, degree=2, seed=np.True_), "generate.regular: seed"),
    (lambda n: hmfnet.generate.complete(True), "generate.complete: n=True"),
])
def test_a_bool_is_refused_where_a_number_or_string_is_needed(karate, call, message):
    with pytest.raises(TypeError, match=message):
        call(karate[0])


def test_one_coupling_may_be_a_number_as_on_the_command_line(karate):
    one = hmfnet.simulate(karate[0], seed=1, K=np.float64(1.5), T=1, transient=0, threads=1)
    listed = hmfnet.simulate(karate[0], seed=1, K=[1.5], T=1, transient=0, threads=1)
    np.testing.assert_array_equal(one["R_mean"], listed["R_mean"])


def test_flags_take_bools_python_or_numpy(karate, tmp_path):
    for value in (True, np.True_):
        out = tmp_path / f"{type(value).__name__}.h5"
        hmfnet.simulate(karate[0], seed=1, K=[1.0], T=0.5, transient=0, threads=1,
                        node_data=value, restart_each_K=np.False_, output=str(out))
        assert hmfnet.read_run(out)["parameters"]["node_data"] is True
    assert hmfnet.generate.complete(5, self_loops=np.True_).nnz == 25


def test_an_output_or_checkpoint_over_the_input_file_is_refused_and_the_file_kept(karate, tmp_path):
    path = tmp_path / "k.mtx"
    karate[0].save(str(path))
    before = path.read_bytes()
    net = hmfnet.read_network(str(path))
    (tmp_path / "link.mtx").symlink_to(path)
    for where in ({"output": str(path)}, {"checkpoint": str(path)},
                  {"output": str(tmp_path / "." / "k.mtx")}, {"checkpoint": str(tmp_path / "link.mtx")}):
        with pytest.raises(hmfnet.InputError, match="names the same file as the input file"):
            hmfnet.simulate(net, seed=1, K=[1], T=10, transient=1, **where)
    assert path.read_bytes() == before


@pytest.mark.parametrize("options, message", [
    ({"K_sweep": "0:1:1e-300"}, "--K-sweep: 0:1:1e-300 gives 1e\\+300 K values \\(allowed: at most 10000"),
    ({"K": [1], "T": 1e300}, "T / h: 1e\\+300 / 0.01 = 1e\\+302 steps per K"),
    ({"K": [1], "h": 1e-300}, "T / h: 1000 / 1e-300 = 1e\\+303 steps per K"),
])
def test_options_that_expand_too_far_are_refused_at_once_in_short_numbers(karate, options, message):
    with pytest.raises(ValueError, match=message):
        hmfnet.simulate(karate[0], seed=1, **options)


def test_a_file_path_is_read_as_the_cli_reads_it(karate, tmp_path):
    net, path = karate
    # The same reader on the same file, then the same code: the same bits, str or pathlib.Path.
    run = dict(seed=3, K=[1.0], T=2, transient=0, threads=1)
    read = hmfnet.simulate(hmfnet.read_network(path), **run)
    for given in (str(path), path):
        np.testing.assert_array_equal(hmfnet.simulate(given, **run)["R_mean"], read["R_mean"])
        assert hmfnet.spectrum(given)["lambda"] == hmfnet.spectrum(net)["lambda"]
        assert hmfnet.theory(given, sigma0=0.35, K=[1.0])["Kc"] == \
            hmfnet.theory(net, sigma0=0.35, K=[1.0])["Kc"]
    # The path is the run's recorded input, so an output over it is refused and the file kept.
    before = path.read_bytes()
    with pytest.raises(hmfnet.InputError, match="names the same file as the input file"):
        hmfnet.simulate(path, output=str(path), **run)
    assert path.read_bytes() == before
    with pytest.raises(hmfnet.InputError, match="cannot open file for reading"):
        hmfnet.spectrum(tmp_path / "missing.mtx")
    # The reader's warnings point at the caller's line, as read_network's do.
    zeros = tmp_path / "zeros.mtx"
    zeros.write_text("%%MatrixMarket matrix coordinate real symmetric\n3 3 2\n2 1 1\n3 1 0\n")
    with pytest.warns(UserWarning, match="1 explicit zero entries dropped") as caught:
        hmfnet.spectrum(zeros)
    assert caught[0].filename == __file__


@pytest.mark.parametrize("given", [nx.karate_club_graph(), np.eye(3), b"karate.mtx", None])
def test_anything_else_raises_a_type_error_naming_the_converters(given):
    for call in (lambda: hmfnet.spectrum(given), lambda: hmfnet.theory(given, sigma0=0.35, K=[1]),
                 lambda: hmfnet.simulate(given, seed=1, K=[1])):
        with pytest.raises(TypeError, match=f"network of type {type(given).__name__} .*"
                           "Network.from_scipy\\(A\\).*Network.from_networkx\\(G\\)"):
            call()


@pytest.mark.parametrize("graph", [nx.path_graph(3), nx.star_graph(2), nx.cycle_graph(3),
                                   nx.path_graph(4), nx.complete_graph(2)])
def test_networks_of_two_to_four_nodes_work_in_every_command(graph):
    net = hmfnet.Network.from_networkx(graph)
    lam = float(np.linalg.eigvalsh(nx.to_numpy_array(graph))[-1])
    # Both are dense symmetric eigensolvers (N <= 64 is solved densely: spectral/perron.hpp):
    # backward stable, they differ by a few N eps lambda, far below 1e-12.
    assert hmfnet.spectrum(net)["lambda"] == pytest.approx(lam, rel=1e-12)
    assert hmfnet.theory(net, sigma0=0.35, K_over_Kc=[2.0])["points"][0]["status"] == "converged"
    run = hmfnet.simulate(net, seed=1, K_over_Kc=[2.0], T=10, transient=1)
    assert run["points"][0]["energy_rel_error_max"] < 1e-2
