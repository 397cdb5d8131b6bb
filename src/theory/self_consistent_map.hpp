#pragma once
// The map whose fixed points solve eq:rSigmaBesselMain and its K -> infinity limit eq:KtoInfinity,
// in the variables (r, eta) with eta = mu / K, mu = sigma^2, so that K r_m / mu = r_m / eta:
//   r_n  <- (1/N) sum_m A_nm v(r_m / eta)                    (first line of eq:rSigmaBesselMain)
//   eta  <- offset + (1/N) sum_n r_n v(r_n / eta)            (second line divided by K)
// with offset = (sigma0^2 + 2 U0/N) / K for finite K and offset = 0 for eq:KtoInfinity.
// ERRATUM applied: the paper's second line has v(K r_m / mu) inside a sum over n; the index is n
// (eq:sigmaSqEq: each rotor's own potential energy r_n <cos theta_n>).
// Both solvers (self_consistent.hpp, large_k_limit.hpp) iterate this map with
// anderson_acceleration.hpp; this file holds what they share.
#include <memory>
#include <string>
#include <vector>

#include "network/adjacency_product.hpp"
#include "network/network.hpp"

namespace hmfnet {

/// converged: residual <= tolerance at a nontrivial solution. incoherent: K is at or below the
/// threshold, r_n = 0 is the only non-negative solution and is returned exactly. failed: no
/// solution to tolerance (the iterate is kept for diagnosis only).
enum class SolveStatus { converged, incoherent, failed };
std::string solve_status_name(SolveStatus status);

struct SelfConsistentOptions {
  /// On the relative residual max(|r' - r|_inf / |r'|_inf, |eta' - eta| / eta') of one map
  /// application. Near onset the solution's relative error is about residual / (2 (K/K_c - 1)).
  double tolerance = 1e-10;
  int max_iterations = 1000;  ///< map evaluations (each one sparse product with A)
  int anderson_memory = 5;    ///< 0: damped fixed-point iteration (the paper's method)
  double damping = 0.5;       ///< beta of anderson_acceleration.hpp, in (0, 1]
};

class SelfConsistentMap {
 public:
  /// Keeps a reference to `product`, which must outlive the map. Not thread-safe (scratch space).
  SelfConsistentMap(const AdjacencyProduct& product, double offset);
  /// On a Network (which must outlive the map) through its own NetworkProduct.
  SelfConsistentMap(const Network& network, double offset);

  NodeIndex size() const { return m_product->size(); }
  double offset() const { return m_offset; }
  const AdjacencyProduct& product() const { return *m_product; }

  /// One application (eta > 0). Rows are threaded with a static schedule, the sum over n is
  /// serial: the result does not depend on the thread count.
  void apply(const std::vector<double>& r, double eta, std::vector<double>& r_out,
             double& eta_out) const;

 private:
  std::shared_ptr<const AdjacencyProduct> m_product;  // owned only when made from a Network
  double m_offset;
  mutable std::vector<double> m_v;
};

/// A point (r, eta) of the map, and how the iteration that produced it ended.
struct MapFixedPoint {
  std::vector<double> r;
  double eta = 0.0;
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;
  int restarts = 0;
};

/// Iterates the map from (r, eta) (r_n > 0 where node n has neighbours, eta > 0) with Anderson
/// acceleration in the variables log r_n, log eta (see the .cpp: this keeps the iteration away
/// from the incoherent root r = 0 and positive). Nodes without neighbours keep r_n = 0. The
/// residual is that of the last map application, from the returned point.
MapFixedPoint iterate_self_consistent_map(const SelfConsistentMap& map,
                                          const std::vector<double>& r, double eta,
                                          const SelfConsistentOptions& options);

/// eq:globalOrderParam: R = sum_n r_n / ||d||.
double global_order_parameter(const std::vector<double>& r, double mean_degree);

}  // namespace hmfnet
