#pragma once
// eq:gammaKKc: growth rate gamma of the fastest-growing perturbation of the incoherent state for
// Gaussian momenta of standard deviation sigma0 (the paper writes sigma where it means sigma0):
//   (gamma/sigma0) sqrt(pi/2) exp(gamma^2 / (2 sigma0^2)) erfc(gamma / (sqrt2 sigma0)) = 1 - K_c/K.
// With y = gamma / (sqrt2 sigma0) the left side is f(y) = sqrt(pi) y erfcx(y), erfcx(y) =
// exp(y^2) erfc(y), which rises from 0 to 1: one root for every K > K_c, gamma -> 0 as K -> K_c+,
// and gamma depends on the network only through K/K_c. exp(y^2) erfc(y) is never formed: it
// overflows (and loses accuracy) long before erfcx does.

namespace hmfnet {

/// erfcx(y) = exp(y^2) erfc(y) for y >= 0 (throws ParameterError for y < 0 or NaN); relative
/// error ~1e-15. y <= 2: Boost's erfc times exp(y^2) (error <= 4 y^2 eps); y > 2: Laplace's
/// continued fraction, which never forms either factor. erfcx(+inf) = 0.
double scaled_erfc(double y);

/// 1 - f(y) = 1 - sqrt(pi) y erfcx(y) for y >= 0, without cancellation for large y
/// (1 - f(y) ~ 1/(2 y^2)).
double growth_rate_deficit(double y);

/// gamma of eq:gammaKKc for K/K_c >= 1 (0 at K = K_c) and sigma0 > 0; throws ParameterError for
/// K/K_c < 1 (no growing mode: the equation has no root) or non-finite input. Solved for y by
/// TOMS 748 on 1 - f(y) = K_c/K to full double precision, stable up to K/K_c ~ 1e300.
double growth_rate(double K_over_Kc, double sigma0);

/// Large-K asymptote of eq:gammaKKc: 1 - f(y) = 1/(2y^2) - 3/(4y^4) + ... gives
/// gamma = sigma0 sqrt(K/K_c) (1 - 3 K_c/(2K) + O((K_c/K)^2)); `corrected` adds the second term.
double growth_rate_large_k(double K_over_Kc, double sigma0, bool corrected = false);

/// Near onset f(y) = sqrt(pi) y + O(y^2) gives gamma = sqrt(2/pi) sigma0 (1 - K_c/K) + O(...^2).
double growth_rate_near_onset(double K_over_Kc, double sigma0);

}  // namespace hmfnet
