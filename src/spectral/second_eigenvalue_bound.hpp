#pragma once
// Bounds on lambda_2, the second largest eigenvalue of a symmetric A, without converging its
// eigenpair: the network summary needs lambda_2 only to tell whether lambda / lambda_2 is below
// 1.1 (a second mode goes unstable near K_c), and converging lambda_2 at the edge of a dense ER
// bulk, where eigenvalues crowd (spacing ~ N^-2/3), cost 28 s of the 31 s of `spectrum` at
// N = 10^6, degree 100, even at a relative tolerance of 1e-3.
//
// Lanczos on B = P A P, P = I - u u^T (u the unit Perron vector), from a Gaussian start in the
// complement of u drawn from a seeded stream per global node (so the same at any rank count):
//   lower  the largest Ritz value theta_k <= lambda_2 (Rayleigh-Ritz on a subspace of u-perp,
//          where B's eigenvalues are lambda_2 >= ... >= lambda_N);
//   upper  lambda_2 <= (theta_k + c)/(1 - eps_k) - c, with c >= -lambda_min so that B + c I is
//          positive semidefinite on u-perp (A >= 0 entrywise, so |lambda_min| <= lambda: c =
//          lambda (1 + 1e-6), the slack covering lambda's own error), and
//          1.648 sqrt(n) exp(-sqrt(eps_k) (2k - 1)) = delta_k (Kuczynski & Wozniakowski, SIAM J.
//          Matrix Anal. Appl. 13 (1992) 1094, Thm 4.2): false at step k with probability <=
//          delta_k over the start. The bound is checked at every step and the run stops at the
//          first that settles the question, so delta_k = 6 delta / (pi^2 k^2), whose sum over all
//          k is delta: every reported upper bound holds with probability >= 1 - delta.
// With the computed u, not the exact one, B's top eigenvalue on u-perp exceeds lambda_2 by at
// most sin^2(u, u_exact) (lambda - lambda_2), ~ (residual lambda / gap)^2: 1e-20 relative at
// the 1e-10 residual the solver asks, far below what the bounds resolve.
// The bound is for exact arithmetic; without reorthogonalisation, finite-precision Lanczos keeps
// its Ritz values inside the spectrum up to round-off (Paige 1980) and its largest one converges
// no slower in practice. A breakdown (beta = 0) means the Krylov space is invariant: with a
// Gaussian start it holds every eigenvector (with probability 1), so theta_k is lambda_2 itself.
#include <functional>
#include <vector>

#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct SecondEigenvalueBound {
  double lower = 0.0;
  double upper = 0.0;
  int steps = 0;                     ///< Lanczos steps (one product with A each)
  bool exact = false;                ///< breakdown: lower = upper = lambda_2
  double failure_probability = 0.0;  ///< delta of the upper bound
};

/// Collective. `u` is the whole unit Perron vector (every rank), `lambda` its eigenvalue (of a
/// network with positive weights, as every Network is). Runs until decided(lower, upper) is
/// true, a breakdown, or max_steps.
SecondEigenvalueBound bound_second_eigenvalue(
    const DistributedNetwork& network, const std::vector<double>& u, double lambda,
    const std::function<bool(double lower, double upper)>& decided, int max_steps = 400,
    double failure_probability = 1e-6, std::uint64_t seed = 0x6c616e637a6f73ULL);

}  // namespace hmfnet
