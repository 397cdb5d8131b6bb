#pragma once
// eq:criticalKFirstOrder: the incoherent state with Gaussian momenta of standard deviation sigma0
// loses stability at K_c = 2 sigma0^2 N / lambda, lambda the largest eigenvalue of A.

//
// For any even g the threshold is where the growth rate gamma of eq:gDashPSGammaPlusOmega reaches
// 0: 2N / (K lambda) = integral of -g'(p) / (p - Omega) dp. Gaussian: that integral is
// 1 / sigma0^2. Water-bag (g = 1 / 2D on [Omega - D, Omega + D], so -g' is two delta functions of
// weight 1 / 2D at Omega +- D): it is 1 / D^2, hence K_c = 2 D^2 N / lambda = 6 sigma0^2 N /
// lambda, three times the Gaussian's at the same sigma0.
#include "theory/momentum_distribution.hpp"

namespace hmfnet {

/// K_c for sigma0 > 0, n >= 1, lambda > 0 (throws ParameterError otherwise).
double critical_coupling(double sigma0, double n, double lambda);

/// The linear threshold for momenta drawn from g (same ranges).
double critical_coupling(MomentumDistribution g, double sigma0, double n, double lambda);

}  // namespace hmfnet
