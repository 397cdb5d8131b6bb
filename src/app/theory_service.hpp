#pragma once
// `theory`'s work on a network already read: the paper's predictions for one momentum spread
// sigma0. K_c (eq:criticalKFirstOrder), G (eq:globalOrderRInDeltaK), the growth rate gamma
// (eq:gammaKKc) and the synchronized state R(K) (eq:rSigmaBesselMain) at each K, and the
// K -> infinity limit R_hat (eq:KtoInfinity and its degree approximation eq:rd).
//
// Two thresholds: K_c, the linear (Vlasov) threshold of the incoherent start for the chosen
// momentum distribution (theory/linear_stability.hpp), which K_over_Kc multiplies and gamma
// follows; and Kc_equilibrium = 2 sigma0^2 N / lambda, where eq:rSigmaBesselMain leaves R = 0 at
// the incoherent start's energy (the equilibrium depends on g only through sigma0^2 and U0 = 0).
// They coincide for Gaussian momenta; the water-bag's K_c is 3 Kc_equilibrium, and between the two
// the incoherent start is linearly stable although the equilibrium is synchronised.
//
// The CLI prints the outcome and Python converts it; both walk the field lists below.
#include <string>
#include <vector>

#include "app/theory_request.hpp"
#include "network/network.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::app {

/// The synchronized state at one K (eq:rSigmaBesselMain, warm-started along the K asked).
struct TheoryPoint {
  double K = 0.0;
  double K_over_Kc = 0.0;        ///< K over the linear threshold K_c
  bool linearly_stable = false;  ///< K < K_c: the incoherent start does not grow
  double R = 0.0;
  double R_onset = 0.0;  ///< G sqrt(K / Kc_equilibrium - 1) (eq:globalOrderRInDeltaK)
  double sigma2 = 0.0;
  std::string status;  ///< converged, incoherent or failed
  int iterations = 0;
  double residual = 0.0;
  double gamma = 0.0;  ///< growth rate (eq:gammaKKc) above K_c; 0 below
};

struct TheoryOutcome {
  NodeIndex n = 0;
  EdgeOffset nnz = 0;
  double mean_degree = 0.0;
  double sigma0 = 0.0;
  double lambda = 0.0;
  std::string momenta;
  double Kc = 0.0;              ///< linear threshold of `momenta`
  double Kc_equilibrium = 0.0;  ///< where eq:rSigmaBesselMain leaves R = 0
  double G = 0.0;
  double R_hat_iteration = 0.0;  ///< eq:KtoInfinity
  int R_hat_iterations = 0;
  double R_hat_residual = 0.0;
  double R_hat_degree_approx = 0.0;  ///< eq:rd
  std::vector<TheoryPoint> points;
  int ranks = 1;
  std::vector<double> peak_rss_mb_per_rank;
  /// One line naming every K whose solve failed ("" when all converged): the CLI prints the
  /// outcome, then exits 3 with it; Python raises ConvergenceError.
  std::string not_converged;
  /// Why the theory's assumptions may fail here (a Perron vector that changes sign), one line
  /// each: the CLI's stderr, Python's warnings.
  std::vector<std::string> warnings;
};

/// Validates the request first. Collective over the MPI ranks; every rank gets the outcome.
TheoryOutcome theory(const TheoryRequest& request, const DistributedInput& input);

/// The outcome's numbers as `theory --json` prints them (the lists `points` and `gamma` are
/// walked by visit_theory_point_fields and visit_growth_fields).
template <class Visitor>
void visit_theory_fields(Visitor& v, const TheoryOutcome& o) {
  v.field("n", o.n);
  v.field("nnz", o.nnz);
  v.field("mean_degree", o.mean_degree);
  v.field("sigma0", o.sigma0);
  v.field("lambda", o.lambda);
  v.field("momenta", o.momenta);
  v.field("Kc", o.Kc);
  v.field("Kc_equilibrium", o.Kc_equilibrium);
  v.field("G", o.G);
  v.field("R_hat_iteration", o.R_hat_iteration);
  v.field("R_hat_iterations", o.R_hat_iterations);
  v.field("R_hat_residual", o.R_hat_residual);
  v.field("R_hat_degree_approx", o.R_hat_degree_approx);
  v.field("ranks", o.ranks);
  v.field("peak_rss_mb_per_rank", o.peak_rss_mb_per_rank);
}

/// One entry of `points`.
template <class Visitor>
void visit_theory_point_fields(Visitor& v, const TheoryPoint& p) {
  v.field("K", p.K);
  v.field("K_over_Kc", p.K_over_Kc);
  v.field("linearly_stable", p.linearly_stable);
  v.field("R", p.R);
  v.field("R_onset", p.R_onset);
  v.field("sigma2", p.sigma2);
  v.field("status", p.status);
  v.field("iterations", p.iterations);
  v.field("residual", p.residual);
}

/// Above the linear threshold: the points that `gamma` lists.
inline bool above_threshold(const TheoryPoint& p) { return p.K_over_Kc > 1.0; }

/// One entry of `gamma` (the points above_threshold).
template <class Visitor>
void visit_growth_fields(Visitor& v, const TheoryPoint& p) {
  v.field("K_over_Kc", p.K_over_Kc);
  v.field("gamma", p.gamma);
}

}  // namespace hmfnet::app
