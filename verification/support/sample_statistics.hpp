#pragma once
// Mean and sample standard deviation over seeds: verification drivers report the paper's numbers
// against "ours +- seed-to-seed sd" so the reader sees whether a difference is realisation noise.
#include <cmath>
#include <vector>

namespace hmfnet::verification {

struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;  ///< sample sd (n - 1); 0 for one value
};

inline MeanSd mean_sd(const std::vector<double>& x) {
  double m = 0.0, v = 0.0;
  for (const double a : x) m += a;
  m /= static_cast<double>(x.size());
  for (const double a : x) v += (a - m) * (a - m);
  return {m, x.size() > 1 ? std::sqrt(v / static_cast<double>(x.size() - 1)) : 0.0};
}

}  // namespace hmfnet::verification
