// Verification (beyond the paper): the water-bag's linear threshold and growth rate.
//
// Claim: eq:gDashPSGammaPlusOmega holds for any momentum density g. For the water-bag (uniform on
//   Omega +- D, D = sqrt(3) sigma0: the Gaussian's mean and sd) g' is two delta functions and
//   2N / (K lambda) = 1 / (gamma^2 + D^2): the incoherent state is linearly stable below
//   K_c^wb = 2 D^2 N / lambda = 6 sigma0^2 N / lambda (3 times the Gaussian's K_c; with Antoni and
//   Ruffo's K = 1 and lambda = N the threshold half-width is D_c = 1/sqrt 2) and above it R grows
//   at gamma = sqrt(K lambda / (2N) - D^2) (theory/linear_stability.hpp).
// Run:   verification_waterbag_threshold [--scale ci|full] [--output F.h5]
//        sigma0 = 0.35, Omega = 6, leap-frog h = 0.02 (h sqrt(K max R_n) < 0.04),
//        R recorded every step.
//        A. Threshold, on K_N (rank-one force) at N and 4N (ci: 10^4 and 4 10^4; full: 10^5 and
//           4 10^5; 8 replicas, 60 time units: the late window must hold about a period of the
//           stable mode, 2 pi / omega = 23 at 0.8 K_c^wb; R every step): K/K_c^wb = 0.8 and 1.2,
//           and Gaussian momenta at the same K as 0.8 K_c^wb (2.4 Gaussian K_c).
//           The same on ER, N = 2000 (full 10^4), at mean degree 100 and 400 (floor ~ d^-1/2;
//           4 replicas, 40 time units, R every 10 steps: only one-sided checks run there, and R
//           saturates by t ~ 20 at 1.1 K_c^wb and at 2.4 Gaussian K_c).
//        B. Growth, water-bag at K/K_c^wb = 1.5, 2, 3, 4 for 10/gamma + 10 on K_N (N = 10^5; full
//           10^6: the window below needs the floor low, ~N^-1/2). Not on ER: its floor ~ d^-1/2
//           (0.045 at d = 500) leaves less than one e-fold between gamma t = 3 and saturation at
//           any degree this machine holds in CI.
// Reference and tolerance:
//   A. (K_N; on ER the part below K_c^wb is reported, not checked: there R leaves the floor
//      within tens of time units, 0.09 -> 0.37 by t = 30 at d = 100 and 0.05 -> 0.29 by t = 45
//      at d = 400, while K_N stays at its floor; open: docs/results_beyond_the_paper.md.)
//      Below K_c^wb the incoherent state is a stable Vlasov equilibrium: the finite-N noise
//      (R(0) ~ N^-1/2) drives its undamped mode (eps(s) = (s^2 + omega^2) / (s^2 + D^2),
//      omega^2 = D^2 (1 - K/K_c^wb): the response is amplified by about (K/K_c^wb) / (1 -
//      K/K_c^wb), 4 at 0.8) but stays O(N^-1/2): the late R (mean over the last 30%) at 4N over
//      that at N is 1/2. Above K_c^wb R grows to an O(1) level: the ratio is ~1. Pass: below
//      K_c^wb (K_N) the ratio equals 1/2 within t SE (replica spread, propagated; t = 3.50, the
//      two-sided 99% Student multiplier for 8 replicas; 5.84 for ER's 4); above it, and for
//      Gaussian momenta, it
//      exceeds 1/2 by more than t SE (an O(1) level does not follow the floor); its value is
//      reported against 1 (the saturated level has finite-size corrections of its own: 0.95
//      between ER d = 100 and 400).
//   B. The fitted slope (verification/growth_rate.cpp's window rule, support/growth_fit.hpp, from
//      gamma t = 3: without Landau damping the water-bag's mode is seeded by the floor itself,
//      R ~ R(0) cosh(gamma t), and the excess's log-slope gamma coth(gamma t) is 42% above gamma
//      where the Gaussian rule starts; measured at 2 K_c^wb, N = 10^4: local slopes over t in
//      [2, 4] (gamma t in [1.2, 2.4], where coth gives 1.2-1.07) were 1.13-1.22 gamma, over
//      t in [4, 6] 0.98-1.05) against gamma of eq:lambdaHat for each replica's own momentum
//      sample. Tolerance: t SEM over the 3 seeds (t = 9.92, two-sided 99% with 2 dof) plus the
//      slope's measured shift when the same window starts at gamma t = 4 instead of 3 (what the
//      start still costs). On K_N without self-loops eq:bkApprox holds to O(1/N) (every rotor
//      sees the same field but its own); the closed form is reported.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/parallel_session.hpp"
#include "support/claim_check.hpp"
#include "support/growth_fit.hpp"
#include "support/network_scene.hpp"
#include "support/sample_statistics.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/linear_stability.hpp"

using namespace hmfnet;
using verification::ClaimCheck;

namespace {

constexpr double k_sigma0 = 0.35;
constexpr double k_omega = 6.0;
constexpr int k_growth_replicas = 3;

// A network with its rows, force, degrees and lambda (support/network_scene.hpp), and a name.
struct Graph : verification::NetworkScene {
  std::string name;
};

std::unique_ptr<Graph> complete_graph(NodeIndex n) {
  auto g = verification::complete_scene<Graph>(n);
  g->name = "K_" + std::to_string(n);
  return g;
}

std::unique_ptr<Graph> er_graph(NodeIndex n, double degree) {
  auto g =
      verification::stored_scene<Graph>(erdos_renyi({n, erdos_renyi_probability(n, degree), 1}));
  g->name = "ER N = " + std::to_string(n) + ", d = " + ClaimCheck::format(degree);
  return g;
}

// One run of `replicas` replicas at K for `duration`, R every step.
SimulationResult run(ClaimCheck& check, const Graph& g, MomentumDistribution momenta, double K,
                     double duration, int replicas, int stride = 1) {
  SimulationParameters p;
  p.h = 0.02;
  p.duration = duration;
  p.transient = 0.0;
  p.K = {K};
  p.record_stride = stride;
  p.replicas.clear();
  for (int b = 0; b < replicas; ++b) {
    p.replicas.push_back({k_omega, k_sigma0, static_cast<std::uint64_t>(21 + b), momenta});
  }
  SimulationResult r = simulate(*g.rows, g.degrees, *g.force, p);
  verification::account(check, p, r);
  return r;
}

std::vector<double> replica_series(const SimulationResult& r, std::size_t b) {
  const std::size_t B = r.points[0].R_mean.size(), records = r.series.t.size();
  std::vector<double> R(records);
  for (std::size_t i = 0; i < records; ++i) R[i] = r.series.R[i * B + b];
  return R;
}

// Mean R over the last 30% of each replica's run.
std::vector<double> late_levels(const SimulationResult& r) {
  std::vector<double> out;
  for (std::size_t b = 0; b < r.points[0].R_mean.size(); ++b) {
    const std::vector<double> R = replica_series(r, b);
    const std::size_t tail = R.size() - (3 * R.size()) / 10;
    double sum = 0.0;
    for (std::size_t i = tail; i < R.size(); ++i) sum += R[i];
    out.push_back(sum / static_cast<double>(R.size() - tail));
  }
  return out;
}

// Ratio of replica means and its standard error (independent replicas at each size).
struct Ratio {
  double value = 0.0, se = 0.0, small = 0.0, large = 0.0;
};
Ratio ratio_of(const std::vector<double>& large, const std::vector<double>& small) {
  const auto a = verification::mean_sd(large), b = verification::mean_sd(small);
  const double B = std::sqrt(static_cast<double>(large.size()));
  Ratio q;
  q.small = b.mean;
  q.large = a.mean;
  q.value = a.mean / b.mean;
  q.se = q.value * std::hypot(a.sd / B / a.mean, b.sd / B / b.mean);
  return q;
}

// Step A: below and above K_c^wb on two networks whose finite-size floors differ by 2 (K_N at N
// and 4N; ER at mean degree d and 4d, whose floor is ~ d^-1/2, Fig. ERerror), and the Gaussian
// at the first K.
// How each threshold pair is run: replicas, duration and record stride.
struct ThresholdRuns {
  int replicas;
  double duration;
  int stride;
};

void threshold(ClaimCheck& check, const Graph& small, const Graph& large, const ThresholdRuns& how,
               std::vector<double>& table) {
  const auto Kc = [](const Graph& g) {
    return critical_coupling(MomentumDistribution::waterbag, k_sigma0, g.n, g.lambda);
  };
  const auto late = [&](const Graph& g, MomentumDistribution m, double kappa) {
    return late_levels(run(check, g, m, kappa * Kc(g), how.duration, how.replicas, how.stride));
  };
  const std::string on = " on " + small.name + " vs " + large.name;
  const double t = verification::t_multiplier_99(how.replicas);
  const std::string why_t =
      "t = " + ClaimCheck::format(t) + " (99%, " + std::to_string(how.replicas - 1) + " dof) SE";
  // Above the threshold (or with Gaussian momenta) the level must not follow the floor: the
  // ratio lies above 1/2 by more than its uncertainty (it is ~1 for an O(1) level; reported).
  const auto unstable = [&](const std::string& what, const Ratio& q) {
    check.holds(what + " does not follow the floor", q.value - 0.5 > t * q.se,
                "ratio " + ClaimCheck::format(q.value) + " - 1/2 > " + why_t + " (" +
                    ClaimCheck::format(t * q.se) + ")");
    check.report(what + ", against an N-independent level", q.value, 1.0,
                 "the saturated level's finite-size dependence makes it differ from 1");
  };
  for (const double kappa : {0.8, 1.2}) {
    const Ratio q = ratio_of(late(large, MomentumDistribution::waterbag, kappa),
                             late(small, MomentumDistribution::waterbag, kappa));
    std::printf("  INFO  water-bag K = %.1f K_c^wb%s: late R %.4f, %.4f\n", kappa, on.c_str(),
                q.small, q.large);
    const std::string what =
        "late R ratio, water-bag at " + ClaimCheck::format(kappa) + " K_c^wb" + on;
    table.insert(table.end(),
                 {small.complete ? 0.0 : 1.0, kappa, 0.0, q.small, q.large, q.value, q.se});
    if (kappa > 1.0) {
      unstable(what, q);
    } else if (!small.complete) {
      // Found, not yet explained (docs/results_beyond_the_paper.md): on ER the water-bag below
      // K_c^wb leaves its floor within tens of time units, which K_N at the same kappa does not.
      check.report(what, q.value, 0.5,
                   "not checked: on ER the incoherent water-bag does not stay at its floor below "
                   "K_c^wb (late R " +
                       ClaimCheck::format(q.small) + " and " + ClaimCheck::format(q.large) +
                       "); see docs/results_beyond_the_paper.md");
    } else {
      check.within_abs(what, q.value, 0.5, t * q.se,
                       "1/2: a stable state's noise follows the floor; " + why_t);
    }
  }
  // The same K with Gaussian momenta is 2.4 times the Gaussian K_c: it synchronises.
  const Ratio q = ratio_of(late(large, MomentumDistribution::gaussian, 0.8),
                           late(small, MomentumDistribution::gaussian, 0.8));
  std::printf("  INFO  Gaussian at 0.8 K_c^wb = 2.4 K_c%s: late R %.4f, %.4f\n", on.c_str(),
              q.small, q.large);
  unstable("late R ratio, Gaussian at 0.8 K_c^wb = 2.4 K_c" + on, q);
  table.insert(table.end(),
               {small.complete ? 0.0 : 1.0, 0.8, 1.0, q.small, q.large, q.value, q.se});
}

// Step B: growth rates on one network.
void growth(ClaimCheck& check, const Graph& g, std::vector<double>& table) {
  const double Kc = critical_coupling(MomentumDistribution::waterbag, k_sigma0, g.n, g.lambda);
  const double t99 = verification::t_multiplier_99(k_growth_replicas);
  for (const double kappa : {1.5, 2.0, 3.0, 4.0}) {
    const double gamma = growth_rate(MomentumDistribution::waterbag, kappa, k_sigma0);
    const SimulationResult r = run(check, g, MomentumDistribution::waterbag, kappa * Kc,
                                   10.0 / gamma + 10.0, k_growth_replicas);
    std::vector<double> slopes, later;
    double reference = 0.0, efolds = INFINITY;
    for (std::size_t b = 0; b < k_growth_replicas; ++b) {
      // The mode grows from the floor itself (support/growth_fit.hpp): the window starts at
      // gamma t = 3; the same fit from gamma t = 4 measures what the start still costs.
      const std::vector<double> R = replica_series(r, b);
      const verification::Fit f = verification::fit_growth(r.series.t, R, gamma, 3.0 / gamma);
      const verification::Fit f4 = verification::fit_growth(r.series.t, R, gamma, 4.0 / gamma);
      slopes.push_back(f.usable ? f.slope : NAN);
      later.push_back(f4.usable ? f4.slope : NAN);
      efolds = std::min(efolds, f.efolds);
      const InitialCondition ic{k_omega, k_sigma0, static_cast<std::uint64_t>(21 + b),
                                MomentumDistribution::waterbag};
      reference += verification::sample_growth_rate(g.n, kappa * Kc, g.lambda, ic, gamma) /
                   static_cast<double>(k_growth_replicas);
    }
    const auto ms = verification::mean_sd(slopes);
    const double sem = ms.sd / std::sqrt(static_cast<double>(k_growth_replicas));
    const double start_shift = std::abs(verification::mean_sd(later).mean - ms.mean);
    std::printf(
        "  INFO  %s, K = %g K_c^wb: gamma %.4f (closed form), %.4f (samples), fitted "
        "%.4f +- %.4f (from gamma t = 4: %+.4f)\n",
        g.name.c_str(), kappa, gamma, reference, ms.mean, sem,
        verification::mean_sd(later).mean - ms.mean);
    const std::string tag = g.name + ", K = " + ClaimCheck::format(kappa) + " K_c^wb";
    if (efolds >= 1.0 && std::isfinite(start_shift)) {
      check.within_abs(tag + ": fitted slope vs gamma of the samples", ms.mean, reference,
                       t99 * sem + start_shift,
                       "t = " + ClaimCheck::format(t99) +
                           " (99%, 2 dof) SEM over seeds + the "
                           "slope's shift when the window starts at gamma t = 4 (" +
                           ClaimCheck::format(start_shift) + ")");
    } else {
      check.report(tag + ": fitted slope, not resolved", ms.mean, reference,
                   "fit window < 1 e-fold from gamma t = 3, or none from gamma t = 4");
    }
    check.report(tag + ": fitted slope vs sqrt(K lambda / 2N - D^2)", ms.mean, gamma,
                 "N -> infinity closed form; the samples' D differs by O(N^-1/2)");
    table.insert(table.end(), {g.complete ? 0.0 : 1.0, kappa, gamma, reference, ms.mean, sem});
  }
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("waterbag_threshold",
                   "water-bag momenta: linear threshold 6 sigma0^2 N / lambda and growth rate "
                   "(beyond the paper)",
                   argc, argv);
  const bool full = check.full();
  std::vector<double> thresholds, rates;
  const NodeIndex n_k = full ? 100000 : 10000;
  threshold(check, *complete_graph(n_k), *complete_graph(4 * n_k), {8, 60.0, 1}, thresholds);
  const NodeIndex n_er = full ? 10000 : 2000;
  threshold(check, *er_graph(n_er, 100.0), *er_graph(n_er, 400.0), {4, 40.0, 10}, thresholds);
  growth(check, *complete_graph(full ? 1000000 : 100000), rates);
  check.data("threshold", thresholds, thresholds.size() / 7,
             {"ER", "K/K_c^wb", "gaussian", "late R small", "late R large", "ratio", "ratio se"});
  check.data("growth", rates, rates.size() / 6,
             {"ER", "K/K_c^wb", "gamma closed form", "gamma samples", "slope", "slope se"});
  // Antoni-Ruffo units: K = 1, lambda = N. K_c^wb is proportional to sigma0^2, so the threshold
  // half-width D_c = sqrt(3) sigma0_c follows from the library's threshold at sigma0 = 1.
  const double n_ar = 1000.0;
  // The general path (quadrature of the smooth part plus the jumps, theory/linear_stability.hpp),
  // not the closed form that K_c^wb = 6 sigma0^2 N / lambda is computed from.
  const double D_c = std::sqrt(
      3.0 / linear_threshold(even_density(MomentumDistribution::waterbag, 1.0), n_ar, n_ar));
  check.within_rel("threshold half-width D_c at K = 1, lambda = N (general dispersion path)", D_c,
                   1.0 / std::sqrt(2.0), 1e-10,
                   "Delta_c = 1/sqrt 2 (Antoni-Ruffo); the general path's tested accuracy");
  return check.exit_code();
}
