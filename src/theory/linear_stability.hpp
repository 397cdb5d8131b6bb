#pragma once
// Linear (Vlasov) stability of the incoherent state for any even momentum density g, from
// eq:gDashPSGammaPlusOmega at omega = Omega (the imaginary part then vanishes by symmetry):
//   2N / (K lambda) = J(gamma),  J(gamma) = integral of -x g'(x) / (gamma^2 + x^2) dx,
// x = p - Omega. J decreases from J(0) = integral of -g'(x) / x dx to 1 / gamma^2 (the density
// has unit mass), so the threshold is K_c = 2N / (lambda J(0)) and above it there is one growing
// rate, J(gamma) = J(0) K_c / K.
//
// Closed forms: Gaussian J(0) = 1 / sigma0^2 and eq:gammaKKc; water-bag (g = 1 / 2D on |x| < D,
// so g' is two delta functions) J(gamma) = 1 / (gamma^2 + D^2), gamma = D sqrt(K / K_c - 1). The
// numerical path below takes any even g as its smooth part plus its jumps and is tested against
// both (tests/theory/test_linear_stability.cpp).
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "theory/momentum_distribution.hpp"

namespace hmfnet {

/// An even density g(x), x = p - Omega, of unit mass, peaked at its centre (-x g'(x) >= 0:
/// the monotone J above; the threshold and growth rate refuse a density with J(0) <= 0).
struct EvenDensity {
  /// -g'(x) / x on the smooth part, x > 0 (finite as x -> 0+ for a density smooth at 0).
  std::function<double(double)> minus_slope_over_x;
  /// g = 0 for |x| > support.
  double support = std::numeric_limits<double>::infinity();
  /// Jumps of g at x_j > 0: (x_j, g(x_j+) - g(x_j-)); the mirror jump at -x_j is implied.
  std::vector<std::pair<double, double>> jumps;
};

/// The density of `g` with standard deviation sigma0 > 0 (ParameterError otherwise).
EvenDensity even_density(MomentumDistribution g, double sigma0);

/// J(gamma) for gamma >= 0 by adaptive Gauss-Kronrod quadrature of the smooth part (relative
/// error ~1e-13) plus the jumps in closed form.
double dispersion_integral(const EvenDensity& g, double gamma);

/// K_c = 2N / (lambda J(0)) (n >= 1, lambda > 0).
double linear_threshold(const EvenDensity& g, double n, double lambda);

/// The growing rate at K / K_c >= 1 (0 at K_c): the root of J(gamma) = J(0) K_c / K, by TOMS 748.
/// Throws ParameterError below the threshold (no growing mode).
double linear_growth_rate(const EvenDensity& g, double K_over_Kc);

/// Closed forms of the growth rate: eq:gammaKKc (Gaussian), D sqrt(K / K_c - 1) (water-bag).
double growth_rate(MomentumDistribution g, double K_over_Kc, double sigma0);

}  // namespace hmfnet
