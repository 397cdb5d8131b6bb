#pragma once
// Mean and sample standard deviation over seeds: verification drivers report the paper's numbers
// against "ours +- seed-to-seed sd" so the reader sees whether a difference is realisation noise.
#include <boost/math/distributions/students_t.hpp>
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

/// The two-sided 99% multiplier of a standard error estimated from `samples` independent values
/// (Student's t with samples - 1 degrees of freedom): 9.92 for 3, 3.50 for 8, 2.95 for 16; a
/// normal "3 SE" covers only ~90% with 3 samples.
inline double t_multiplier_99(int samples) {
  const boost::math::students_t t(static_cast<double>(samples - 1));
  return boost::math::quantile(t, 0.995);
}

}  // namespace hmfnet::verification
