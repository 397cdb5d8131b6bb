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

}  // namespace hmfnet::test
