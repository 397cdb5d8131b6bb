#pragma once
// The ER network a benchmark runs on, generated once per (N, degree) and kept between
// benchmark repetitions (generation is not what these benchmarks measure). Fixed seed 7.
#include "network/erdos_renyi.hpp"

namespace hmfnet::bench {

inline const Network& cached_erdos_renyi(NodeIndex n, double degree) {
  static Network net;
  static NodeIndex cached_n = 0;
  static double cached_degree = 0.0;
  if (cached_n != n || cached_degree != degree) {
    net = erdos_renyi({n, erdos_renyi_probability(n, degree), 7});
    cached_n = n;
    cached_degree = degree;
  }
  return net;
}

}  // namespace hmfnet::bench
