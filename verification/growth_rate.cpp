// Verification: growth rate of the order parameter out of the incoherent state (Fig. growthRate,
// eq:gammaKKc).
//
// Claim: in the linear regime R(t) grows like e^{gamma t} with gamma of eq:gammaKKc, and
//   "theory and simulations agree well with increasing K/K_c values".
// Run:   verification_growth_rate [--scale ci|full]   (ctest -L verification)
//        ci: ER N = 2000, ||d|| = 500, K/K_c in {1.5, 2, 3, 4}, 3 replicas (seeds);
//        full: ER N = 10^4, ||d|| = 2000, 3 replicas. The paper's N = 25000, ||d|| = 5000
//        (1.25e8 nnz) does not fit the budget. sigma0 = 0.35, Omega = 6, h = 0.02 (the fastest
//        libration sqrt(K max R_n) < 1.5 here, h omega < 0.03); each run lasts 10/gamma + 10 time
//        units (the theory sets the time scale, never the data); R recorded every step.
// Fit quantity: R = sum_n |y_n| / sum_n d_n has a finite-size floor R_0 ~ 1/sqrt(||d||) from the
//   incoherent part of every local field, which adds to the growing mode in quadrature, so
//   log R grows slower than gamma until the mode dominates. The fit uses the excess
//   E(t) = sqrt(R(t)^2 - R_0^2), R_0 = R(0) (the initial state is incoherent).
// Fit window (a stated rule, the same for every run): R_sat = mean R over the last 30% of the
//   run; the window runs from the first time E >= R_0 (the mode above the floor) to the last
//   record before R first reaches R_sat / 2 (before the nonlinear saturation), and the slope is
//   the least-squares slope of log E over it. A K/K_c whose window spans less than one e-fold of
//   the theory's growth (gamma (t2 - t1) < 1 in any replica) is reported, not checked.
//   History, so the choice is visible: fitting log R itself (2 R_0 to R_sat/2) gave slopes
//   10-13% below gamma at 3-4 K_c (the floor); the steepest window of length 1/gamma of log E
//   gave 11-13% above (a maximum over noisy windows is biased up); this rule gives 1-8%.
// Reference: gamma of eq:lambdaHat (dispersion_relation.hpp) for each replica's own sample of
//   momenta on the network's lambda: the finite-N form of eq:gammaKKc, free of the sample error
//   of sigma0^2 (sqrt(2/N) = 3%, which moves K_c by as much). eq:gammaKKc itself is reported.
// Tolerance: 3 standard errors of the replica-mean slope (seed-to-seed spread) plus the bias of
//   the independence approximation eq:bkApprox, measured elsewhere as 31% at ||d|| = 20 and 5% at
//   160: a power law through those, 5% (160/||d||)^0.88, gives 1.8% at 500 and 0.5% at 2000.
//   The qualitative claim is checked as: the relative error at the largest K/K_c is smaller than
//   at the smallest.
#include "theory/growth_rate.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/rotor_state.hpp"
#include "dynamics/simulation.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/growth_fit.hpp"
#include "support/sample_statistics.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/dispersion_relation.hpp"

using namespace hmfnet;
using verification::ClaimCheck;
using verification::Fit;
using verification::fit_growth;
using verification::sample_growth_rate;

namespace {

constexpr double k_sigma0 = 0.35;
constexpr double k_omega = 6.0;

struct KResult {
  double gamma = 0.0, gamma_sample = 0.0, slope = 0.0, slope_sem = 0.0, rel_error = 0.0;
};

// Step 2 for one K: B replicas from the incoherent state, one fit each.
KResult run_one_k(ClaimCheck& check, const Network& net, const DistributedNetwork& d, double lambda,
                  double x, int replicas, double bias) {
  const double Kc = critical_coupling(k_sigma0, net.size(), lambda);
  KResult k;
  k.gamma = growth_rate(x, k_sigma0);
  SimulationParameters p;
  p.h = 0.02;
  p.duration = 10.0 / k.gamma + 10.0;
  p.transient = 0.0;
  p.K = {x * Kc};
  p.replicas.clear();
  for (int b = 0; b < replicas; ++b) {
    p.replicas.push_back({k_omega, k_sigma0, static_cast<std::uint64_t>(11 + b)});
  }
  p.record_stride = 1;
  const auto force = app::choose_force("auto", "float64", d);
  const SimulationResult sim = simulate(d, net.degrees(), *force, p);
  verification::account(check, p, sim);
  const auto B = static_cast<std::size_t>(replicas);
  const std::size_t records = sim.series.t.size();
  std::vector<double> slopes, table(records * (B + 1));
  bool usable = true;
  double efolds = INFINITY;
  for (std::size_t b = 0; b < B; ++b) {
    std::vector<double> R(records);
    for (std::size_t i = 0; i < records; ++i) {
      R[i] = sim.series.R[i * B + b];
      table[i * (B + 1)] = sim.series.t[i];
      table[i * (B + 1) + b + 1] = R[i];
    }
    const Fit f = fit_growth(sim.series.t, R, k.gamma);
    slopes.push_back(f.slope);
    k.gamma_sample += sample_growth_rate(net.size(), p.K[0], lambda, p.replicas[b], k.gamma) /
                      static_cast<double>(B);
    std::printf("  INFO  K/K_c %g replica %zu: window [%.2f, %.2f], slope %.4f\n", x, b, f.t1, f.t2,
                f.slope);
    usable = usable && f.usable;
    efolds = std::min(efolds, f.efolds);
    check.data("fit_K" + ClaimCheck::format(x) + "_r" + std::to_string(b),
               {{"t1", f.t1}, {"t2", f.t2}, {"slope", f.slope}, {"intercept", f.intercept}});
  }
  std::vector<std::string> columns{"t"};
  for (std::size_t b = 0; b < B; ++b) columns.push_back("R replica " + std::to_string(b));
  check.data("R_K" + ClaimCheck::format(x), table, records, std::move(columns));
  const verification::MeanSd ms = verification::mean_sd(slopes);
  k.slope = ms.mean;
  k.slope_sem = ms.sd / std::sqrt(static_cast<double>(B));
  k.rel_error = std::abs(k.slope - k.gamma_sample) / k.gamma_sample;
  const std::string tag = "K/K_c = " + ClaimCheck::format(x);
  check.holds(tag + ": fit window found in every replica", usable,
              "a window of 1/gamma = " + ClaimCheck::format(1.0 / k.gamma) +
                  " before R first reaches R_sat");
  const double tol = 3.0 * k.slope_sem / k.gamma_sample + bias;
  if (efolds >= 1.0) {
    check.within_rel(tag + ": fitted slope vs gamma of eq:lambdaHat (sample)", k.slope,
                     k.gamma_sample, tol,
                     "3 SEM over seeds (" + ClaimCheck::format(k.slope_sem) +
                         ") + eq:bkApprox bias " + ClaimCheck::format(100 * bias) + "%");
  } else {
    check.report(tag + ": fitted slope vs gamma of eq:lambdaHat (sample), not resolved", k.slope,
                 k.gamma_sample,
                 "(the fit window spans " + ClaimCheck::format(efolds) +
                     " e-folds < 1: growth too slow to leave the floor before saturating)");
  }
  check.report(tag + ": fitted slope vs eq:gammaKKc", k.slope, k.gamma,
               "N -> infinity Gaussian form; differs from the sample's by the sigma0^2 error");
  return k;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("growth_rate",
                   "R(t) grows at gamma of eq:gammaKKc from the incoherent state, better with "
                   "larger K/K_c (Fig. growthRate)",
                   argc, argv);
  // Step 1: the ER network (high degree: the independence approximation's error falls with it).
  const bool full = check.full();
  const NodeIndex n = full ? 10000 : 2000;
  const double degree = full ? 2000.0 : 500.0;
  const int replicas = 3;
  const Network net = erdos_renyi({n, erdos_renyi_probability(n, degree), 1});
  const DistributedNetwork d(net);
  const double lambda = perron_eigenpair(d).lambda;
  const double bias = 0.05 * std::pow(160.0 / degree, 0.88);
  std::printf("  INFO  ER N = %lld, ||d|| = %g, lambda = %.2f, eq:bkApprox bias %.2f%%\n",
              static_cast<long long>(n), degree, lambda, 100 * bias);
  // Step 2: one run per K/K_c; Step 3: the comparison and the trend.
  const std::vector<double> xs{1.5, 2.0, 3.0, 4.0};
  std::vector<double> summary;
  std::vector<KResult> results;
  for (const double x : xs) {
    const KResult k = run_one_k(check, net, d, lambda, x, replicas, bias);
    std::printf(
        "  INFO  K/K_c %g: gamma eq:gammaKKc %.4f, eq:lambdaHat (sample) %.4f, fitted "
        "%.4f +- %.4f (SEM), relative error %.1f%%\n",
        x, k.gamma, k.gamma_sample, k.slope, k.slope_sem, 100 * k.rel_error);
    for (const double v : {x, k.gamma, k.gamma_sample, k.slope, k.slope_sem}) summary.push_back(v);
    results.push_back(k);
  }
  check.data(
      "summary", summary, xs.size(),
      {"K/K_c", "gamma eq:gammaKKc", "gamma eq:lambdaHat sample", "slope mean", "slope SEM"});
  check.note("K_over_Kc", "[1.5, 2, 3, 4]");
  check.holds("agreement improves with K/K_c", results.back().rel_error < results.front().rel_error,
              "relative error " + ClaimCheck::format(100 * results.front().rel_error) +
                  "% at K/K_c = 1.5, " + ClaimCheck::format(100 * results.back().rel_error) +
                  "% at 4");
  return check.exit_code();
}
