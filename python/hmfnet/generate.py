"""The generators of `hmfnet generate`, returning the network in memory (the same network the
CLI writes for the same parameters and seed). The keyword arguments set the generator's typed
request, checked in the CLI's words (src/app/generate_requests.hpp)."""
from . import _hmfnet
from ._arguments import request as _request


def er(n, *, seed, q=None, mean_degree=None):
    """Erdos-Renyi G(N, q): each pair linked with probability q (or q = d / (N - 1))."""
    return _hmfnet._generate_er(_request("generate.er", _hmfnet.ErRequest(), n=n, q=q,
                                         mean_degree=mean_degree, seed=seed))


def sf(n, *, alpha, seed, dmin=None, mean_degree=None, cutoff=None, link=None):
    """Scale-free Chung-Lu network, power-law targets P(d) ~ d^-alpha for d > dmin."""
    return _hmfnet._generate_sf(_request("generate.sf", _hmfnet.SfRequest(), n=n, alpha=alpha,
                                         dmin=dmin, mean_degree=mean_degree, cutoff=cutoff,
                                         link=link, seed=seed))


def sbm(half, *, p_in, p_out, seed):
    """Two-block stochastic block model: 2 half nodes, p_in inside a block, p_out across."""
    return _hmfnet._generate_sbm(_request("generate.sbm", _hmfnet.SbmRequest(), half=half,
                                          p_in=p_in, p_out=p_out, seed=seed))


def regular(n, *, degree, seed):
    """Random d-regular graph: every node has exactly `degree` neighbours (pairing model)."""
    return _hmfnet._generate_regular(_request("generate.regular", _hmfnet.RegularRequest(), n=n,
                                              degree=degree, seed=seed))


def complete(n, *, self_loops=False):
    """The complete graph K_N, held in O(1) space."""
    return _hmfnet._generate_complete(_request("generate.complete", _hmfnet.CompleteRequest(),
                                               n=n, self_loops=self_loops))
