#include "parallel/distributed_network.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <Tpetra_Core.hpp>

#include "parallel/distributed_network_impl.hpp"

namespace hmfnet {

namespace {

Teuchos::RCP<TpetraMatrix> assemble(const Network& net, const Teuchos::RCP<const TpetraMap>& map) {
  const auto local_rows = map->getNodeNumElements();
  std::vector<size_t> counts(local_rows);
  for (size_t r = 0; r < local_rows; ++r) {
    const auto i = static_cast<NodeIndex>(map->getGlobalElement(static_cast<LocalOrdinal>(r)));
    counts[r] = static_cast<size_t>(net.row_end(i) - net.row_begin(i));
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
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      cols.push_back(net.col(k));
      vals.push_back(net.weight(k));
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
  m_impl->map = Teuchos::rcp(
      new TpetraMap(static_cast<Tpetra::global_size_t>(network.size()), 0, comm));
  m_impl->matrix = assemble(network, m_impl->map);
}

DistributedNetwork::~DistributedNetwork() = default;

NodeIndex DistributedNetwork::global_size() const {
  return static_cast<NodeIndex>(m_impl->map->getGlobalNumElements());
}

NodeIndex DistributedNetwork::local_size() const {
  return static_cast<NodeIndex>(m_impl->map->getNodeNumElements());
}

NodeIndex DistributedNetwork::first_row() const {
  return static_cast<NodeIndex>(m_impl->map->getMinGlobalIndex());
}

EdgeOffset DistributedNetwork::local_nnz() const {
  return static_cast<EdgeOffset>(m_impl->matrix->getNodeNumEntries());
}

EdgeOffset DistributedNetwork::global_nnz() const {
  return static_cast<EdgeOffset>(m_impl->matrix->getGlobalNumEntries());
}

void DistributedNetwork::apply(const std::vector<double>& x_local,
                               std::vector<double>& y_local) const {
  TpetraMultiVector x(m_impl->map, 1), y(m_impl->map, 1);
  {
    auto xv = x.getDataNonConst(0);
    std::copy(x_local.begin(), x_local.begin() + local_size(), xv.begin());
  }
  m_impl->matrix->apply(x, y);
  const auto yv = y.getData(0);
  y_local.assign(yv.begin(), yv.end());
}

std::vector<double> DistributedNetwork::gather(const std::vector<double>& x_local) const {
  const auto n = static_cast<size_t>(global_size());
  std::vector<double> mine(n, 0.0), all(n, 0.0);
  const auto first = static_cast<size_t>(first_row());
  for (size_t r = 0; r < x_local.size(); ++r) mine[first + r] = x_local[r];
  // Blocks are disjoint, so a sum reduction assembles the vector exactly (x + 0 = x).
  Teuchos::reduceAll(*m_impl->map->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n),
                     mine.data(), all.data());
  return all;
}

}  // namespace hmfnet
