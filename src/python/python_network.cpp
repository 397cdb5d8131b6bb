// `hmfnet.Network`, `hmfnet.read_network` and the generators, for src/python/module.cpp. A
// matrix from Python (scipy.sparse, networkx) is built by the file readers' builder
// (network/network_builder.hpp) as a `general` matrix, so it gets their checks and messages:
// negative or non-finite weights, duplicates, an asymmetric matrix refused unless symmetrised.
#include "python/python_network.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/network_generation.hpp"
#include "app/read_request.hpp"
#include "core/error.hpp"
#include "network/network_builder.hpp"
#include "parallel/distributed_network.hpp"

namespace py = pybind11;

namespace hmfnet::python {

DistributedInput PythonNetwork::distributed() const {
  DistributedInput in;
  if (const CompleteGraph* graph = input.complete()) {
    in.network = std::make_unique<DistributedNetwork>(*graph);
    in.complete = *graph;
  } else {
    in.network = std::make_unique<DistributedNetwork>(input.stored());
  }
  return in;
}

namespace {

using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using WeightArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Entry k of the COO arrays is "line" k + 1 of the source, so a message names the entry.
PythonNetwork from_entries(std::int64_t n, const IndexArray& rows, const IndexArray& cols,
                           const WeightArray& weights, bool symmetrize, const std::string& source) {
  if (n < 1 || n > std::numeric_limits<NodeIndex>::max()) {
    throw ParameterError("shape", std::to_string(n), "1 to 2147483647 nodes");
  }
  const auto count = static_cast<std::size_t>(rows.size());
  if (static_cast<std::size_t>(cols.size()) != count ||
      static_cast<std::size_t>(weights.size()) != count) {
    throw ParameterError("rows, cols, weights", "arrays of different lengths", "equal lengths");
  }
  const auto r = rows.unchecked<1>();
  const auto c = cols.unchecked<1>();
  const auto w = weights.unchecked<1>();
  std::vector<MatrixEntry> entries;
  entries.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    const auto line = static_cast<std::int64_t>(k) + 1;
    if (r(i) < 0 || r(i) >= n || c(i) < 0 || c(i) >= n) {
      throw InputError(source, line,
                       "index (" + std::to_string(r(i)) + "," + std::to_string(c(i)) +
                           ") outside 0.." + std::to_string(n - 1));
    }
    if (!(w(i) >= 0.0 && w(i) < HUGE_VAL)) {
      throw InputError(source, line,
                       "weight " + std::to_string(w(i)) + " (weights must be finite and >= 0)");
    }
    entries.push_back({static_cast<NodeIndex>(r(i)), static_cast<NodeIndex>(c(i)), w(i), line});
  }
  BuildOptions options;
  options.symmetry = EntrySymmetry::general;
  options.asymmetry = symmetrize ? AsymmetryPolicy::symmetrize : AsymmetryPolicy::reject;
  BuildResult built = build_network(source, static_cast<NodeIndex>(n), std::move(entries), options);
  PythonNetwork net{{std::move(built.network), std::move(built.warnings)}, source};
  return net;
}

py::tuple csr_arrays(const Network& net) {
  py::array_t<std::int64_t> indptr(static_cast<py::ssize_t>(net.row_ptr().size()));
  py::array_t<std::int64_t> indices(static_cast<py::ssize_t>(net.cols().size()));
  py::array_t<double> data(static_cast<py::ssize_t>(net.cols().size()));
  auto p = indptr.mutable_unchecked<1>();
  auto c = indices.mutable_unchecked<1>();
  auto d = data.mutable_unchecked<1>();
  for (std::size_t k = 0; k < net.row_ptr().size(); ++k)
    p(static_cast<py::ssize_t>(k)) = net.row_ptr()[k];
  for (std::size_t k = 0; k < net.cols().size(); ++k) {
    c(static_cast<py::ssize_t>(k)) = net.cols()[k];
    d(static_cast<py::ssize_t>(k)) = net.weight(static_cast<EdgeOffset>(k));
  }
  return py::make_tuple(indptr, indices, data);
}

// The network the generator makes, whole in memory (the one the CLI writes for the same request).
template <class Request>
PythonNetwork generated(const Request& request, const std::string& name) {
  app::GeneratedNetwork g = [&] {
    py::gil_scoped_release release;
    return app::generated_network(request);
  }();
  return {{std::move(g.network), {}}, "generate " + name};
}

// The generators' requests, every field settable by name (python/hmfnet/generate.py sets the
// keyword arguments it was given).
void bind_generate_requests(py::module_& m) {
  py::class_<app::ErRequest>(m, "ErRequest")
      .def(py::init<>())
      .def_readwrite("n", &app::ErRequest::n)
      .def_readwrite("q", &app::ErRequest::q)
      .def_readwrite("mean_degree", &app::ErRequest::mean_degree)
      .def_readwrite("seed", &app::ErRequest::seed);
  py::class_<app::SfRequest>(m, "SfRequest")
      .def(py::init<>())
      .def_readwrite("n", &app::SfRequest::n)
      .def_readwrite("alpha", &app::SfRequest::alpha)
      .def_readwrite("dmin", &app::SfRequest::d_min)
      .def_readwrite("mean_degree", &app::SfRequest::mean_degree)
      .def_readwrite("cutoff", &app::SfRequest::cutoff)
      .def_readwrite("link", &app::SfRequest::link)
      .def_readwrite("seed", &app::SfRequest::seed);
  py::class_<app::SbmRequest>(m, "SbmRequest")
      .def(py::init<>())
      .def_readwrite("half", &app::SbmRequest::half)
      .def_readwrite("p_in", &app::SbmRequest::p_in)
      .def_readwrite("p_out", &app::SbmRequest::p_out)
      .def_readwrite("seed", &app::SbmRequest::seed);
  py::class_<app::RegularRequest>(m, "RegularRequest")
      .def(py::init<>())
      .def_readwrite("n", &app::RegularRequest::n)
      .def_readwrite("degree", &app::RegularRequest::degree)
      .def_readwrite("seed", &app::RegularRequest::seed);
  py::class_<app::CompleteRequest>(m, "CompleteRequest")
      .def(py::init<>())
      .def_readwrite("n", &app::CompleteRequest::n)
      .def_readwrite("self_loops", &app::CompleteRequest::self_loops);
}

void bind_read_request(py::module_& m) {
  py::class_<app::ReadRequest>(m, "ReadRequest")
      .def(py::init<>())
      .def_readwrite("symmetrize", &app::ReadRequest::symmetrize)
      .def_readwrite("index_base", &app::ReadRequest::index_base)
      .def_readwrite("nodes", &app::ReadRequest::nodes);
}

}  // namespace

void bind_network(py::module_& m) {
  py::class_<PythonNetwork>(m, "Network",
                            "A network: stored rows (CSR) or the complete graph kept implicitly.")
      .def_static("_from_entries", &from_entries, py::arg("n"), py::arg("rows"), py::arg("cols"),
                  py::arg("weights"), py::arg("symmetrize"), py::arg("source"))
      .def_static(
          "complete",
          [](std::int64_t n, bool self_loops) {
            return PythonNetwork{{CompleteGraph::make(n, self_loops), {}}, "generate complete"};
          },
          py::arg("n"), py::arg("self_loops") = false,
          "The complete graph K_N held in O(1) space (lambda exact: N - 1, or N with self-loops).")
      .def_property_readonly("n", [](const PythonNetwork& p) { return p.input.size(); })
      .def_property_readonly("nnz",
                             [](const PythonNetwork& p) {
                               const CompleteGraph* g = p.input.complete();
                               return g != nullptr ? g->nnz() : p.input.stored().nnz();
                             })
      .def_property_readonly("edges",
                             [](const PythonNetwork& p) {
                               const CompleteGraph* g = p.input.complete();
                               return g != nullptr ? g->edges() : p.input.stored().edges();
                             })
      .def_property_readonly("weighted",
                             [](const PythonNetwork& p) {
                               return p.input.complete() == nullptr && p.input.stored().weighted();
                             })
      .def_property_readonly("is_complete",
                             [](const PythonNetwork& p) { return p.input.complete() != nullptr; })
      .def_property_readonly("source", [](const PythonNetwork& p) { return p.source; })
      .def_property_readonly("warnings", [](const PythonNetwork& p) { return p.input.warnings; })
      .def("_csr",
           [](const PythonNetwork& p) {
             if (p.input.complete() != nullptr) {
               throw ParameterError("to_scipy", "the complete graph held implicitly",
                                    "a network with stored rows (K_N has N (N - 1) entries)");
             }
             return csr_arrays(p.input.stored());
           })
      .def(
          "save",
          [](const PythonNetwork& p, const std::string& path) {
            if (const CompleteGraph* g = p.input.complete()) {
              write_complete_graph(path, *g);
            } else {
              write_network(path, p.input.stored());
            }
          },
          py::arg("path"),
          "Writes the network (.h5, .mtx, edge list .txt), to a temporary file then renamed.")
      .def("__repr__", [](const PythonNetwork& p) {
        return "<hmfnet.Network N=" + std::to_string(p.input.size()) + " from " + p.source + ">";
      });

  bind_read_request(m);
  m.def(
      "_read_network",
      [](const std::string& path, const app::ReadRequest& request) {
        app::validate(request);
        py::gil_scoped_release release;
        return PythonNetwork{read_network_input(path, app::read_options(request)), path};
      },
      py::arg("path"), py::arg("request"));
  bind_generate_requests(m);
  m.def("_generate_er", &generated<app::ErRequest>, py::arg("request"), py::arg("name") = "er");
  m.def("_generate_sf", &generated<app::SfRequest>, py::arg("request"), py::arg("name") = "sf");
  m.def("_generate_sbm", &generated<app::SbmRequest>, py::arg("request"), py::arg("name") = "sbm");
  m.def("_generate_regular", &generated<app::RegularRequest>, py::arg("request"),
        py::arg("name") = "regular");
  m.def(
      "_generate_complete",
      [](const app::CompleteRequest& request) {
        app::validate(request);
        return PythonNetwork{{CompleteGraph::make(request.n, request.self_loops), {}},
                             "generate complete"};
      },
      py::arg("request"));
}

}  // namespace hmfnet::python
