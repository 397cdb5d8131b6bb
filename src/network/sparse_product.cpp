#include "network/sparse_product.hpp"

#include <cstddef>

namespace hmfnet {

void multiply(const Network& network, const std::vector<double>& x, std::vector<double>& y) {
  const NodeIndex n = network.size();
  y.resize(static_cast<std::size_t>(n));
  // Raw arrays and the weighted test hoisted out of the loop: this product is the cost of each
  // self-consistent map evaluation (docs/theory.md), and RowView's per-entry weight test is not.
  const EdgeOffset* row_ptr = network.row_ptr().data();
  const NodeIndex* cols = network.cols().data();
  const double* weights = network.weights().data();
  const double* xs = x.data();
  double* ys = y.data();
  const bool weighted = network.weighted();
#pragma omp parallel for schedule(static)
  for (NodeIndex i = 0; i < n; ++i) {
    double sum = 0.0;
    const EdgeOffset end = row_ptr[i + 1];
    if (weighted) {
      for (EdgeOffset k = row_ptr[i]; k < end; ++k) sum += weights[k] * xs[cols[k]];
    } else {
      for (EdgeOffset k = row_ptr[i]; k < end; ++k) sum += xs[cols[k]];
    }
    ys[i] = sum;
  }
}

}  // namespace hmfnet
