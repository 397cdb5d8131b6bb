#pragma once
// The synchronized state of eq:rSigmaBesselMain (index corrected, see self_consistent_map.hpp):
// N + 1 unknowns, the local order parameters r_n and the variance mu = sigma^2,
//   r_n = (1/N) sum_m A_nm v(K r_m / mu),
//   mu  = sigma0^2 + (K/N) sum_n r_n v(K r_n / mu) + 2 U0 / N,
// and R = sum_n r_n / ||d|| (eq:globalOrderParam).
//
// Threshold. Let mu0 = sigma0^2 + 2 U0/N = sigma0^2 - K c0 (the incoherent solution's variance)
// and kappa = K lambda / (2 N mu0); with U0 = 0, kappa = K / K_c (eq:criticalKFirstOrder). For
// kappa <= 1 the incoherent solution r = 0 is the only non-negative one: multiplying the first
// line by the Perron vector u > 0 and using v(x) < x/2 for x > 0 and mu >= mu0 gives
// u.r < (K lambda / (2 N mu0)) u.r <= u.r unless r = 0. It is returned exactly, with status
// incoherent. kappa = 1 at K = threshold() = 2 N sigma0^2 / (lambda + 2 N c0); above it the
// solver looks for the nontrivial solution.
//
// Method: Anderson acceleration (anderson_acceleration.hpp) of the damped fixed-point iteration
// of self_consistent_map.hpp, in the variables log r_n, log mu with a trust region (see
// self_consistent_map.cpp for why); the paper's plain iteration is memory 0, damping 1. First
// guess: r proportional to the Perron vector (the onset solution r ~ C u of the paper's Sec.
// approxOnsetSynchrony; degrees when u is not given) scaled to R = min(G sqrt(kappa - 1),
// all-to-all R(kappa)), or in a sweep the previous solution moved along that curve (warm start
// along K). A converged point whose R is below 1e-3 of the guess would be the incoherent root
// and is reported as failed, never as a solution. Disconnected networks: only the components
// above their own threshold (K lambda_c / (2 N mu0) > 1, spectral/component_radii.hpp) start
// coherent (r = 0 on a component is a fixed point of the map); see docs/theory.md. Measured
// costs: docs/theory.md.
#include <memory>
#include <string>
#include <vector>

#include "network/adjacency_product.hpp"
#include "network/network.hpp"
#include "network/structure.hpp"
#include "theory/self_consistent_map.hpp"

namespace hmfnet {

/// The K-independent part of the initial potential energy (eq:Hsub0):
/// c0 = (1/N^2) sum_nm A_nm cos(theta_m - theta_n), so that 2 U0 / N = -K c0. For phases uniform
/// in [0, 2 pi), c0 = O(sqrt(||d|| N) / N^2) and the paper drops it. theta has N entries.
double initial_coherence(const Network& network, const std::vector<double>& theta);

struct SelfConsistentSolution {
  SolveStatus status = SolveStatus::failed;
  double K = 0.0;
  double K_over_Kc = 0.0;  ///< K / threshold(): K / K_c of eq:criticalKFirstOrder when U0 = 0
  std::vector<double> r;   ///< r_n (all 0 when incoherent; the last iterate when failed)
  double sigma2 = 0.0;     ///< mu = sigma^2
  double R = 0.0;          ///< eq:globalOrderParam
  int iterations = 0;      ///< map evaluations (0 when incoherent)
  double residual = 0.0;   ///< relative residual of self_consistent_map.hpp (0 when incoherent)
  int restarts = 0;        ///< Anderson safeguard restarts
  double seconds = 0.0;
  std::string message;  ///< why it failed, or empty
};

class SelfConsistentSystem {
 public:
  /// network: A (kept by reference, must outlive this object); lambda: its largest eigenvalue;
  /// sigma0 > 0: the initial momentum spread; coherence: c0 of initial_coherence (0 for an
  /// incoherent start); perron: optional Perron vector (any normalisation, N entries) used for
  /// the first guess. Throws ParameterError for sigma0 <= 0, lambda <= 0, a network without
  /// edges, or a Perron vector of the wrong size.
  SelfConsistentSystem(const Network& network, double lambda, double sigma0, double coherence = 0.0,
                       std::vector<double> perron = {});
  /// The same on any AdjacencyProduct (rows distributed over ranks: every rank runs the same
  /// steps), given its connected components; `product` must outlive the system.
  SelfConsistentSystem(const AdjacencyProduct& product, Components components, double lambda,
                       double sigma0, double coherence = 0.0, std::vector<double> perron = {});

  /// K at which kappa = 1: 2 N sigma0^2 / (lambda + 2 N c0) (infinite if lambda + 2 N c0 <= 0).
  double threshold() const;
  double mean_degree() const { return m_mean_degree; }

  /// The solution at coupling K > 0; warm_start: a converged solution at another K (or null).
  SelfConsistentSolution solve(double K, const SelfConsistentOptions& options = {},
                               const SelfConsistentSolution* warm_start = nullptr) const;

  /// Solutions for every K (in the order given), solved in increasing K with each converged
  /// solution the warm start of the next.
  std::vector<SelfConsistentSolution> sweep(const std::vector<double>& Ks,
                                            const SelfConsistentOptions& options = {}) const;

 private:
  SelfConsistentSystem(std::shared_ptr<const AdjacencyProduct> product, Components components,
                       double lambda, double sigma0, double coherence, std::vector<double> perron);
  /// r of the first guess at K/K_c = kappa; mu: in, the incoherent variance mu0; out, the guess.
  /// shape: the guess's shape (sum 1), m_shape when null.
  std::vector<double> first_guess(double kappa, double& mu,
                                  const std::vector<double>* shape = nullptr) const;
  /// One solve from the first guess (or the warm start) of `shape`; fills out's solution fields.
  void attempt(SelfConsistentSolution& out, const SelfConsistentOptions& options,
               const SelfConsistentSolution* warm_start, const std::vector<double>* shape) const;
  /// Disconnected networks: components with K lambda_c > 2 N mu0, and the largest one.
  std::vector<char> active_components(double K, double mu0) const;
  /// The first guess's shape with only the active components coherent, sum 1.
  std::vector<double> component_shape(const std::vector<char>& active) const;
  /// Whether s is coherent on every active component (a usable warm start).
  bool supports_match(const SelfConsistentSolution& s, const std::vector<char>& active) const;
  /// Deactivates the active component of smallest lambda_c; false if one or none is active.
  bool drop_weakest(std::vector<char>& active) const;
  /// After a failed attempt: deactivates the components below threshold at sigma2 (the last
  /// iterate's variance), or else the weakest; false if nothing could be dropped.
  bool drop_decayed(std::vector<char>& active, double K, double sigma2) const;

  std::shared_ptr<const AdjacencyProduct> m_product;  // owned only when made from a Network
  double m_lambda;
  double m_sigma0;
  double m_coherence;
  double m_mean_degree = 0.0;
  std::vector<double> m_shape;             ///< u (or d), scaled to sum 1
  Components m_components;                 ///< connected components of the network
  std::vector<double> m_component_lambda;  ///< their lambda_c (only when disconnected)
  double m_onset_G = 0.0;                  ///< G of eq:globalOrderRInDeltaK with u = m_shape
};

}  // namespace hmfnet
