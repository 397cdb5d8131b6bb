#pragma once
// How long a slow relaxation of R(t) takes, as the drivers beyond the paper measure it
// (qss_lifetime.cpp, near_onset_gap.cpp): the replica mean of R(t), smoothed by a running mean,
// first passes half way from its initial level to a target level. The error comes from
// bootstrap resamples of the replicas (the rule applied to each), and a power law in N from a
// weighted least-squares fit of the logarithms.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "support/sample_statistics.hpp"

namespace hmfnet::verification {

/// Records x replicas of one quantity (row-major, as TimeSeries::R), from `first` to `last`.
struct ReplicaSeries {
  const std::vector<double>* values = nullptr;
  std::size_t replicas = 0, first = 0, last = 0;
};

/// The mean over the chosen replicas, per record of the slice.
inline std::vector<double> replica_mean(const ReplicaSeries& s, const std::vector<int>& chosen) {
  std::vector<double> mean(s.last - s.first, 0.0);
  for (std::size_t i = s.first; i < s.last; ++i) {
    for (const int b : chosen) {
      mean[i - s.first] += (*s.values)[i * s.replicas + static_cast<std::size_t>(b)];
    }
    mean[i - s.first] /= static_cast<double>(chosen.size());
  }
  return mean;
}

/// The mean of records [begin, end) of a series.
inline double window_mean(const std::vector<double>& x, std::size_t begin, std::size_t end) {
  double sum = 0.0;
  for (std::size_t i = begin; i < end; ++i) sum += x[i];
  return sum / static_cast<double>(end - begin);
}

/// The first time the running mean of `x` over `width` records (record spacing dt, record i at
/// t0 + (i + 1) dt) reaches half way from its first window's mean to `target`; NaN if it never
/// does. The time is that of the window's last record less width dt / 2 (half a record before
/// the window's centre; the rule of qss_lifetime.cpp since it was written). A target below the
/// start is approached from above.
inline double half_way_passage(const std::vector<double>& x, double t0, double dt,
                               std::size_t width, double target) {
  if (x.size() <= width || width == 0) return NAN;
  const double start = window_mean(x, 0, width);
  const double half = 0.5 * (start + target);
  const double sign = target >= start ? 1.0 : -1.0;
  double window = start * static_cast<double>(width);
  for (std::size_t i = width; i < x.size(); ++i) {
    window += x[i] - x[i - width];
    if (sign * (window / static_cast<double>(width) - half) >= 0.0) {
      return t0 + dt * (static_cast<double>(i) + 1.0 - 0.5 * static_cast<double>(width));
    }
  }
  return NAN;
}

/// The rule applied to the mean over all replicas, and its spread over bootstrap resamples of
/// the replicas.
struct Passage {
  double time = NAN;  ///< of the mean over all replicas
  double se = NAN;    ///< sd of the resamples' times
  int passed = 0;     ///< resamples whose passage came within the series
};

/// `rule` maps a replica-mean series to its passage time (NaN: none). Resamples draw replicas
/// with replacement from a generator seeded with `seed`.
inline Passage bootstrap_passage(const ReplicaSeries& s,
                                 const std::function<double(const std::vector<double>&)>& rule,
                                 int resamples, std::uint64_t seed) {
  const int B = static_cast<int>(s.replicas);
  std::vector<int> all(s.replicas);
  for (int b = 0; b < B; ++b) all[static_cast<std::size_t>(b)] = b;
  Passage p;
  p.time = rule(replica_mean(s, all));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> pick(0, B - 1);
  std::vector<double> times;
  for (int k = 0; k < resamples; ++k) {
    std::vector<int> chosen(s.replicas);
    for (auto& c : chosen) c = pick(rng);
    const double x = rule(replica_mean(s, chosen));
    if (std::isfinite(x)) times.push_back(x);
  }
  p.passed = static_cast<int>(times.size());
  if (p.passed > 1) p.se = mean_sd(times).sd;
  return p;
}

/// y ~ x^slope: weighted least squares of ln y on ln x, sigma(ln y) = se / y; points without a
/// finite y or a positive se are left out. NaN slope with fewer than two points.
struct PowerLaw {
  double slope = NAN, slope_se = NAN;
  double log_prefactor = NAN;  ///< ln y = log_prefactor + slope ln x
  double at(double x) const { return std::exp(log_prefactor + slope * std::log(x)); }
};

inline PowerLaw power_law_fit(const std::vector<double>& x, const std::vector<double>& y,
                              const std::vector<double>& se) {
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(y[i]) || !(y[i] > 0.0) || !(se[i] > 0.0)) continue;
    const double w = std::pow(y[i] / se[i], 2), lx = std::log(x[i]), ly = std::log(y[i]);
    sw += w;
    sx += w * lx;
    sy += w * ly;
    sxx += w * lx * lx;
    sxy += w * lx * ly;
  }
  const double det = sw * sxx - sx * sx;
  if (!(det > 0.0)) return {};
  const double slope = (sw * sxy - sx * sy) / det;
  return {slope, std::sqrt(sw / det), (sy - slope * sx) / sw};
}

}  // namespace hmfnet::verification
