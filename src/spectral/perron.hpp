#pragma once
// The largest eigenvalue lambda of A and its Perron vector u (eq:criticalKFirstOrder needs
// lambda; eq:globalOrderRInDeltaK needs u). Solved by Anasazi's block Krylov-Schur on the
// distributed Tpetra matrix, asking for the largest *real* eigenvalue ("LR"): on a bipartite
// network -lambda has the same magnitude, so "largest magnitude" could return it.
#include <cstdint>
#include <limits>
#include <vector>

#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// Networks of at most this many nodes are solved densely (Eigen's symmetric eigensolver on the
/// whole matrix, every pair to machine precision, lambda_2 exact): Krylov-Schur cannot run on a
/// network with fewer nodes than its basis needs (3 and fewer), and below ~100 nodes the dense
/// solve costs less than setting up Anasazi.
inline constexpr NodeIndex k_dense_perron_nodes = 64;

struct PerronOptions {
  double tolerance = 1e-10;  ///< Anasazi's relative residual tolerance ||Au - lambda u|| / |lambda|
  int max_restarts = 1000;
  int num_blocks = 24;  ///< Krylov basis size, >= 3
  /// Also the second largest real eigenvalue lambda_2 (Krylov-Schur asked for two pairs): the
  /// gap lambda - lambda_2 bounds the eigenvector's error (~ residual lambda / gap) and sets
  /// where the second mode of A goes unstable (K = (lambda / lambda_2) K_c, eq:bkApprox).
  bool second_eigenvalue = false;
  /// With second_eigenvalue: bound lambda_2 first (spectral/second_eigenvalue_bound.hpp, a few
  /// dozen products) and converge it only when the bounds do not show lambda / lambda_2 >
  /// gap_ratio. Off: always converge it (the top pair of A with u deflated, Krylov-Schur).
  bool bound_lambda2_first = false;
  double gap_ratio = 1.1;  ///< the ratio the bounds must settle (network_summary's warning)
};

struct PerronResult {
  double lambda = 0.0;
  /// The whole vector on every rank, ||u||_2 = 1, sign chosen so that sum u > 0. Entries that are
  /// negative only by round-off (>= -1e3 eps max|u|) are set to 0.
  std::vector<double> u;
  double residual = 0.0;    ///< ||A u - lambda u||_2 / |lambda|, recomputed here, not Anasazi's
  bool nonnegative = true;  ///< false: u has entries of both signs (A reducible, lambda degenerate)
  int iterations = 0;
  double seconds = 0.0;
  double lambda2 = std::numeric_limits<double>::quiet_NaN();  ///< NaN unless asked and found
  double lambda2_residual = 0.0;
  /// With bound_lambda2_first: lambda2_lower <= lambda_2 <= lambda2_upper, the upper bound with
  /// probability >= 1 - lambda2_bound_failure over the seeded start; NaN when not bounded.
  double lambda2_lower = std::numeric_limits<double>::quiet_NaN();
  double lambda2_upper = std::numeric_limits<double>::quiet_NaN();
  double lambda2_bound_failure = 0.0;
  int lambda2_bound_steps = 0;
};

/// Collective. Throws ConvergenceError if Anasazi does not converge (never returns an
/// unconverged pair), ParameterError for a network without edges.
PerronResult perron_eigenpair(const DistributedNetwork& network, const PerronOptions& options = {});

}  // namespace hmfnet
