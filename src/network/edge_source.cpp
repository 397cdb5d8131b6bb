#include "network/edge_source.hpp"

#include <algorithm>

namespace hmfnet {

Network network_from_source(const EdgeSource& source) {
  std::vector<Edge> edges;
  for (std::int64_t k = 0; k < source.units(); ++k) source.emit(k, edges);
  return Network::from_undirected_edges(source.nodes(), edges);
}

std::vector<std::int64_t> balanced_unit_starts(const EdgeSource& source, int parts) {
  const std::int64_t units = source.units();
  const double total = source.work_before(units);
  std::vector<std::int64_t> starts(static_cast<std::size_t>(parts) + 1, units);
  starts[0] = 0;
  for (int p = 1; p < parts; ++p) {
    // First unit k with work_before(k) >= p total / parts (bisection on the monotone work).
    const double goal = total * p / parts;
    std::int64_t low = starts[static_cast<std::size_t>(p) - 1];
    std::int64_t high = units;
    while (low < high) {
      const std::int64_t mid = low + (high - low) / 2;
      if (source.work_before(mid) >= goal) {
        high = mid;
      } else {
        low = mid + 1;
      }
    }
    starts[static_cast<std::size_t>(p)] = low;
  }
  return starts;
}

}  // namespace hmfnet
