#include "parallel/distributed_product.hpp"

namespace hmfnet {

DistributedProduct::DistributedProduct(const DistributedNetwork& network)
    : m_network(network),
      m_globals(network.column_globals()),
      m_degrees(network.gather(network.local_degrees())) {}

void DistributedProduct::apply(const std::vector<double>& x, std::vector<double>& y) const {
  const auto& a = m_network.local_adjacency();
  const auto rows = static_cast<NodeIndex>(a.row_ptr.size() - 1);
  // x in the column space first (one pass over the columns), so the row sums read it as a
  // Network's product reads x: one indirection per entry, not two.
  m_columns.resize(m_globals.size());
  for (std::size_t c = 0; c < m_globals.size(); ++c) {
    m_columns[c] = x[static_cast<std::size_t>(m_globals[c])];
  }
  m_local.resize(static_cast<std::size_t>(rows));
  const EdgeOffset* row_ptr = a.row_ptr.data();
  const NodeIndex* cols = a.cols.data();
  const double* weights = a.weights.data();
  const double* xs = m_columns.data();
  double* ys = m_local.data();
  const bool weighted = !a.weights.empty();
#pragma omp parallel for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    double sum = 0.0;
    const EdgeOffset end = row_ptr[r + 1];
    if (weighted) {
      for (EdgeOffset k = row_ptr[r]; k < end; ++k) sum += weights[k] * xs[cols[k]];
    } else {
      for (EdgeOffset k = row_ptr[r]; k < end; ++k) sum += xs[cols[k]];
    }
    ys[r] = sum;
  }
  y = m_network.gather(m_local);
}

}  // namespace hmfnet
