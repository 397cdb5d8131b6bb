#pragma once
// Test tolerances, each with its reason (MFEM's MFEM_Approx idea): one place to read why a
// comparison is as loose or tight as it is. Never change one to make a test pass.
#include <limits>

namespace hmfnet::test {

constexpr double k_eps = std::numeric_limits<double>::epsilon();

/// Eigenvalues from Anasazi (relative residual tolerance 1e-10) against closed forms or Eigen's
/// dense solver: for a symmetric matrix the eigenvalue error is bounded by the squared residual
/// over the gap, so 1e-9 relative holds with room; it fails if the solver returns a wrong pair.
constexpr double k_eigenvalue_rel = 1e-9;

/// Perron vectors (unit 2-norm) against the dense solver: error ~ residual / gap <= 1e-10 / gap;
/// our test networks have gaps >= 0.1 lambda, so 1e-7 absolute per entry.
constexpr double k_eigenvector_abs = 1e-7;

/// Sums of O(N) terms of size O(1) in double: N eps relative with N <= 1e6 (pairwise-free loops).
constexpr double k_sum_rel = 1e-9;

/// Statistical tests state their number of standard deviations; 4 sigma gives a false-alarm
/// rate of 6e-5 per check (normal approximation).
constexpr double k_sigmas = 4.0;

/// Special functions (v = I1/I0, erfcx) against independent evaluations in extended precision:
/// both sides round a handful of operations (Boost's I0, I1, erfc are accurate to a few ulp), so
/// 1e-14 = 45 eps holds with room, while a wrong branch or a truncated series misses by orders of
/// magnitude.
constexpr double k_special_function_rel = 1e-14;

/// Scalar roots found by TOMS 748 to full precision, against another solution of the same
/// equation: the double rounding of the function (~1e-16) over a slope of order 1, with room.
constexpr double k_root_rel = 1e-12;

/// Solutions of eq:rSigmaBesselMain / eq:KtoInfinity at solver tolerance 1e-12 against closed
/// forms: the error is the residual over the distance of the iteration's Jacobian from 1, about
/// 2 (K/K_c - 1) near onset; the tests keep K/K_c >= 1.01 (error <= 5e-11) unless they say so.
constexpr double k_self_consistent_rel = 1e-9;

/// Adaptive quadrature (Gauss-Kronrod, tanh-sinh) of smooth integrands at requested tolerance
/// <= 1e-10.
constexpr double k_quadrature_rel = 1e-9;

}  // namespace hmfnet::test
