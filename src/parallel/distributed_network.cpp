#include "parallel/distributed_network.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <utility>

#include "core/error.hpp"
#include "parallel/distributed_network_impl.hpp"

namespace hmfnet {

namespace {

const TpetraMatrix& stored_matrix(const DistributedNetwork::Impl& impl, const char* what) {
  if (impl.matrix.is_null()) {
    throw ParameterError(what, "the complete graph, held without stored rows",
                         "a network with stored rows (K_N: the rank-one force and the closed "
                         "forms of network/complete_graph.hpp)");
  }
  return *impl.matrix;
}

Teuchos::RCP<TpetraMatrix> assemble(const Network& net, const Teuchos::RCP<const TpetraMap>& map) {
  const auto local_rows = map->getNodeNumElements();
  std::vector<size_t> counts(local_rows);
  for (size_t r = 0; r < local_rows; ++r) {
    const auto i = static_cast<NodeIndex>(map->getGlobalElement(static_cast<LocalOrdinal>(r)));
    counts[r] = net.row(i).size();
  }
  auto matrix = Teuchos::rcp(new TpetraMatrix(
      map, Teuchos::ArrayView<const size_t>(counts.data(), static_cast<int>(counts.size())),
      Tpetra::StaticProfile));
  std::vector<GlobalOrdinal> cols;
  std::vector<double> vals;
  for (size_t r = 0; r < local_rows; ++r) {
    const GlobalOrdinal gi = map->getGlobalElement(static_cast<LocalOrdinal>(r));
    const auto i = static_cast<NodeIndex>(gi);
    cols.clear();
    vals.clear();
    for (const auto [j, w] : net.row(i)) {
      cols.push_back(j);
      vals.push_back(w);
    }
    if (cols.empty()) continue;
    const auto len = static_cast<int>(cols.size());
    matrix->insertGlobalValues(gi, Teuchos::ArrayView<const GlobalOrdinal>(cols.data(), len),
                               Teuchos::ArrayView<const double>(vals.data(), len));
  }
  matrix->fillComplete();
  return matrix;
}

}  // namespace

DistributedNetwork::DistributedNetwork(const Network& network) : m_impl(std::make_unique<Impl>()) {
  auto comm = Tpetra::getDefaultComm();
  m_impl->map =
      Teuchos::rcp(new TpetraMap(static_cast<Tpetra::global_size_t>(network.size()), 0, comm));
  m_impl->matrix = assemble(network, m_impl->map);
  m_impl->weighted = network.weighted();
}

DistributedNetwork::DistributedNetwork(const CompleteGraph& graph)
    : m_impl(std::make_unique<Impl>()) {
  auto comm = Tpetra::getDefaultComm();
  m_impl->map = Teuchos::rcp(new TpetraMap(static_cast<Tpetra::global_size_t>(graph.n), 0, comm));
  m_impl->implicit_nnz = graph.nnz();
}

DistributedNetwork::~DistributedNetwork() = default;

const DistributedNetwork::Impl& tpetra_impl(const DistributedNetwork& network) {
  return *network.m_impl;
}

NodeIndex DistributedNetwork::global_size() const {
  return static_cast<NodeIndex>(m_impl->map->getGlobalNumElements());
}

NodeIndex DistributedNetwork::local_size() const {
  return static_cast<NodeIndex>(m_impl->map->getNodeNumElements());
}

NodeIndex DistributedNetwork::first_row() const {
  return static_cast<NodeIndex>(m_impl->map->getMinGlobalIndex());
}

EdgeOffset DistributedNetwork::global_nnz() const {
  if (m_impl->matrix.is_null()) return m_impl->implicit_nnz;
  return static_cast<EdgeOffset>(m_impl->matrix->getGlobalNumEntries());
}

bool DistributedNetwork::stores_rows() const { return !m_impl->matrix.is_null(); }

void DistributedNetwork::apply(const std::vector<double>& x_local,
                               std::vector<double>& y_local) const {
  TpetraMultiVector x(m_impl->map, 1), y(m_impl->map, 1);
  {
    auto xv = x.getDataNonConst(0);
    std::copy(x_local.begin(), x_local.begin() + local_size(), xv.begin());
  }
  stored_matrix(*m_impl, "DistributedNetwork::apply").apply(x, y);
  const auto yv = y.getData(0);
  y_local.assign(yv.begin(), yv.end());
}

std::vector<double> DistributedNetwork::gather(const std::vector<double>& x_local) const {
  const auto n = static_cast<size_t>(global_size());
  std::vector<double> mine(n, 0.0), all(n, 0.0);
  const auto first = static_cast<size_t>(first_row());
  for (size_t r = 0; r < x_local.size(); ++r) mine[first + r] = x_local[r];
  // Blocks are disjoint, so a sum reduction assembles the vector exactly (x + 0 = x).
  Teuchos::reduceAll(*m_impl->map->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n), mine.data(),
                     all.data());
  return all;
}

}  // namespace hmfnet

namespace hmfnet {

DistributedNetwork::LocalAdjacency DistributedNetwork::local_adjacency() const {
  const auto& matrix = stored_matrix(*m_impl, "DistributedNetwork::local_adjacency");
  const auto col_map = matrix.getColMap();
  LocalAdjacency a;
  a.columns = static_cast<NodeIndex>(col_map->getNodeNumElements());
  a.row_ptr.assign(1, 0);
  std::vector<std::pair<GlobalOrdinal, std::pair<NodeIndex, double>>> row;
  const auto rows = static_cast<LocalOrdinal>(local_size());
  for (LocalOrdinal r = 0; r < rows; ++r) {
    TpetraMatrix::local_inds_host_view_type indices;
    TpetraMatrix::values_host_view_type values;
    matrix.getLocalRowView(r, indices, values);
    row.clear();
    for (size_t k = 0; k < indices.extent(0); ++k) {
      row.push_back({col_map->getGlobalElement(indices(k)), {indices(k), values(k)}});
    }
    // Global column order, so every rank count sums a row in the same order as the serial CSR.
    std::sort(row.begin(), row.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& entry : row) {
      a.cols.push_back(entry.second.first);
      if (m_impl->weighted) a.weights.push_back(entry.second.second);
    }
    a.row_ptr.push_back(static_cast<EdgeOffset>(a.cols.size()));
  }
  return a;
}

bool DistributedNetwork::columns_are_owned_rows() const {
  return stored_matrix(*m_impl, "DistributedNetwork::columns_are_owned_rows")
      .getColMap()
      ->isSameAs(*m_impl->map);
}

void DistributedNetwork::import_columns(const double* owned, int width, double* columns) const {
  const auto col_map = stored_matrix(*m_impl, "DistributedNetwork::import_columns").getColMap();
  if (m_impl->row_to_columns.is_null()) {
    m_impl->row_to_columns = Teuchos::rcp(new TpetraImport(m_impl->map, col_map));
  }
  const auto w = static_cast<size_t>(width);
  auto& impl = *m_impl;
  if (impl.import_source.is_null() || impl.import_source->getNumVectors() != w) {
    impl.import_source = Teuchos::rcp(new TpetraMultiVector(impl.map, w));
    impl.import_target = Teuchos::rcp(new TpetraMultiVector(col_map, w));
  }
  TpetraMultiVector& source = *impl.import_source;
  TpetraMultiVector& target = *impl.import_target;
  const auto n_owned = static_cast<size_t>(local_size());
  {
    auto view = source.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t r = 0; r < n_owned; ++r)
      for (size_t c = 0; c < w; ++c) view(r, c) = owned[r * w + c];
  }
  target.doImport(source, *m_impl->row_to_columns, Tpetra::INSERT);
  const auto view = target.getLocalViewHost(Tpetra::Access::ReadOnly);
  const size_t n_columns = col_map->getNodeNumElements();
  for (size_t r = 0; r < n_columns; ++r)
    for (size_t c = 0; c < w; ++c) columns[r * w + c] = view(r, c);
}

}  // namespace hmfnet
