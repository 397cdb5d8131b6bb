"""hmfnet: the Hamiltonian Mean Field model of coupled rotors on networks.

The C++ library behind the `hmfnet` command line, for Python. A network comes from scipy.sparse,
networkx, a file or a generator; `spectrum`, `theory` and `simulate` take it, or a file's path as
the CLI does, run the same code as the CLI's subcommands and return what `--json` prints, as a
dict (per-K fields and time series as numpy arrays). Parameters are the CLI's options as keyword
arguments (``K_over_Kc=[1.5, 2]`` is ``--K-over-Kc 1.5,2``), checked by the same checks as the
command line: a value out of range raises ValueError with the CLI's message, naming the option
and its range.

    import networkx as nx, hmfnet
    net = hmfnet.Network.from_networkx(nx.karate_club_graph())
    hmfnet.spectrum(net)["lambda"]
    hmfnet.theory(net, sigma0=0.35, K_over_Kc=[1.5, 2.0])["R"]
    run = hmfnet.simulate(net, K_over_Kc=[2.0], T=200, transient=100, seed=1)
"""
import os as _os
import warnings as _warnings

import numpy as _np

from . import _hmfnet
from ._arguments import request as _request
from ._hmfnet import ConvergenceError, InputError, Network, SimulationBlowUp
from .run_file import read_run
from . import generate

__all__ = [
    "Network", "read_network", "generate", "spectrum", "theory", "simulate", "read_run",
    "InputError", "ConvergenceError", "SimulationBlowUp",
]


def _warn(net, stacklevel=3):
    for w in net.warnings:
        _warnings.warn(w, stacklevel=stacklevel)
    return net


def _from_scipy(A, symmetrize=False, source="scipy matrix"):
    """A network from any scipy.sparse matrix (or a dense 2-D array): A_nm is the weight of the
    link n-m. It must be symmetric, with finite weights >= 0; a non-symmetric matrix raises
    InputError unless ``symmetrize=True``, which uses (A + A^T)/2 with a warning (the
    antisymmetric part does not act on the dynamics, eq:hamiltonianNetworkCase). Explicit zeros
    are dropped with a warning; a duplicate entry is refused, as the file readers refuse it.
    Weights must be real: a complex matrix raises InputError, as a Matrix Market file of field
    'complex' does. Entry k of ``A.tocoo()`` is named "SOURCE:k+1" in messages."""
    import scipy.sparse as sp

    coo = sp.coo_matrix(A)
    if coo.ndim != 2 or coo.shape[0] != coo.shape[1]:
        raise ValueError(f"{source}: shape {coo.shape} is not square (allowed: N x N)")
    if coo.dtype.kind == "c":
        # Casting to float64 would drop the imaginary part without a word.
        raise InputError(f"{source}: dtype '{coo.dtype}' is not supported (bool, integer, real)")
    try:
        net = Network._from_entries(coo.shape[0], _np.asarray(coo.row, dtype=_np.int64),
                                    _np.asarray(coo.col, dtype=_np.int64),
                                    _np.asarray(coo.data, dtype=_np.float64), symmetrize, source)
    except InputError as e:
        # The builder speaks the CLI's language; here the option is a keyword argument.
        raise InputError(str(e).replace("--symmetrize", "symmetrize=True")) from None
    return _warn(net)


def _from_networkx(G, weight=None, symmetrize=False):
    """A network from a networkx graph, nodes in ``G.nodes`` order (``list(G)[n]`` is node n).
    ``weight=None`` links every edge with weight 1; ``weight="w"`` reads that edge attribute
    (missing: 1). A directed graph is a non-symmetric matrix: refused unless ``symmetrize``.
    A self-loop of weight w is A_nn = w, as the file readers store it; the weights of a
    multigraph's parallel edges are summed (networkx's own matrix)."""
    import networkx as nx

    A = nx.to_scipy_sparse_array(G, weight=weight, format="coo", dtype=float)
    # For an undirected graph networkx writes a self-loop as the entries w, w and -w on the
    # diagonal (it symmetrises, then subtracts the doubled diagonal) and a multigraph's parallel
    # edges as repeated entries: the sums are the matrix it means.
    A.sum_duplicates()
    return _from_scipy(A, symmetrize=symmetrize, source="networkx graph")


def _to_scipy(self):
    """The stored rows as a scipy.sparse.csr_matrix (the complete graph, held implicitly, has
    none)."""
    import scipy.sparse as sp

    indptr, indices, data = self._csr()
    return sp.csr_matrix((data, indices, indptr), shape=(self.n, self.n))


Network.from_scipy = staticmethod(_from_scipy)
Network.from_networkx = staticmethod(_from_networkx)
Network.to_scipy = _to_scipy


def _read(path, stacklevel, **options):
    return _warn(_hmfnet._read_network(_os.fspath(path), _request(
        "read_network", _hmfnet.ReadRequest(), **options)), stacklevel)


def read_network(path, symmetrize=False, index_base=0, nodes=0):
    """Reads a network file (.h5, .mtx, edge list) as the CLI does (FILE:LINE errors raise
    InputError); the options are the CLI's --symmetrize, --index-base and --nodes."""
    return _read(path, 4, symmetrize=symmetrize, index_base=index_base, nodes=nodes)


def _network(where, network):
    """The network a command runs on: a Network as given, or a file path (str or os.PathLike)
    read as read_network reads it with its defaults, as the CLI reads its positional argument.
    Anything else raises TypeError naming the converters, not pybind11's list of overloads."""
    if isinstance(network, Network):
        return network
    if isinstance(network, (str, _os.PathLike)):
        # Its warnings point at the line that called `where` (_warn, _read, _network, where).
        return _read(network, 5)
    raise TypeError(f"{where}: network of type {type(network).__name__} (allowed: an "
                    "hmfnet.Network or a file path; a scipy matrix: Network.from_scipy(A), a "
                    "networkx graph: Network.from_networkx(G))")


def _per_K_arrays(points, fields):
    return {f: _np.array([p[f] for p in points]) for f in fields if points and f in points[0]}


def spectrum(network, sigma0=None, tolerance=None, lambda2=None):
    """`hmfnet spectrum --json`: lambda, the Perron vector's summaries, rho, G, lambda_2 or its
    bounds, structure, warnings, and K_c when sigma0 is given. ``network``: an hmfnet.Network or
    a file's path (read as read_network reads it)."""
    request = _request("spectrum", _hmfnet.SpectrumRequest(), sigma0=sigma0, tolerance=tolerance,
                       lambda2=lambda2)
    return _hmfnet._spectrum(_network("spectrum", network), request)


def theory(network, sigma0, K=None, K_over_Kc=None, momenta=None, tolerance=None):
    """`hmfnet theory --json`: K_c (the linear threshold of `momenta`), Kc_equilibrium, G, the
    growth rates and the synchronized state R(K) (eq:rSigmaBesselMain) at each K. The per-K
    fields (K, K_over_Kc, R, R_onset, sigma2, status, linearly_stable, iterations, residual) are
    also returned as numpy arrays at the top level; raises ConvergenceError naming every K
    whose solve failed. ``network``: an hmfnet.Network or a file's path."""
    request = _request("theory", _hmfnet.TheoryRequest(), sigma0=sigma0, K=K, K_over_Kc=K_over_Kc,
                       momenta=momenta, tolerance=tolerance)
    out = _hmfnet._theory(_network("theory", network), request)
    for w in out.pop("warnings"):
        _warnings.warn(w, stacklevel=2)
    out.update(_per_K_arrays(out["points"], ["K", "K_over_Kc", "R", "R_onset", "sigma2", "status",
                                             "linearly_stable", "iterations", "residual"]))
    return out


def simulate(network, *, seed, K=None, K_over_Kc=None, K_sweep=None, sigma0=None, omega=None,
             momenta=None, h=None, T=None, transient=None, replicas=None, threads=None,
             integrator=None, precision=None, force=None, output=None, checkpoint=None,
             resume=False, node_data=False, rotor_node=None, phase_bins=None,
             restart_each_K=False, K_across_replicas=False, record_stride=None,
             energy_tolerance=None, device=None):
    """`hmfnet simulate --json` with the same options (defaults as the CLI: sigma0 0.35,
    omega 6, h 0.01, T 1000, transient 500, leapfrog), set on a typed request and checked by the
    request's own validation (the CLI's messages); threads=0 is the default count, as leaving
    it out (the thread rule's, or on a long enough run the count whose first steps ran fastest);
    device="cuda" steps on a CUDA GPU (the same bits as "cpu", the default). ``network``: an
    hmfnet.Network or a file's path. Returns its dict; the per-K fields (K, K_over_Kc, R_mean,
    R_sem, energy_rel_error_max, momentum_drift) also as numpy arrays, R_mean_replicas /
    R_sem_replicas as [K x replicas] arrays, and ``timeseries`` with t, K [records] and R,
    energy, momentum [records x replicas]. ``output`` writes the CLI's results
    file (read it with read_run). The GIL is released while it integrates; Ctrl-C stops the run
    at the next record and raises KeyboardInterrupt (with ``checkpoint``, resumable)."""
    if seed is None:
        raise ValueError("--seed is required (an integer 0 <= seed < 2^64)")
    request = _request(
        "simulate", _hmfnet.SimulateRequest(), seed=seed, K=K, K_over_Kc=K_over_Kc,
        K_sweep=K_sweep, sigma0=sigma0, omega=omega, momenta=momenta, h=h, T=T,
        transient=transient, replicas=replicas, threads=threads, integrator=integrator,
        precision=precision, force=force, output=output, checkpoint=checkpoint, resume=resume,
        node_data=node_data, rotor_node=rotor_node, phase_bins=phase_bins,
        restart_each_K=restart_each_K, K_across_replicas=K_across_replicas,
        record_stride=record_stride, energy_tolerance=energy_tolerance, device=device)
    out = _hmfnet._simulate(_network("simulate", network), request)
    points = out.get("points", [])
    out.update(_per_K_arrays(points, ["K", "K_over_Kc", "R_mean", "R_sem", "energy_rel_error_max",
                                      "momentum_drift", "R_mean_replicas", "R_sem_replicas"]))
    return out
