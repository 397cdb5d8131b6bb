#include "network/degree_statistics.hpp"

#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "network/sparse_product.hpp"

namespace hmfnet {

double mean_degree(const Network& network) {
  if (network.size() == 0) throw ParameterError("mean degree: network", "0 nodes", "N >= 1");
  const auto d = network.degrees();
  return std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
}

double degree_correlation(const Network& network) {
  const auto d = network.degrees();
  double sum_d = 0.0, sum_d2 = 0.0, dad = 0.0;
  std::vector<double> ad;
  multiply(network, d, ad);
  for (std::size_t i = 0; i < d.size(); ++i) {
    sum_d += d[i];
    sum_d2 += d[i] * d[i];
    dad += d[i] * ad[i];
  }
  if (sum_d2 == 0.0) {
    throw ParameterError("degree correlation: network", "no edges", "a network with edges");
  }
  return dad * sum_d / (sum_d2 * sum_d2);
}

}  // namespace hmfnet
