#pragma once
// eq:BesselRatio: v(x) = I1(x) / I0(x), the Boltzmann average of cos(theta) of one rotor
// (eq:cosThetaBar) that closes the self-consistent system eq:rSigmaBesselMain and eq:KtoInfinity.
// v is odd and increasing with |v| < 1: v(x) = x/2 - x^3/16 + ... near 0 and
// v(x) = 1 - 1/(2x) - 1/(8x^2) - ... for large x. I0 and I1 overflow a double near x = 713 while
// their ratio does not, so large arguments use the asymptotic series of the ratio.

namespace hmfnet {

/// Where bessel_ratio switches from Boost's I1/I0 to the ratio of the Hankel asymptotic series.
/// At x = 50 the series' smallest term is ~1e-40 and Boost's ratio is still far from overflow,
/// so both sides are accurate to a few ulp there (tests/theory/test_bessel_ratio.cpp).
constexpr double k_bessel_ratio_switch = 50.0;

/// v(x) for every double x: v(+-inf) = +-1, v(NaN) = NaN. Relative error ~1e-15 (a few ulp).
double bessel_ratio(double x);

}  // namespace hmfnet
