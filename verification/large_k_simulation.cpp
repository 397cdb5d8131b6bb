// Verification: simulated <R>_t at large K against R_hat of eq:KtoInfinity (Fig. maxSynchrony,
// the blue circles).
//
// Claims: (a) "For the simulations, K = 10^4 and the observed order parameters are about 1%
//   smaller than the theory"; (b) like R_hat, the simulated <R>_t is nearly independent of alpha
//   (scale-free Chung-Lu, capped, alpha = 2.5, 2.8, 3.1, 3.5, 3.8, ||d|| = 100: Table II's family,
//   as in max_synchrony_alpha.cpp, network seed 1), sigma0 = 0.35, Omega = 6.
// Run:   verification_large_k_simulation [--scale ci|full]   (ctest -L verification)
//        Every alpha starts from the incoherent state at K = N (the paper's K = 10^4 at N = 10^4;
//        K/K_c = lambda K / (2 sigma0^2 N) = lambda / 0.245 is then the paper's ratio at either
//        N: 540-1180, printed per alpha).
//        ci: N = 2000, T2 = 400, T1 = 200, h = 0.01, 2 replicas (~65 s CPU); full: N = 10^4,
//        the paper's T2 = 1000, T1 = 500, h = 0.01, 1 replica (630 s CPU, 11 min wall).
// Relaxation: R jumps to ~0.6 within one time unit (growth rate ~ sqrt(K lambda / 2N) ~ 10),
//   then creeps up over ~200 time units (the HMF model's quasi-stationary states). Measured,
//   N = 2000, alpha = 2.5, 2 replicas: <R> over [0, 100] 0.644, [100, 200] 0.654, [200, 2000]
//   0.6565 +- 0.001 against R_hat = 0.6558; a run with T1 = 20, T2 = 60 gives 0.6485, i.e. 1.1%
//   below R_hat: the paper's "about 1%" is what an unrelaxed run shows. Hence T1 = 200 at ci.
// Step size: leap-frog is stable for h omega_max < 2, omega_max = sqrt(K max_n R_n) (the hubs'
//   libration); with max_n r_n of the theory at this K, h omega_max is printed and checked
//   (< 1, margin 2; the blow-up guard stops the run otherwise). Measured: 0.27-0.30 (ci),
//   0.35-0.56 (full). Accuracy: alpha = 2.5 (the largest h omega_max) is rerun at h/2 from the
//   same initial state with the same T and |<R>_t(h) - <R>_t(h/2)| must be below 3 combined SEM
//   (the trajectories are chaotic, so the two runs are statistically independent samples).
//   Measured (ci): h = 0.01 vs 0.005 differ by 1.5 combined SEM (0.0011); h = 0.02 was not
//   accurate (0.6535 against 0.6572 at h = 0.01, 6 SEM: a -0.6% bias), so h = 0.01 it is.
//   Full: 0.6583 (h = 0.01) against 0.6597 (h = 0.005), 2.6 combined SEM: if real, an O(h^2)
//   bias of -0.2% at the paper's h where h omega_max = 0.56, i.e. part of the 0.55% gap at
//   alpha = 2.5 and perhaps of the paper's 1%.
// References: R_hat of eq:KtoInfinity on the same network (large_k_limit.hpp), and the finite-K
//   state eq:rSigmaBesselMain at this K (self_consistent.hpp): at the nominal sigma0 with U0 = 0,
//   and at each replica's own conserved E and P (mu0 = 2E/N - (P/N)^2, as in
//   simulation_vs_theory.cpp: at large K the random initial potential energy K c0 ~ K
//   sqrt(||d|| N) / N^2 is comparable to sigma0^2, so mu0 differs from sigma0^2 by O(1); in R
//   both enter only through mu0 / K, an O(K_c / K) correction).
// Tolerances, per alpha (SEM: batch means of <R>_t over [T1, T2], combined over replicas):
//   finite K: (R_hat - R(K)) / R_hat from the two solves, O(K_c / K) (the mu0 / K term of eta):
//   measured 0.08-0.10% at sigma0, within +-0.3% at the runs' (E, P);
//   finite size: the incoherent part of each local field adds to the coherent part in
//   quadrature, delta_fs = sqrt(R^2 + R_floor^2) - R, with R_floor = sum_n sqrt(pi d_n) / 2 /
//   (N ||d||) the order parameter of independent uniform phases (Rayleigh mean of d_n unit
//   phasors), an upper bound because in the synchronized state each phasor's incoherent part is
//   smaller; delta_fs ~ R_floor^2 / (2 R) = O(1 / ||d||): 0.8-0.95% of R. It dominates the
//   budget (3 SEM: 0.1-0.25%).
//   (a1) |<R>_t - R(K at E, P)| <= 3 SEM + delta_fs (the finite-K theory is the right reference).
//   (a2) the gap g = (R_hat - <R>_t) / R_hat is reported beside the paper's 1% and checked:
//   |g| <= |finite K| + (3 SEM + delta_fs) / R_hat. "Below R_hat": per alpha <R>_t <= R_hat +
//   3 SEM + delta_fs (delta_fs can lift <R>_t), and over the family the mean gap > -3 SEM.
//   Measured gaps (%), alpha = 2.5 ... 3.8: ci -0.16, -0.13, 0.20, 0.27, 0.61 (mean 0.16 +-
//   0.03); full 0.55, 0.22, 0.30, 0.19, 0.21. The relaxed simulations are 0.2-0.6% below
//   R_hat, not 1%, and agree with the finite-K theory within 0.35% (well inside delta_fs).
//   (b) the spread (max - min) / mean of <R>_t over alpha is below 10% (max_synchrony_alpha's
//   reading of "nearly independent") and within 2 (3 SEM + delta_fs) / mean of R_hat's spread,
//   while lambda's spread exceeds 20% (ci: 4.6% against lambda's 25%; at N = 2000 the cutoff
//   N - 1 narrows lambda's range to a factor 1.28, against 2.1 at N = 10^4).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;
using verification::ClaimCheck;

namespace {

constexpr double k_sigma0 = 0.35;
constexpr double k_omega = 6.0;
constexpr double k_sqrt_pi = 1.7724538509055160273;

struct Scale {
  NodeIndex n;
  double duration, transient, h;
  int replicas;
  double halving_duration, halving_transient;
};

struct Sample {
  double mean = 0.0, sem = 0.0;  ///< <R>_t over replicas and its combined batch-means SEM
  double theory_ep = 0.0;        ///< eq:rSigmaBesselMain at each replica's (E, P), averaged
  double energy_error = 0.0;     ///< max relative energy error over replicas
  bool converged = true;
};

// One run at coupling K from the incoherent state; the theory at each replica's E and P.
Sample simulate_at(ClaimCheck& check, const Network& net, const DistributedNetwork& d,
                   const PerronResult& perron, double K, double h, double duration,
                   double transient, int replicas) {
  SimulationParameters p;
  p.h = h;
  p.duration = duration;
  p.transient = transient;
  p.K = {K};
  p.replicas.clear();
  for (int b = 0; b < replicas; ++b) {
    p.replicas.push_back({k_omega, k_sigma0, static_cast<std::uint64_t>(100 + b)});
  }
  p.record_stride = 100;
  const auto force = app::choose_force("auto", "float64", d);
  const SimulationResult sim = simulate(d, net.degrees(), *force, p);
  verification::account(check, p, sim);
  const PointResult& pt = sim.points.front();
  const auto B = static_cast<std::size_t>(replicas);
  const double n = static_cast<double>(net.size());
  const std::size_t last = sim.series.K.size() - 1;
  Sample s;
  for (std::size_t b = 0; b < B; ++b) {
    s.mean += pt.R_mean[b] / static_cast<double>(B);
    s.sem += pt.R_sem[b] * pt.R_sem[b];
    s.energy_error = std::max(s.energy_error, pt.energy_rel_error_max[b]);
    // mu0 = sigma0^2 - K c0 = 2E/N - (P/N)^2 (self_consistent.hpp, eq:Hsub0).
    const double P = sim.series.momentum[last * B + b] / n;
    const double mu0 = 2.0 * sim.series.energy[last * B + b] / n - P * P;
    const double c0 = (k_sigma0 * k_sigma0 - mu0) / K;
    const SelfConsistentSystem system(net, perron.lambda, k_sigma0, c0, perron.u);
    const SelfConsistentSolution sol = system.solve(K);
    s.converged = s.converged && sol.status == SolveStatus::converged;
    s.theory_ep += sol.R / static_cast<double>(B);
  }
  s.sem = std::sqrt(s.sem) / static_cast<double>(B);
  return s;
}

struct AlphaResult {
  double alpha, lambda, K, Kc, R_hat, rd, R_K, h_omega, R_floor;
  Sample sim;
  bool converged;
};

// Steps 2-4 for one alpha: the network, the references and the simulation.
AlphaResult run_alpha(ClaimCheck& check, double alpha, const Scale& sc) {
  const double d_min = power_law_d_min_for_mean(alpha, 100.0);
  const Network net =
      chung_lu(power_law_targets(sc.n, {alpha, d_min, sc.n - 1.0}, 1), LinkProbability::capped, 1);
  const DistributedNetwork d(net);
  const PerronResult perron = perron_eigenpair(d);
  const double n = static_cast<double>(net.size());
  AlphaResult a{};
  a.alpha = alpha;
  a.lambda = perron.lambda;
  a.K = n;  // the paper's K / N = 1 (K = 10^4 at N = 10^4)
  a.Kc = critical_coupling(k_sigma0, n, perron.lambda);
  const LargeKLimit limit = solve_large_k_limit(net);
  a.R_hat = limit.R_hat;
  a.rd = degree_approximation_R_hat(net.degrees());
  const SelfConsistentSystem nominal(net, perron.lambda, k_sigma0, 0.0, perron.u);
  const SelfConsistentSolution sol = nominal.solve(a.K);
  a.R_K = sol.R;
  a.h_omega = sc.h * std::sqrt(a.K * *std::max_element(sol.r.begin(), sol.r.end()));
  double floor_sum = 0.0;
  for (const double dn : net.degrees()) floor_sum += k_sqrt_pi * std::sqrt(dn) / 2.0;
  a.R_floor = floor_sum / (n * mean_degree(net));
  a.converged = limit.status == SolveStatus::converged && sol.status == SolveStatus::converged;
  a.sim = simulate_at(check, net, d, perron, a.K, sc.h, sc.duration, sc.transient, sc.replicas);
  a.converged = a.converged && a.sim.converged;
  std::printf(
      "  INFO  alpha %.1f: lambda %.1f, K %.0f, K_c %.3f, K/K_c %.0f, h omega_max %.3f; <R>_t "
      "%.4f +- %.4f (SEM), energy error %.1e; R_hat %.4f, R(K) %.4f (sigma0), %.4f (E, P); "
      "eq:rd %.4f; R_floor %.4f\n",
      alpha, a.lambda, a.K, a.Kc, a.K / a.Kc, a.h_omega, a.sim.mean, a.sim.sem, a.sim.energy_error,
      a.R_hat, a.R_K, a.sim.theory_ep, a.rd, a.R_floor);
  return a;
}

// Claim (a) for one alpha.
void check_gap(ClaimCheck& check, const AlphaResult& a) {
  const std::string at = "alpha " + ClaimCheck::format(a.alpha) + ": ";
  const double R = a.sim.theory_ep;
  const double fs = std::sqrt(R * R + a.R_floor * a.R_floor) - R;
  const double stat = 3.0 * a.sim.sem;
  check.within_abs(at + "<R>_t vs eq:rSigmaBesselMain at this K and the run's (E, P)", a.sim.mean,
                   R, stat + fs,
                   "3 SEM (" + ClaimCheck::format(stat) + ") + finite-size delta_fs (" +
                       ClaimCheck::format(fs) + ")");
  const double gap = (a.R_hat - a.sim.mean) / a.R_hat;
  const double finite_k = (a.R_hat - R) / a.R_hat;
  check.report(at + "gap (R_hat - <R>_t) / R_hat", gap, 0.01,
               "paper: about 1%; budget: finite K " + ClaimCheck::format(finite_k) +
                   " (at sigma0, U0 = 0: " + ClaimCheck::format((a.R_hat - a.R_K) / a.R_hat) +
                   ", K_c / K = " + ClaimCheck::format(a.Kc / a.K) + ")" + ", 3 SEM " +
                   ClaimCheck::format(stat / a.R_hat) + ", finite size " +
                   ClaimCheck::format(fs / a.R_hat) +
                   " (K/K_c = " + ClaimCheck::format(a.K / a.Kc) + ")");
  const double bound = std::abs(finite_k) + (stat + fs) / a.R_hat;
  check.holds(at + "gap small: |gap| <= |finite K| + (3 SEM + delta_fs) / R_hat",
              std::abs(gap) <= bound,
              "|gap| " + ClaimCheck::format(std::abs(gap)) + " <= " + ClaimCheck::format(bound));
  check.holds(at + "<R>_t not above R_hat beyond 3 SEM + delta_fs",
              a.sim.mean <= a.R_hat + stat + fs,
              ClaimCheck::format(a.sim.mean) + " <= " + ClaimCheck::format(a.R_hat) + " + " +
                  ClaimCheck::format(stat + fs));
  check.holds(at + "leap-frog stable with margin: h omega_max < 1", a.h_omega < 1.0,
              "h sqrt(K max_n r_n) = " + ClaimCheck::format(a.h_omega) +
                  " (stability limit 2); energy error " + ClaimCheck::format(a.sim.energy_error));
}

double spread(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  double mean = 0.0;
  for (const double v : x) mean += v / static_cast<double>(x.size());
  return (*hi - *lo) / mean;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("large_k_simulation",
                   "simulated <R>_t at K = 10^4 about 1% below R_hat (eq:KtoInfinity) and nearly "
                   "independent of alpha (Fig. maxSynchrony)",
                   argc, argv);
  // Step 1: scale.
  const Scale sc = check.full() ? Scale{10000, 1000.0, 500.0, 0.01, 1, 1000.0, 500.0}
                                : Scale{2000, 400.0, 200.0, 0.01, 2, 400.0, 200.0};
  const double alphas[] = {2.5, 2.8, 3.1, 3.5, 3.8};
  // Steps 2-4: per alpha, the network, R_hat, R(K), the simulation and claim (a).
  std::vector<AlphaResult> results;
  std::vector<double> table, R_sim, R_hat, lambda;
  bool converged = true;
  double budget = 0.0;
  for (const double alpha : alphas) {
    results.push_back(run_alpha(check, alpha, sc));
    const AlphaResult& a = results.back();
    converged = converged && a.converged;
    check_gap(check, a);
    R_sim.push_back(a.sim.mean);
    R_hat.push_back(a.R_hat);
    lambda.push_back(a.lambda);
    const double fs =
        std::sqrt(a.sim.theory_ep * a.sim.theory_ep + a.R_floor * a.R_floor) - a.sim.theory_ep;
    budget = std::max(budget, 3.0 * a.sim.sem + fs);
    for (const double v : {a.alpha, a.lambda, a.K, a.Kc, a.sim.mean, a.sim.sem, a.R_hat, a.R_K,
                           a.sim.theory_ep, a.rd, a.R_floor}) {
      table.push_back(v);
    }
  }
  // "Below R_hat" over the family: the mean gap and its SEM (replica and batch errors combined).
  double mean_gap = 0.0, gap_var = 0.0;
  for (const AlphaResult& a : results) {
    const double m = static_cast<double>(results.size());
    mean_gap += (a.R_hat - a.sim.mean) / a.R_hat / m;
    gap_var += a.sim.sem * a.sim.sem / (a.R_hat * a.R_hat * m * m);
  }
  check.report("mean gap over alpha", mean_gap, 0.01,
               "paper: about 1%; SEM " + ClaimCheck::format(std::sqrt(gap_var)));
  check.holds("<R>_t below R_hat on average over alpha (mean gap > -3 SEM)",
              mean_gap > -3.0 * std::sqrt(gap_var),
              "mean gap " + ClaimCheck::format(mean_gap) + ", SEM " +
                  ClaimCheck::format(std::sqrt(gap_var)));
  check.holds("every eq:KtoInfinity and eq:rSigmaBesselMain solve converged", converged,
              "relative residual <= 1e-10");
  // Step 5: claim (b).
  double mean = 0.0;
  for (const double r : R_sim) mean += r / static_cast<double>(R_sim.size());
  check.holds("<R>_t nearly independent of alpha: spread < 10%", spread(R_sim) < 0.10,
              "spread " + ClaimCheck::format(100.0 * spread(R_sim)) +
                  "% (R_hat: " + ClaimCheck::format(100.0 * spread(R_hat)) +
                  "%, lambda: " + ClaimCheck::format(100.0 * spread(lambda)) + "%)");
  check.within_abs("spread of <R>_t vs spread of R_hat", spread(R_sim), spread(R_hat),
                   2.0 * budget / mean, "2 (3 SEM + delta_fs) / mean, largest over alpha");
  check.holds(
      "... while lambda's spread exceeds 20%", spread(lambda) > 0.20,
      "spread " + ClaimCheck::format(100.0 * spread(lambda)) + "%, lambda(2.5) / " +
          "lambda(3.8) = " + ClaimCheck::format(lambda.front() / lambda.back()) +
          "; <R>_t spread / lambda spread = " + ClaimCheck::format(spread(R_sim) / spread(lambda)));
  // Step 6: accuracy of the step, alpha = 2.5 at h/2.
  {
    const double alpha = alphas[0];
    const double d_min = power_law_d_min_for_mean(alpha, 100.0);
    const Network net = chung_lu(power_law_targets(sc.n, {alpha, d_min, sc.n - 1.0}, 1),
                                 LinkProbability::capped, 1);
    const DistributedNetwork d(net);
    const PerronResult perron = perron_eigenpair(d);
    const double K = results[0].K;
    const Sample coarse = sc.halving_duration == sc.duration
                              ? results[0].sim
                              : simulate_at(check, net, d, perron, K, sc.h, sc.halving_duration,
                                            sc.halving_transient, sc.replicas);
    const Sample fine = simulate_at(check, net, d, perron, K, sc.h / 2.0, sc.halving_duration,
                                    sc.halving_transient, sc.replicas);
    const double sem = std::hypot(coarse.sem, fine.sem);
    std::printf("  INFO  alpha %.1f: <R>_t %.4f +- %.4f (h), %.4f +- %.4f (h/2)\n", alpha,
                coarse.mean, coarse.sem, fine.mean, fine.sem);
    check.within_abs("alpha 2.5: <R>_t at h/2 vs h", fine.mean, coarse.mean, 3.0 * sem,
                     "3 combined SEM; change / SEM = " +
                         ClaimCheck::format(std::abs(fine.mean - coarse.mean) / sem));
    check.data("step_halving", {{"h", sc.h},
                                {"R h", coarse.mean},
                                {"SEM h", coarse.sem},
                                {"R h/2", fine.mean},
                                {"SEM h/2", fine.sem}});
  }
  check.data("points", table, results.size(),
             {"alpha", "lambda", "K", "K_c", "R_sim", "R_sim SEM", "R_hat", "R(K) sigma0",
              "R(K) (E, P)", "eq:rd", "R_floor"});
  check.note("network", "Chung-Lu capped, seed 1, N = " + std::to_string(sc.n) +
                            ", ||d|| = 100; sigma0 = 0.35, Omega = 6, K = N");
  return check.exit_code();
}
