#include "theory/large_k_limit.hpp"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "network/degree_statistics.hpp"
#include "theory/bessel_ratio.hpp"

namespace hmfnet {

namespace {

// Root in (0, 1] of h(R) = mean_k[k v(k / (R D))] / D - R, where mean_k is the degree average
// supplied by `average` and D = ||d||. h -> 1 - R > 0 as R -> 0 (v -> 1) and h(1) < 0 (v < 1).
template <class Average>
double solve_degree_equation(Average average, double mean) {
  auto h = [&](double R) {
    const double scale = 1.0 / (R * mean);
    return average([scale](double k) { return k * bessel_ratio(k * scale); }) / mean - R;
  };
  double lo = 1e-3;
  for (int k = 0; k < 60 && !(h(lo) > 0.0); ++k) lo *= 0.5;
  std::uintmax_t max_iter = 200;
  const auto root = boost::math::tools::toms748_solve(
      h, lo, 1.0, boost::math::tools::eps_tolerance<double>(50), max_iter);
  return 0.5 * (root.first + root.second);
}

}  // namespace

double degree_approximation_R_hat(const std::vector<double>& degrees) {
  if (degrees.empty()) throw ParameterError("degrees", "empty", "at least one node");
  double sum = 0.0;
  for (const double d : degrees) {
    if (!(d >= 0.0) || !std::isfinite(d)) {
      throw ParameterError("degree", std::to_string(d), "finite and >= 0");
    }
    sum += d;
  }
  const double n = static_cast<double>(degrees.size());
  if (!(sum > 0.0)) throw ParameterError("degrees", "all zero", "a network with edges");
  auto average = [&](auto f) {
    double s = 0.0;
    for (const double d : degrees) s += f(d);
    return s / n;
  };
  return solve_degree_equation(average, sum / n);
}

double degree_approximation_R_hat(const PowerLaw& law) {
  if (!(law.alpha > 2.0) || !(law.d_min > 0.0) || !(law.cutoff > law.d_min)) {
    throw ParameterError(
        "power law", "alpha " + std::to_string(law.alpha) + ", d_min " + std::to_string(law.d_min),
        "alpha > 2, d_min > 0, cutoff > d_min");
  }
  // Survival function of the truncated Pareto law: u(k) = ((k/d_min)^(1-a) - c) / (1 - c),
  // c = (cutoff/d_min)^(1-a); inverted: k(u) = d_min (c + u (1 - c))^(-1/(a-1)), u in (0, 1].
  const double a = law.alpha;
  const double c = std::isinf(law.cutoff) ? 0.0 : std::pow(law.cutoff / law.d_min, 1.0 - a);
  auto k_of_u = [&](double u) { return law.d_min * std::pow(c + u * (1.0 - c), -1.0 / (a - 1.0)); };
  // Not const: Boost 1.74 declares integrate() const but defines the 1-argument form without it.
  boost::math::quadrature::tanh_sinh<double> integrator;
  auto average = [&](auto f) {
    // Tolerance on the change between tanh-sinh levels; the error itself is about its square.
    return integrator.integrate([&](double u) -> double { return f(k_of_u(u)); }, 0.0, 1.0, 1e-10);
  };
  const double mean = average([](double k) { return k; });
  return solve_degree_equation(average, mean);
}

LargeKLimit solve_large_k_limit(const Network& network, const SelfConsistentOptions& options) {
  return solve_large_k_limit(NetworkProduct(network), options);
}

LargeKLimit solve_large_k_limit(const AdjacencyProduct& product,
                                const SelfConsistentOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double>& d = product.degrees();
  const double mean = mean_degree(product);
  if (!(mean > 0.0)) throw ParameterError("network", "no edges", "a network with edges");
  // First guess from eq:rd: r_n = B d_n, B = R_hat / N, eta = B^2 N ||d||.
  const double R = degree_approximation_R_hat(d);
  const double n = static_cast<double>(product.size());
  const double B = R / n;
  std::vector<double> r(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) r[i] = B * d[i];
  const SelfConsistentMap map(product, 0.0);
  const MapFixedPoint fp = iterate_self_consistent_map(map, r, B * B * n * mean, options);
  LargeKLimit out;
  out.r_hat = fp.r;
  out.eta_hat = fp.eta;
  out.R_hat = global_order_parameter(fp.r, mean);
  out.iterations = fp.iterations;
  out.residual = fp.residual;
  out.restarts = fp.restarts;
  if (fp.converged) {
    out.status = SolveStatus::converged;
  } else {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "residual %.3g after %d iterations (tolerance %.3g)",
                  fp.residual, fp.iterations, options.tolerance);
    out.message = buffer;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace hmfnet
