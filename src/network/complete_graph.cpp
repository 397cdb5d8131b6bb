#include "network/complete_graph.hpp"

#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace hmfnet {

namespace {
// materialise() is for cross-checks: 2^28 column indices are 1 GB.
constexpr EdgeOffset k_max_materialised_nnz = EdgeOffset{1} << 28;
}  // namespace

CompleteGraph CompleteGraph::make(std::int64_t n, bool self_loops) {
  if (n < 2 || n > std::numeric_limits<NodeIndex>::max()) {
    throw ParameterError("--n", "complete graph with " + std::to_string(n) + " nodes",
                         "2 <= N <= " + std::to_string(std::numeric_limits<NodeIndex>::max()));
  }
  return {static_cast<NodeIndex>(n), self_loops};
}

EdgeOffset CompleteGraph::nnz() const {
  const auto nodes = static_cast<EdgeOffset>(n);
  return nodes * (nodes - 1) + (self_loops ? nodes : 0);
}

EdgeOffset CompleteGraph::edges() const {
  const auto nodes = static_cast<EdgeOffset>(n);
  return nodes * (nodes - 1) / 2 + (self_loops ? nodes : 0);
}

double CompleteGraph::degree() const { return static_cast<double>(n) - (self_loops ? 0.0 : 1.0); }

Network CompleteGraph::materialise() const {
  if (nnz() > k_max_materialised_nnz) {
    throw ParameterError("complete graph", std::to_string(n) + " nodes to store",
                         "at most 2^28 stored entries (N <= 16384)");
  }
  const auto nodes = static_cast<std::size_t>(n);
  std::vector<EdgeOffset> row_ptr(nodes + 1, 0);
  std::vector<NodeIndex> cols;
  cols.reserve(static_cast<std::size_t>(nnz()));
  for (NodeIndex i = 0; i < n; ++i) {
    for (NodeIndex j = 0; j < n; ++j) {
      if (j != i || self_loops) cols.push_back(j);
    }
    row_ptr[static_cast<std::size_t>(i) + 1] = static_cast<EdgeOffset>(cols.size());
  }
  return Network::from_trusted_csr(n, std::move(row_ptr), std::move(cols));
}

Network CompleteGraph::quotient() const {
  return Network::from_csr(1, {0, 1}, {0}, {degree() / static_cast<double>(n)});
}

}  // namespace hmfnet
