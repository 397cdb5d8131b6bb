"""Shared fixtures of the Python module's tests: the CLI beside the module (HMFNET_CLI, set by
CTest) and a few small networks written to files both can read."""
import json
import os
import subprocess

import networkx as nx
import pytest

import hmfnet


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("HMFNET_CLI")
    if not path:
        pytest.skip("HMFNET_CLI (the hmfnet executable) is not set; CTest sets it")
    return path


@pytest.fixture(scope="session")
def run_cli(cli):
    """Runs `hmfnet ARGS --json` and returns its JSON (or the CompletedProcess with json=False)."""

    def run(*args, parse=True):
        p = subprocess.run([cli, *map(str, args)], capture_output=True, text=True,
                           env={**os.environ, "OMP_NUM_THREADS": "1"})
        if not parse:
            return p
        assert p.returncode == 0, p.stderr
        return json.loads(p.stdout)

    return run


@pytest.fixture(scope="session")
def karate(tmp_path_factory):
    """Zachary's karate club (networkx's copy, weights dropped) and the same graph as a
    Matrix Market file the CLI reads."""
    net = hmfnet.Network.from_networkx(nx.karate_club_graph())
    path = tmp_path_factory.mktemp("karate") / "karate.mtx"
    net.save(str(path))
    return net, path
