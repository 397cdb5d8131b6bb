#include "theory/linear_stability.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "theory/growth_rate.hpp"

namespace hmfnet {

namespace {

void require_sigma0(double sigma0) {
  if (!(sigma0 > 0.0) || !std::isfinite(sigma0))
    throw ParameterError("sigma0", std::to_string(sigma0), "sigma0 > 0");
}

void require_supercritical(double K_over_Kc) {
  if (!(K_over_Kc >= 1.0) || !std::isfinite(K_over_Kc)) {
    throw ParameterError("K/K_c", std::to_string(K_over_Kc),
                         ">= 1 (below the threshold no mode grows)");
  }
}

}  // namespace

EvenDensity even_density(MomentumDistribution g, double sigma0) {
  require_sigma0(sigma0);
  EvenDensity d;
  if (g == MomentumDistribution::gaussian) {
    // g = exp(-x^2 / 2 sigma0^2) / (sqrt(2 pi) sigma0): -g'(x) / x = g(x) / sigma0^2.
    const double s2 = sigma0 * sigma0,
                 norm = 1.0 / (std::sqrt(boost::math::constants::two_pi<double>()) * sigma0);
    d.minus_slope_over_x = [s2, norm](double x) { return norm * std::exp(-0.5 * x * x / s2) / s2; };
  } else {
    const double D = waterbag_half_width(sigma0);
    d.minus_slope_over_x = [](double) { return 0.0; };
    d.support = D;
    d.jumps = {{D, -1.0 / (2.0 * D)}};
  }
  return d;
}

namespace {

// Integral of f over [0, b], b finite or infinite.
template <typename F>
double half_line(F f, double b) {
  double error = 0.0;
  const double value =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, 0.0, b, 15, 1e-14, &error);
  if (!(error <= 1e-11 * std::max(1.0, std::abs(value)))) {
    throw ConvergenceError("eq:gDashPSGammaPlusOmega quadrature: error estimate " +
                           std::to_string(error) + " for the value " + std::to_string(value));
  }
  return value;
}

// 2 * integral over x > 0 of m(x) x^2 / (gamma^2 + x^2), m = -g'/x on the smooth part. For gamma
// below the density's own scale the integrand turns over at x ~ gamma, which adaptive quadrature
// resolves only slowly; there it is written J0 - 2 gamma integral m(gamma t) / (1 + t^2) dt
// (x = gamma t), smooth in t. Above that scale the direct form has no such feature and no
// cancellation.
double smooth_part(const EvenDensity& g, double gamma, double J0) {
  const auto& m = g.minus_slope_over_x;
  if (gamma == 0.0) return J0;
  const double g2 = gamma * gamma;
  if (gamma * gamma * J0 >= 1.0)
    return 2.0 * half_line([&](double x) { return m(x) * x * x / (g2 + x * x); }, g.support);
  return J0 -
         2.0 * gamma *
             half_line([&](double t) { return m(gamma * t) / (1.0 + t * t); }, g.support / gamma);
}

}  // namespace

double dispersion_integral(const EvenDensity& g, double gamma) {
  if (!(gamma >= 0.0) || !std::isfinite(gamma))
    throw ParameterError("gamma", std::to_string(gamma), ">= 0");
  // Even integrand: twice the half line. -x g'(x) / (gamma^2 + x^2) = m(x) x^2 / (gamma^2 + x^2).
  const double J0 = 2.0 * half_line(g.minus_slope_over_x, g.support);
  double J = smooth_part(g, gamma, J0);
  // A jump delta at x_j and its mirror -delta at -x_j put delta (delta(x - x_j) - delta(x + x_j))
  // into g', contributing -2 x_j delta / (gamma^2 + x_j^2).
  for (const auto& [x, delta] : g.jumps) J += -2.0 * x * delta / (gamma * gamma + x * x);
  return J;
}

// J(0) > 0 for a density peaked at its centre (-x g'(x) >= 0), the case the header's
// monotonicity and the root bracket rely on; anything else is refused, not answered.
double positive_J0(const EvenDensity& g) {
  const double J0 = dispersion_integral(g, 0.0);
  if (!(J0 > 0.0) || !std::isfinite(J0)) {
    throw ParameterError("momentum density", "J(0) = " + std::to_string(J0),
                         "J(0) = int -g'(x)/x dx > 0 (a density peaked at its centre)");
  }
  return J0;
}

double linear_threshold(const EvenDensity& g, double n, double lambda) {
  if (!(n >= 1.0)) throw ParameterError("N", std::to_string(n), "N >= 1");
  if (!(lambda > 0.0) || !std::isfinite(lambda))
    throw ParameterError("lambda", std::to_string(lambda), "lambda > 0 (a network with edges)");
  return 2.0 * n / (lambda * positive_J0(g));
}

double linear_growth_rate(const EvenDensity& g, double K_over_Kc) {
  require_supercritical(K_over_Kc);
  if (K_over_Kc == 1.0) return 0.0;
  const double target = positive_J0(g) / K_over_Kc;
  const auto f = [&](double gamma) { return dispersion_integral(g, gamma) - target; };
  // J(gamma) < 1 / gamma^2 bounds the root by sqrt(1 / target); widen until the sign changes.
  double hi = std::sqrt(1.0 / target);
  while (f(hi) > 0.0) hi *= 2.0;
  std::uintmax_t max_iter = 200;
  const auto root = boost::math::tools::toms748_solve(
      f, 0.0, hi, f(0.0), f(hi), boost::math::tools::eps_tolerance<double>(50), max_iter);
  return 0.5 * (root.first + root.second);
}

double growth_rate(MomentumDistribution g, double K_over_Kc, double sigma0) {
  require_sigma0(sigma0);
  if (g == MomentumDistribution::gaussian) return growth_rate(K_over_Kc, sigma0);
  require_supercritical(K_over_Kc);
  return waterbag_half_width(sigma0) * std::sqrt(K_over_Kc - 1.0);
}

}  // namespace hmfnet
