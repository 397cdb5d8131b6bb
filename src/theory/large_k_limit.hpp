#pragma once
// The K -> infinity limit of the synchronized state (Sec. largeK).
//
// eq:KtoInfinity: with eta = sigma^2 / K finite as K -> infinity, eq:rSigmaBesselMain becomes
//   r_n = (1/N) sum_m A_nm v(r_m / eta),   eta = (1/N) sum_n r_n v(r_n / eta),
// and R_hat = sum_n r_n / ||d||. The initial energy drops out (it enters as sigma0^2 / K), so
// R_hat depends on the network only. The paper solves it by the relaxed iteration
// r <- (1 - beta) g(r) + beta r; here that is Anderson memory 0 with damping 1 - beta, and the
// default is the accelerated iteration of anderson_acceleration.hpp from the eq:rd solution
// (r_n = B d_n, which is exact for rank-one A).
//
// eq:rd (degree approximation, r_n = B d_n, Ichinomiya 2004): the scalar equation
//   R_hat ||d|| = (1/N) sum_m d_m v(d_m / (R_hat ||d||)),
// a root in (0, 1) found by TOMS 748 (the right side minus the left is positive as R -> 0 and
// negative at R = 1, and has one sign change). Its continuum form for a degree density P(k):
//   R_hat ||d|| = int k P(k) v(k / (R_hat ||d||)) dk.
#include <vector>

#include "network/chung_lu.hpp"
#include "network/network.hpp"
#include "theory/self_consistent_map.hpp"

namespace hmfnet {

struct LargeKLimit {
  SolveStatus status = SolveStatus::failed;  ///< converged or failed (never incoherent)
  std::vector<double> r_hat;
  double eta_hat = 0.0;
  double R_hat = 0.0;
  int iterations = 0;
  double residual = 0.0;
  int restarts = 0;
  double seconds = 0.0;
  std::string message;
};

/// eq:KtoInfinity on a network with edges (throws ParameterError otherwise).
LargeKLimit solve_large_k_limit(const Network& network, const SelfConsistentOptions& options = {});
/// The same on any AdjacencyProduct (collective for distributed rows).
LargeKLimit solve_large_k_limit(const AdjacencyProduct& product,
                                const SelfConsistentOptions& options = {});

/// eq:rd for a degree sequence (all d_m >= 0, mean > 0; throws ParameterError otherwise).
double degree_approximation_R_hat(const std::vector<double>& degrees);

/// The continuum form of eq:rd for the power law eq:powerlaw, P(k) ~ k^-alpha on
/// (d_min, cutoff), alpha > 2. The integrals run over the survival function u = P(K > k), in
/// which P(k) dk = -du and k(u) has an integrable u^(-1/(alpha-1)) singularity at u = 0
/// (tanh-sinh quadrature, relative error ~1e-12). Depends on alpha and cutoff/d_min only.
double degree_approximation_R_hat(const PowerLaw& law);

}  // namespace hmfnet
