"""hmfnet.Network from scipy.sparse, networkx, files and generators: the same network every way
it can be made, and the readers' checks as Python exceptions."""
import networkx as nx
import numpy as np
import pytest
import scipy.sparse as sp

import hmfnet


def csr(net):
    return net.to_scipy().toarray()


def test_networkx_and_its_scipy_matrix_give_the_same_network():
    G = nx.les_miserables_graph()  # weighted, string node labels
    for weight in (None, "weight"):
        a = hmfnet.Network.from_networkx(G, weight=weight)
        b = hmfnet.Network.from_scipy(nx.to_scipy_sparse_array(G, weight=weight))
        np.testing.assert_array_equal(csr(a), csr(b))
        assert a.n == G.number_of_nodes() and a.edges == G.number_of_edges()
    assert hmfnet.Network.from_networkx(G, weight="weight").weighted
    assert not hmfnet.Network.from_networkx(G).weighted


def test_scipy_weights_kept_in_every_sparse_format():
    rng = np.random.default_rng(5)
    W = sp.random(40, 40, density=0.2, random_state=6, format="csr")
    W = W + W.T
    for fmt in ("csr", "csc", "coo", "lil", "dok"):
        net = hmfnet.Network.from_scipy(W.asformat(fmt))
        np.testing.assert_array_equal(csr(net), W.toarray())
    dense = rng.random((5, 5))
    np.testing.assert_array_equal(csr(hmfnet.Network.from_scipy(dense + dense.T)),
                                  dense + dense.T)


def test_non_symmetric_refused_unless_symmetrized():
    A = sp.csr_matrix(np.array([[0, 1, 0], [0, 0, 2], [1, 2, 0]], float))
    with pytest.raises(hmfnet.InputError, match="not symmetric.*symmetrize=True"):
        hmfnet.Network.from_scipy(A)
    with pytest.warns(UserWarning, match="using \\(A\\+A\\^T\\)/2"):
        net = hmfnet.Network.from_scipy(A, symmetrize=True)
    np.testing.assert_array_equal(csr(net), (A + A.T).toarray() / 2)
    with pytest.raises(hmfnet.InputError, match="not symmetric"):
        hmfnet.Network.from_networkx(nx.DiGraph([(0, 1), (1, 2)]))


@pytest.mark.parametrize("value, message", [(-1.0, "weight"), (np.nan, "weight"),
                                            (np.inf, "weight")])
def test_bad_weights_name_the_entry(value, message):
    A = np.zeros((3, 3))
    A[0, 1] = A[1, 0] = value
    with pytest.raises(hmfnet.InputError, match=f"scipy matrix:[12]: .*{message}"):
        hmfnet.Network.from_scipy(A)


def test_shapes_and_empty_matrices_refused():
    with pytest.raises(ValueError, match="not square"):
        hmfnet.Network.from_scipy(sp.csr_matrix((3, 4)))
    with pytest.raises(hmfnet.InputError):
        hmfnet.Network.from_scipy(sp.csr_matrix((3, 3)))  # no links: the readers refuse it


def test_explicit_zeros_dropped_with_a_warning():
    A = sp.coo_matrix(([1.0, 1.0, 0.0, 0.0], ([0, 1, 1, 2], [1, 0, 2, 1])), shape=(3, 3))
    with pytest.warns(UserWarning, match="zero"):
        net = hmfnet.Network.from_scipy(A)
    assert net.nnz == 2


def test_file_round_trip_and_read_errors(tmp_path):
    net = hmfnet.Network.from_networkx(nx.les_miserables_graph(), weight="weight")
    for name in ("a.h5", "a.mtx", "a.txt"):
        net.save(str(tmp_path / name))
        np.testing.assert_array_equal(csr(hmfnet.read_network(tmp_path / name)), csr(net))
    bad = tmp_path / "bad.txt"
    bad.write_text("0 1\n1 x\n")
    with pytest.raises(hmfnet.InputError, match=f"{bad}:2"):
        hmfnet.read_network(bad)
    with pytest.raises(hmfnet.InputError, match="missing.mtx"):
        hmfnet.read_network(tmp_path / "missing.mtx")
    with pytest.raises(ValueError, match="--index-base"):
        hmfnet.read_network(bad, index_base=2)
    one_based = tmp_path / "one.txt"
    one_based.write_text("1 2\n2 3\n")
    assert hmfnet.read_network(one_based, index_base=1).n == 3


def test_generators_equal_the_cli(tmp_path, run_cli):
    cases = [
        (["er", "--n", 300, "--mean-degree", 8, "--seed", 4],
         lambda: hmfnet.generate.er(300, mean_degree=8, seed=4)),
        (["sf", "--n", 300, "--alpha", 2.5, "--dmin", 3, "--seed", 4],
         lambda: hmfnet.generate.sf(300, alpha=2.5, dmin=3, seed=4)),
        (["sbm", "--half", 100, "--p-in", 0.1, "--p-out", 0.01, "--seed", 4],
         lambda: hmfnet.generate.sbm(100, p_in=0.1, p_out=0.01, seed=4)),
        (["regular", "--n", 300, "--degree", 6, "--seed", 4],
         lambda: hmfnet.generate.regular(300, degree=6, seed=4)),
    ]
    for args, make in cases:
        path = tmp_path / f"{args[0]}.mtx"
        run_cli("generate", *args, "-o", path, parse=False).check_returncode()
        np.testing.assert_array_equal(csr(make()), csr(hmfnet.read_network(path)))


def test_generator_and_complete_graph_errors():
    with pytest.raises(ValueError, match="--q"):
        hmfnet.generate.er(10, q=1.5, seed=1)
    with pytest.raises(ValueError, match="one of --q or --mean-degree"):
        hmfnet.generate.er(10, seed=1)
    with pytest.raises(ValueError, match="--n"):
        hmfnet.generate.complete(1)
    with pytest.raises(ValueError, match="n d even"):
        hmfnet.generate.regular(11, degree=3, seed=1)
    with pytest.raises(ValueError, match="--seed"):
        hmfnet.generate.er(10, q=0.5, seed=-1)


def test_complete_graph_held_implicitly(tmp_path):
    k = hmfnet.generate.complete(10**6)
    assert k.is_complete and k.n == 10**6 and k.nnz == 10**6 * (10**6 - 1)
    with pytest.raises(ValueError, match="complete graph"):
        k.to_scipy()
    small = hmfnet.generate.complete(300)
    small.save(str(tmp_path / "k.h5"))
    assert hmfnet.read_network(tmp_path / "k.h5").is_complete


def test_duplicate_entries_refused_as_the_readers_refuse_them():
    A = sp.coo_matrix(([1.0, 1.0, 1.0, 1.0], ([0, 0, 1, 1], [1, 1, 0, 0])), shape=(2, 2))
    with pytest.raises(hmfnet.InputError, match="scipy matrix:2: .*duplicate"):
        hmfnet.Network.from_scipy(A)


@pytest.mark.parametrize("weight", [None, "weight"])
def test_networkx_self_loops_equal_the_matrix_market_reader(tmp_path, weight):
    # networkx writes an undirected self-loop as the diagonal entries w, w and -w; the file
    # readers store A_nn = w. Weight 2.5 on a loop tells w from 2w.
    G = nx.Graph()
    G.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 2.0), (2, 0, 1.5), (2, 3, 1.0), (3, 3, 2.5),
                               (0, 0, 1.0)])
    field, lines = ("real", ["2 1 1", "3 2 2", "3 1 1.5", "4 3 1", "4 4 2.5", "1 1 1"])
    if weight is None:
        field, lines = "pattern", [" ".join(line.split()[:2]) for line in lines]
    path = tmp_path / "loops.mtx"
    path.write_text(f"%%MatrixMarket matrix coordinate {field} symmetric\n4 4 6\n"
                    + "\n".join(lines) + "\n")
    from_file = hmfnet.read_network(path)
    net = hmfnet.Network.from_networkx(G, weight=weight)
    np.testing.assert_array_equal(csr(net), csr(from_file))
    a, b = hmfnet.spectrum(net), hmfnet.spectrum(from_file)
    assert a["lambda"] == pytest.approx(b["lambda"], rel=1e-12)
    for key in ("nnz", "edges", "self_loops"):
        assert a[key] == b[key], key
    assert a["self_loops"] == 2 and net.nnz == 2 * (6 - 2) + 2


@pytest.mark.parametrize("matrix", [
    sp.csr_matrix(np.array([[0, 1 + 2j], [1 - 2j, 0]])),
    np.array([[0, 1], [1, 0]], dtype=complex),  # a zero imaginary part is still complex
])
def test_complex_matrices_refused_as_the_matrix_market_reader_refuses_them(matrix):
    with pytest.raises(hmfnet.InputError,
                       match="^scipy matrix: dtype 'complex128' is not supported"):
        hmfnet.Network.from_scipy(matrix)
    with pytest.raises(hmfnet.InputError, match="^mine: dtype"):
        hmfnet.Network.from_scipy(matrix, source="mine")
