#include "network/degree_statistics.hpp"

#include <numeric>
#include <stdexcept>

namespace hmfnet {

double mean_degree(const Network& network) {
  if (network.size() == 0) throw std::invalid_argument("mean degree of an empty network");
  const auto d = network.degrees();
  return std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
}

double degree_correlation(const Network& network) {
  const auto d = network.degrees();
  double sum_d = 0.0, sum_d2 = 0.0, dad = 0.0;
  for (NodeIndex i = 0; i < network.size(); ++i) {
    const double di = d[static_cast<std::size_t>(i)];
    sum_d += di;
    sum_d2 += di * di;
    double row = 0.0;
    for (EdgeOffset k = network.row_begin(i); k < network.row_end(i); ++k) {
      row += network.weight(k) * d[static_cast<std::size_t>(network.col(k))];
    }
    dad += di * row;
  }
  if (sum_d2 == 0.0) throw std::invalid_argument("degree correlation of a network with no edges");
  return dad * sum_d / (sum_d2 * sum_d2);
}

}  // namespace hmfnet
