#pragma once
// eq:criticalKFirstOrder: the incoherent state with Gaussian momenta of standard deviation sigma0
// loses stability at K_c = 2 sigma0^2 N / lambda, lambda the largest eigenvalue of A.

namespace hmfnet {

/// K_c for sigma0 > 0, n >= 1, lambda > 0 (throws ParameterError otherwise).
double critical_coupling(double sigma0, double n, double lambda);

}  // namespace hmfnet
