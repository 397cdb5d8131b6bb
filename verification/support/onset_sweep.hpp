#pragma once
// The onset of synchrony measured from a K sweep, shared by the drivers of Figs. ERPLnet, PLcorr
// and ERstdP (onset_er_sf, onset_rewired, onset_sigma0).
//
// Sweep: the paper's protocol (Sec. numericalExperiments): K raised in steps from 0, each K
// continuing from the current state, <R>_t over [T1, T2] (eq:timeAverage). The grid is given in
// x = K / K_c with K_c = 2 sigma0^2 N / lambda (eq:criticalKFirstOrder), so every network is
// sampled at the same lambda K / (2 sigma0^2 N); B replicas (seeds of the initial condition)
// run side by side.
//
// Equilibration (critical slowing down): above K_c the state relaxes from the previous grid
//   point's state on the time scale of the growth rate gamma(x) of eq:gammaKKc
//   (theory/growth_rate.hpp; gamma ~ sqrt(2/pi) sigma0 (1 - 1/x) near onset: 0.027 at x = 1.1,
//   0.052 at 1.2 for sigma0 = 0.35). Measured (ER <d> = 50, sigma0 = 0.35 and ER <d> = 100,
//   sigma0 = 0.2, N = 1000, 3 replicas, 600 time units per K, means over 25-unit windows): the
//   approach of <R> to its plateau is slower than 1/gamma, time constant tau ~ 6-9 / gamma at
//   x = 1.35-3 (e.g. x = 1.35, sigma0 = 0.35: R 0.249 -> 0.30 over ~200 time units); the steps
//   between grid points are Delta R ~ 0.05. A segment of T2 at one K is therefore used only if
//   the time already spent at that K before its average starts is at least k_equilibration_efolds /
//   gamma(x) (= 15 / gamma ~ 2 tau: the residual lag is <~ e^-2 Delta R ~ 0.007 at the start of the
//   average, less over it, below the per-point error ~0.01-0.02). A grid point gets m repeated
//   segments at its K (a repeated K continues the state; the first m - 1 are relaxation) with
//   the smallest m for which its last segment qualifies, if m <= max_segments; otherwise one
//   segment, and the point is shown but not equilibrated. Points at x <= 1 have no growing mode
//   (gamma undefined) and are never equilibrated in this sense; they are not needed by the fit
//   (theory R = 0 there). A point's <R> is the mean over its qualifying segments (its last
//   segment when none qualifies).
//
// Onset rule (one rule for simulation and theory, on the same points):
//   excess E(x) = sqrt(max(<R>^2 - R0^2, 0)), R0 = <R>_t at K = 0: the finite-size floor
//   (R ~ ||sqrt d|| / ||d|| of incoherent rotors, Sec. numericalExperiments), removed in
//   quadrature because the incoherent fluctuation and the coherent part add as independent
//   vectors. Near onset E^2 grows linearly in K (eq:globalOrderRInDeltaK), so x_on is the zero of
//   the weighted least-squares line through (x, E^2) over the equilibrated grid points with
//   k_window_low <= E <= k_window_high (at least 3): below 0.1 the excess is dominated by the
//   near-critical enhancement of the floor fluctuations (E ~ 0.07 at x = 0.9 measured, ER
//   <d> = 100, N = 1000), above 0.35 R^2 bends away from the line (eq:globalOrderRInDeltaK holds
//   only near K_c). When the sweep leaves fewer than 3 points in the window, the grid is refined
//   once by the rule of onset_grid.hpp (midpoints where the window lies between two grid points)
//   and the refined prefix is swept again from K = 0. The theory curve (eq:rSigmaBesselMain of the
//   same network, R = 0 below K_c, no floor) goes through the same fit on the same points with the
//   same weights: x_on(theory) is where the rule puts the onset of a system that follows the theory
//   exactly, so x_on - x_on(theory) is free of the rule's curvature bias x_on(theory) - 1.
//   The same fit on the theory at the sweep's own energy and momentum (theory_at_sweep_state)
//   separates the sweep's energy path from the dynamics: at ci scale (onset_rewired, N = 1000)
//   it moves x_on(theory) from 0.86-0.91 to 0.90-0.95 against the simulated 0.97-1.12, so the
//   energy path explains 0.03-0.04 of the 0.06-0.26 gap; at x = 3 it raises the theory by ~7%.
// Errors: a point's error is the larger of the replica spread sd / sqrt(B) and the batch-means
//   SEM of the time average / sqrt(B) (both of the mean over its qualifying segments);
//   dE^2 = 2 R dR. The standard error of x_on follows from the covariance of the fitted line
//   (weights 1 / dE^2^2), x_on = -a / b: var = (var a + x_on^2 var b + 2 x_on cov ab) / b^2.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/network.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"
#include "support/onset_grid.hpp"
#include "support/pipeline_step.hpp"
#include "support/run_variance.hpp"
#include "support/sample_statistics.hpp"
#include "support/work_account.hpp"
#include "theory/growth_rate.hpp"
#include "theory/self_consistent.hpp"

namespace hmfnet::verification {

/// c of the equilibration criterion: time at K before a segment's average >= c / gamma(x).
constexpr double k_equilibration_efolds = 15.0;

struct SweepProtocol {
  std::vector<double> x;  ///< K / K_c, increasing, x[0] = 0 (the floor R0)
  double h = 0.01;        ///< leap-frog step (unless pipeline_steps)
  /// Per grid point the method of support/pipeline_step.hpp (the paper-scale work-precision
  /// choice for that x and sigma0) instead of leap-frog with h.
  bool pipeline_steps = false;
  SceneFamily family = SceneFamily::erdos_renyi;  ///< the scene of pipeline_step
  double duration = 1000;                         ///< T2 per segment
  double transient = 500;                         ///< T1 per segment
  int max_segments = 4;  ///< repeated segments allowed per grid point (>= 1)
  int replicas = 3;      ///< initial-condition seeds 1..B (times seed_base)
  std::uint64_t seed_base = 1000;
  double omega = 6.0;
};

struct OnsetCurve {
  double lambda = 0.0, Kc = 0.0, sigma0 = 0.0;
  std::vector<double> x, K;
  std::vector<double> R, R_err;  ///< replica mean of <R>_t and its error
  std::vector<double> R_theory;  ///< eq:rSigmaBesselMain (0 below K_c)
  /// eq:rSigmaBesselMain at the energy and momentum the sweep has at each K (replica mean; NaN
  /// where a solve failed): see theory_at_sweep_state.
  std::vector<double> R_theory_ep;
  std::vector<double> segments;      ///< segments run at each grid point
  std::vector<double> equilibrated;  ///< 1: at least one segment met the criterion
  std::vector<double> fitted;        ///< 1: used by the onset fit
  double R0 = 0.0;
  double x_on = NAN, x_on_err = NAN;  ///< simulation onset and its statistical error
  double x_on_theory = NAN;           ///< the same fit on the theory curve
  double x_on_theory_ep = NAN;        ///< the same fit on R_theory_ep
  int points = 0;                     ///< grid points in the fit
  SimulationCost cost;                ///< of every sweep run for this curve
  /// Refined grids: largest |<R>| difference between the two sweeps on the points before the
  /// first midpoint (same seeds, same K sequence: must be 0); NaN when not refined.
  double prefix_repeat = NAN;
};

struct Onset {
  double x = NAN, err = NAN;
};

/// Time at K = x K_c before an average may start: k_equilibration_efolds / gamma(x); infinite at
/// x <= 1 (no growing mode).
inline double equilibration_time(double x, double sigma0) {
  return x > 1.0 ? k_equilibration_efolds / growth_rate(x, sigma0) : INFINITY;
}

/// Segments for one grid point: the smallest m with (m - 1) T2 + T1 >= equilibration_time, if
/// m <= max_segments; otherwise 1.
inline int segments_for(double x, double sigma0, const SweepProtocol& p) {
  const double t = equilibration_time(x, sigma0);
  if (!std::isfinite(t)) return 1;
  const double m = 1.0 + std::max(0.0, std::ceil((t - p.transient) / p.duration));
  return m <= p.max_segments ? static_cast<int>(m) : 1;
}

/// Zero of the weighted line through (x, R^2 - R0^2) over the points with use[k]; the weights
/// 1 / (2 R_w dR_w)^2 come from (R_w, dR_w), so theory and simulation share them. NaN with fewer
/// than 3 points.
inline Onset extrapolated_onset(const std::vector<double>& x, const std::vector<double>& R,
                                double R0, const std::vector<double>& R_w,
                                const std::vector<double>& R_err_w,
                                const std::vector<double>& use) {
  double S = 0, Sx = 0, Sy = 0, Sxx = 0, Sxy = 0;
  int points = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (use[k] == 0.0) continue;
    const double sigma = std::max(2.0 * R_w[k] * R_err_w[k], 1e-12);
    const double w = 1.0 / (sigma * sigma), E2 = R[k] * R[k] - R0 * R0;
    S += w, Sx += w * x[k], Sy += w * E2, Sxx += w * x[k] * x[k], Sxy += w * x[k] * E2;
    ++points;
  }
  Onset onset;
  if (points < 3) return onset;
  const double det = S * Sxx - Sx * Sx;
  const double slope = (S * Sxy - Sx * Sy) / det, intercept = (Sxx * Sy - Sx * Sxy) / det;
  const double var_a = Sxx / det, var_b = S / det, cov = -Sx / det;
  onset.x = -intercept / slope;
  onset.err = std::sqrt(std::max(var_a + onset.x * onset.x * var_b + 2.0 * onset.x * cov, 0.0)) /
              std::abs(slope);
  return onset;
}

/// One grid point from its segments [first, first + m): the mean over the qualifying segments
/// (the last one if none qualifies) of the replica means, and its error.
inline void reduce_point(OnsetCurve& c, const SimulationResult& r, std::size_t first, int m,
                         double t_eq, const SweepProtocol& p) {
  std::vector<std::size_t> used;
  for (int j = 0; j < m; ++j)
    if (j * p.duration + p.transient >= t_eq) used.push_back(first + static_cast<std::size_t>(j));
  c.equilibrated.push_back(used.empty() ? 0.0 : 1.0);
  if (used.empty()) used.push_back(first + static_cast<std::size_t>(m - 1));
  const std::size_t B = r.points[first].R_mean.size();
  const double n = static_cast<double>(used.size());
  std::vector<double> per_replica(B, 0.0);
  double sem2 = 0.0;
  for (const std::size_t i : used) {
    for (std::size_t b = 0; b < B; ++b) {
      per_replica[b] += r.points[i].R_mean[b] / n;
      sem2 += r.points[i].R_sem[b] * r.points[i].R_sem[b] / (n * n);
    }
  }
  // sem2 sums B replicas' SEM^2 of the segment mean: its rms over replicas.
  const double sem = std::sqrt(sem2 / static_cast<double>(B));
  const MeanSd m_sd = mean_sd(per_replica);
  c.R.push_back(m_sd.mean);
  c.R_err.push_back(std::max(m_sd.sd, sem) / std::sqrt(static_cast<double>(B)));
}

/// The theory curve on the grid: eq:rSigmaBesselMain above the threshold, 0 below.
inline void theory_curve(OnsetCurve& c, const Network& net, const PerronResult& perron) {
  const SelfConsistentSystem system(net, c.lambda, c.sigma0, 0.0, perron.u);
  std::vector<double> above;
  for (const double K : c.K)
    if (K > system.threshold()) above.push_back(K);
  const std::vector<SelfConsistentSolution> s = system.sweep(above, SelfConsistentOptions{});
  std::size_t j = 0;
  for (const double K : c.K) {
    const bool solved = K > system.threshold() && s[j].status == SolveStatus::converged;
    c.R_theory.push_back(K > system.threshold() ? (solved ? s[j].R : NAN) : 0.0);
    if (K > system.threshold()) ++j;
  }
}

/// The theory at the state the sweep actually reached at each of its K: the variance
/// mu0 = 2 E / N - (P / N)^2 of the run's own energy and momentum at that K (run_variance.hpp),
/// per replica, then the replica mean of eq:rSigmaBesselMain with that offset. The swept states
/// differ from the incoherent state of R_theory: each raise of K at a coherent state lowers H by
/// dK / (2N) sum A cos, so late in a sweep the system has less energy than a fresh start at the
/// same K (simulation_vs_theory.cpp); near onset the two coincide. Comparing <R> with both
/// separates that energy path from a lag of the dynamics.
inline void theory_at_sweep_state(OnsetCurve& c, const Network& net, const SimulationResult& r,
                                  std::size_t first_point) {
  const std::size_t B = r.points.front().R_mean.size();
  const double n = static_cast<double>(net.size());
  for (std::size_t k = first_point; k < c.x.size(); ++k) {
    const double K = c.K[k];
    if (!(K > 0.0)) {
      c.R_theory_ep.push_back(0.0);
      continue;
    }
    double sum = 0.0;
    for (std::size_t b = 0; b < B; ++b) {
      const double mu0 = incoherent_variance(r, K, b, n);
      const double c0 = (c.sigma0 * c.sigma0 - mu0) / K;  // mu0 = sigma0^2 - K c0
      const SelfConsistentSolution s = SelfConsistentSystem(net, c.lambda, c.sigma0, c0).solve(K);
      sum += s.status == SolveStatus::failed ? NAN : s.R;
    }
    c.R_theory_ep.push_back(sum / static_cast<double>(B));
  }
}

/// One sweep over the grid x (K = x K_c raised from 0, each K continuing the state): appends
/// the points' x, K, segments, <R>, error and equilibration flag to c (lambda, Kc, sigma0 set)
/// and adds the run's cost to c.cost.
inline void run_sweep(OnsetCurve& c, const DistributedNetwork& distributed, const Network& net,
                      const std::vector<double>& x, const SweepProtocol& protocol) {
  SimulationParameters p;
  const std::size_t first_point = c.x.size();
  for (const double v : x) {
    const int m = segments_for(v, c.sigma0, protocol);
    c.x.push_back(v);
    c.K.push_back(v * c.Kc);
    c.segments.push_back(m);
    p.K.insert(p.K.end(), static_cast<std::size_t>(m), v * c.Kc);
    if (protocol.pipeline_steps) {
      p.steps.insert(
          p.steps.end(), static_cast<std::size_t>(m),
          pipeline_step(v, c.sigma0, protocol.duration, protocol.transient, protocol.family));
    }
  }
  p.h = protocol.h;
  p.duration = protocol.duration;
  p.transient = protocol.transient;
  p.continue_state = true;
  p.replicas.clear();
  for (int b = 1; b <= protocol.replicas; ++b) {
    p.replicas.push_back(
        {protocol.omega, c.sigma0, protocol.seed_base + static_cast<std::uint64_t>(b)});
  }
  p.record_stride = 1000;
  const auto force = app::choose_force("auto", "float64", distributed);
  const SimulationResult r = simulate(distributed, net.degrees(), *force, p);
  c.cost += cost_of(p, r);
  std::size_t segment = 0;
  for (std::size_t k = first_point; k < c.x.size(); ++k) {
    const int m = static_cast<int>(c.segments[k]);
    reduce_point(c, r, segment, m, equilibration_time(c.x[k], c.sigma0), protocol);
    segment += static_cast<std::size_t>(m);
  }
  theory_at_sweep_state(c, net, r, first_point);
}

/// Points of the fit (equilibrated, excess in the window, theory finite) and both onsets.
inline void fit_onsets(OnsetCurve& c) {
  c.fitted.clear();
  c.points = 0;
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    const bool use =
        c.equilibrated[k] != 0.0 && in_window(excess(c.R[k], c.R0)) && std::isfinite(c.R_theory[k]);
    c.fitted.push_back(use ? 1.0 : 0.0);
    c.points += use ? 1 : 0;
  }
  const Onset sim = extrapolated_onset(c.x, c.R, c.R0, c.R, c.R_err, c.fitted);
  c.x_on = sim.x;
  c.x_on_err = sim.err;
  c.x_on_theory = extrapolated_onset(c.x, c.R_theory, 0.0, c.R, c.R_err, c.fitted).x;
  c.x_on_theory_ep = extrapolated_onset(c.x, c.R_theory_ep, 0.0, c.R, c.R_err, c.fitted).x;
}

/// The refinement of onset_grid.hpp: a second sweep from K = 0 over the refined prefix of the
/// grid (same seeds, so up to the first midpoint it repeats the first sweep exactly, which is
/// printed as a check), then the first sweep's points beyond it. Returns the merged curve.
inline OnsetCurve refined_sweep(const OnsetCurve& first, const DistributedNetwork& distributed,
                                const Network& net, const std::vector<double>& added,
                                const SweepProtocol& protocol) {
  OnsetCurve c;
  c.lambda = first.lambda, c.Kc = first.Kc, c.sigma0 = first.sigma0;
  c.cost = first.cost;
  run_sweep(c, distributed, net, refined_prefix(first.x, added), protocol);
  double repeat = 0.0;
  for (std::size_t k = 0; k < first.x.size() && first.x[k] < added.front(); ++k)
    repeat = std::max(repeat, std::abs(first.R[k] - c.R[k]));
  std::printf("  INFO  refined grid: %zu midpoints; the repeated prefix differs by %.3g\n",
              added.size(), repeat);
  c.prefix_repeat = repeat;
  const double last = c.x.back();
  for (std::size_t k = 0; k < first.x.size(); ++k) {
    if (first.x[k] <= last) continue;
    c.x.push_back(first.x[k]), c.K.push_back(first.K[k]);
    c.segments.push_back(first.segments[k]), c.equilibrated.push_back(first.equilibrated[k]);
    c.R.push_back(first.R[k]), c.R_err.push_back(first.R_err[k]);
    c.R_theory_ep.push_back(first.R_theory_ep[k]);
  }
  return c;
}

/// Steps 1-3 for one network: lambda, the simulated sweep (refined once if the window holds
/// fewer than k_minimum_fit_points points, onset_grid.hpp), the theory curve, both onsets.
inline OnsetCurve measure_onset(const Network& net, double sigma0, const SweepProtocol& protocol) {
  OnsetCurve c;
  const DistributedNetwork distributed(net);
  const PerronResult perron = perron_eigenpair(distributed);
  c.lambda = perron.lambda;
  c.sigma0 = sigma0;
  c.Kc = 2.0 * sigma0 * sigma0 * static_cast<double>(net.size()) / c.lambda;
  run_sweep(c, distributed, net, protocol.x, protocol);
  c.R0 = c.R.front();
  theory_curve(c, net, perron);
  fit_onsets(c);
  if (c.points >= k_minimum_fit_points) return c;
  std::vector<double> E;
  for (const double R : c.R) E.push_back(excess(R, c.R0));
  const std::vector<double> added = refinement_points(c.x, E);
  if (added.empty()) return c;
  OnsetCurve refined = refined_sweep(c, distributed, net, added, protocol);
  refined.R0 = refined.R.front();
  theory_curve(refined, net, perron);
  fit_onsets(refined);
  return refined;
}

/// Columns of a figure array: the longest grid (refined grids are longer).
inline std::size_t grid_columns(const std::vector<OnsetCurve>& curves) {
  std::size_t cols = 0;
  for (const OnsetCurve& c : curves) cols = std::max(cols, c.x.size());
  return cols;
}

/// Rows of a figure array: one per curve, padded with NaN to grid_columns.
inline std::vector<double> stack(const std::vector<OnsetCurve>& curves,
                                 std::vector<double> OnsetCurve::*member) {
  const std::size_t cols = grid_columns(curves);
  std::vector<double> out;
  for (const OnsetCurve& c : curves) {
    out.insert(out.end(), (c.*member).begin(), (c.*member).end());
    out.insert(out.end(), cols - (c.*member).size(), NAN);
  }
  return out;
}

}  // namespace hmfnet::verification
