// Verification: simulated <R>_t against the self-consistent synchronized state (Fig.
// R_vs_K_theoretical, eq:rSigmaBesselMain) and its near-onset form (eq:globalOrderRInDeltaK).
//
// Claim: "The theory agrees with the simulations, except that when K < K_c the observed order
//   parameter R is not zero [...] because of finite-size effects" for (a) ER, q = 0.01,
//   sigma0^2 = 0.12 and (b) scale-free, sigma0^2 = 1, N = 10^4, ||d|| = 100. Panel (b) uses
//   alpha = 2.8 (Table II); the caption says alpha = 2.5, d_min = 33 (recorded as a note).
// Run:   verification_simulation_vs_theory [--scale ci|full]   (ctest -L verification)
//        ci: N = 2000 with ||d|| = 100 (the same degree, so the same finite-size floor), K/K_c in
//        {0.5, 2, 3, 4}, per K T2 = 600, T1 = 300, h = 0.02 (h omega_max <= 0.15 here), 2
//        replicas; full: N = 10^4, the same K, the paper's T2 = 1000, T1 = 500, 4 replicas
//        (header: Tolerance per point), and per K the
//        method of support/pipeline_step.hpp (the work-precision choice; ER: leap-frog h = 0.32
//        at K_c / 2, blanes_moan 0.16 at 2-3 K_c, 0.08 at 4 K_c; SF, sigma0 = 1: leap-frog 0.08,
//        0.04 at 4 K_c) instead of the paper's leap-frog
//        h = 0.01.
//        The sweep (Fig. R_vs_K_theoretical as the paper shows it): 17 K/K_c from 0
//        to 4.5, each continuing from the state the previous one left (the paper's protocol),
//        the same replicas, per K the pipeline's method; T2 = 1000, T1 = 500 per K at full
//        scale, T2 = 80, T1 = 40 at CI scale. At full scale its points at K/K_c >= 2 are
//        checked as the restart-each-K points (below), at the E and P each K's segment
//        conserves; at CI scale they are reported. Checked at both scales: each replica's
//        <R>_t rises with every step of K above onset (by > 3 batch-means SEM of the
//        difference), and each K starts where the previous one ended (not from the floor).
// Protocol: the four points start each K from the incoherent state. The theory is a
//   function of the conserved E and P of the start (eq:Hsub0, eq:sigmaSqEq); raising K at a fixed
//   synchronized state changes E by (K2 - K1) U / K1 < 0, so a swept state has less energy than
//   the theory's fresh start and sits above the paper's line (measured, N = 2000, T = 120 per K:
//   0.619 against 0.542 at 4 K_c). Both are handled by the reference below.
// Reference: eq:rSigmaBesselMain on the same network with mu0 = sigma0^2 + 2 U0 / N = 2E/N -
//   (P/N)^2 from each replica's own conserved E and P, so the comparison is free of the
//   O(sqrt(2/N)) sample error of sigma0^2 (3% at N = 2000, which moves K_c by as much). The
//   paper's line (nominal sigma0, U0 = 0) is reported beside it and drawn.
// Where: the checks are at K/K_c >= 2. Nearer onset the relaxation time grows like
//   1/(K/K_c - 1) and the finite-size floor (~1/sqrt(||d||) = 0.1) is comparable to R itself.
//   Even at 3 K_c the approach to the stationary value is slow (the HMF model's long-lived
//   quasi-stationary states): ER N = 2000, <R>_t over [60, 120] 0.471, [200, 400] 0.496,
//   [400, 800] 0.500 against 0.513. So at CI scale the per-point agreement is reported, and
//   what is checked is the direction of the relaxation: <R> over the second half of [T1, T2]
//   is not above the theory (+ tolerance) and, unless already within the tolerance, not farther
//   below it than over the first half (+ 2 sqrt(2) SEM, the noise of the difference of two
//   half-window means). At full scale (the paper's T) the agreement itself is checked, and
//   fails for ER at 2 and 3 K_c (reported, not tuned). That too is the lag: the same scene run
//   to T = 4000 (docs/scripts/er_long_window.sh) closes the gap at 2 K_c from -0.022
//   over [500, 1000] to -0.013, -0.009 and -0.007 over [1000, 2000], [2000, 3000] and
//   [3000, 4000] (se <= 0.002), and at 3 K_c from -0.010 to -0.003; the paper's T is too short
//   for N = 10^4 at these K. The sweep, which reaches each K from a synchronized state, does not
//   lag: at full scale (paper/full/beyond/) all its K >= 2 K_c points pass on ER and
//   SF (|diff| <= 0.0076), while the restart points fail again at ER 2 and 3 K_c and, at the
//   edge, SF 3 K_c (diff -0.0097 against a tolerance of 0.0096).
// Tolerance per point: |<R>_sim - R_theory| <= 3 se + delta_fs. se: the standard error of the
//   replica-mean gap, the larger of the batch-means SEM of <R>_t (20 batches, combined over
//   replicas) and the replica sd of each replica's own gap <R>_t - R_theory over sqrt(B). The SEM
//   alone is not enough: at full scale with 2 replicas (an earlier run, ER 2 K_c) the replica sd of
//   <R>_t was 0.0060 against an SEM of 0.0005, i.e. the 20 batches of one trajectory are not
//   independent while the state still relaxes; hence 4 replicas at full scale. delta_fs = sqrt(R^2
//   + R_floor^2) - R: the incoherent part of each local field (variance <= d/N^2 per node, 1 - v^2
//   per neighbour in the synchronized state against 1 below onset) adds to the coherent part in
//   quadrature, so the finite-size level measured below onset, R_floor = <R>_t at K = K_c/2, bounds
//   it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/pipeline_step.hpp"
#include "support/run_variance.hpp"
#include "support/sample_statistics.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/onset_amplitude.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;
using verification::ClaimCheck;

namespace {

struct Scale {
  NodeIndex n;
  std::vector<double> K_over_Kc;
  double duration, transient, h;
  int replicas;
  bool pipeline_steps;  ///< per K support/pipeline_step.hpp instead of leap-frog with h
  /// The paper's sweep (continue from the current state), always with the pipeline's steps.
  std::vector<double> sweep;
  double sweep_duration, sweep_transient;
};

struct Panel {
  std::string name;
  Network net;
  double sigma0;
  verification::SceneFamily family;  ///< the work-precision scene it resembles (pipeline_step)
};

struct PointStats {
  std::vector<double> mean, sem, sd;  ///< <R>_t over replicas: mean, combined SEM, replica sd
  /// Standard error of the replica-mean gap <R>_t - theory: the larger of the combined SEM and
  /// the replica sd of each replica's own gap over sqrt(B) (header: Tolerance per point).
  std::vector<double> se;
  std::vector<double> theory;   ///< eq:rSigmaBesselMain at each replica's E and P
  std::vector<double> nominal;  ///< eq:rSigmaBesselMain at sigma0, U0 = 0 (paper's line)
  bool converged = true;
};

PointStats point_statistics(const Panel& panel, const PerronResult& perron,
                            const SimulationParameters& p, const SimulationResult& sim) {
  const std::size_t B = p.replicas.size(), nk = p.K.size();
  const double n = static_cast<double>(panel.net.size());
  PointStats st{std::vector<double>(nk, 0.0),
                std::vector<double>(nk, 0.0),
                std::vector<double>(nk, 0.0),
                std::vector<double>(nk, 0.0),
                std::vector<double>(nk, 0.0),
                {},
                true};
  for (std::size_t k = 0; k < nk; ++k) {
    std::vector<double> gap(B);
    for (std::size_t b = 0; b < B; ++b) {
      st.mean[k] += sim.points[k].R_mean[b] / static_cast<double>(B);
      st.sem[k] += sim.points[k].R_sem[b] * sim.points[k].R_sem[b];
      gap[b] = sim.points[k].R_mean[b];
      if (p.K[k] == 0.0) continue;  // uncoupled: the theory's R is 0 (no solve at K = 0)
      const double mu0 = verification::incoherent_variance(sim, p.K[k], b, n);
      // mu0 = sigma0^2 - K c0 (self_consistent.hpp); late in a sweep mu0 can reach 0 or below.
      const double c0 = (panel.sigma0 * panel.sigma0 - mu0) / p.K[k];
      const SelfConsistentSystem system(panel.net, perron.lambda, panel.sigma0, c0, perron.u);
      const SelfConsistentSolution sol = system.solve(p.K[k]);
      st.converged = st.converged && sol.status != SolveStatus::failed;
      st.theory[k] += sol.R / static_cast<double>(B);
      gap[b] -= sol.R;
    }
    st.sem[k] = std::sqrt(st.sem[k]) / static_cast<double>(B);
    for (std::size_t b = 0; b < B; ++b) {
      const double e = sim.points[k].R_mean[b] - st.mean[k];
      st.sd[k] += B > 1 ? e * e / static_cast<double>(B - 1) : 0.0;
    }
    st.sd[k] = std::sqrt(st.sd[k]);
    const verification::MeanSd g = verification::mean_sd(gap);
    st.se[k] = std::max(st.sem[k], g.sd / std::sqrt(static_cast<double>(B)));
  }
  const SelfConsistentSystem nominal(panel.net, perron.lambda, panel.sigma0, 0.0, perron.u);
  const auto first = std::find_if(p.K.begin(), p.K.end(), [](double K) { return K > 0.0; });
  st.nominal.assign(static_cast<std::size_t>(first - p.K.begin()), 0.0);
  for (const auto& sol : nominal.sweep(std::vector<double>(first, p.K.end()), {})) {
    st.converged = st.converged && sol.status != SolveStatus::failed;
    st.nominal.push_back(sol.R);
  }
  return st;
}

// <R> over the first and the second half of [T1, T2] at the k-th K, over replicas: the
// direction of the relaxation (see the header, "Where").
struct Halves {
  double early = 0.0, late = 0.0;
};

Halves half_means(const SimulationResult& sim, const SimulationParameters& p, std::size_t k) {
  const std::size_t B = p.replicas.size();
  const double step = step_at(p, k).h;  // this K's step (per-K steps at full scale)
  std::vector<double> R;                // replica-mean R of the records of this K inside [T1, T2]
  std::size_t j = 0;
  for (std::size_t i = 0; i < sim.series.K.size(); ++i) {
    if (sim.series.K[i] != p.K[k]) continue;
    const double t = static_cast<double>(++j * static_cast<std::size_t>(p.record_stride)) * step;
    if (t <= p.transient) continue;
    double mean = 0.0;
    for (std::size_t b = 0; b < B; ++b) mean += sim.series.R[i * B + b] / static_cast<double>(B);
    R.push_back(mean);
  }
  Halves h;
  const std::size_t m = R.size() / 2;
  for (std::size_t i = 0; i < R.size(); ++i) {
    (i < m ? h.early : h.late) += R[i] / static_cast<double>(i < m ? m : R.size() - m);
  }
  return h;
}

// K/K_c >= 2: against the theory at the run's own E and P (checked at full scale; at CI scale
// the direction of the relaxation is checked and the gap reported); 1 < K/K_c < 2: reported;
// the paper's line (nominal sigma0, U0 = 0) reported beside it.
void compare_point(ClaimCheck& check, const std::string& name, double x, const PointStats& st,
                   std::size_t k, double floor, const Halves& halves, bool sweep) {
  const double th = st.theory[k];
  const double tol = 3.0 * st.se[k] + std::sqrt(th * th + floor * floor) - th;
  std::printf(
      "  INFO  %s: K/K_c %-5g <R>_t %.4f, SEM %.4f, replica sd %.4f, se of the gap %.4f; theory "
      "at (E, P) %.4f, at sigma0 %.4f; tol %.4f\n",
      name.c_str(), x, st.mean[k], st.sem[k], st.sd[k], st.se[k], th, st.nominal[k], tol);
  const std::string what = name + ": <R>_t at K/K_c = " + ClaimCheck::format(x);
  if (x >= 2.0 && check.full()) {
    check.within_abs(what + " vs theory at the run's (E, P)", st.mean[k], th, tol,
                     "3 se + finite-size floor in quadrature");
  } else if (x >= 2.0 && sweep) {
    // T2 = 80, T1 = 40 per K: halves of 20 time units are too short to show a direction.
    check.report(what + " vs theory at the run's (E, P), CI scale", st.mean[k], th,
                 "(checked at full scale; tolerance there: " + ClaimCheck::format(tol) + ")");
  } else if (x >= 2.0) {
    check.report(what + " vs theory at the run's (E, P), CI scale", st.mean[k], th,
                 "(not relaxed by T2 at CI scale; checked at full scale; tolerance there: " +
                     ClaimCheck::format(tol) + ")");
    // sqrt(2) SEM: each half has half the samples.
    const double noise = 2.0 * std::sqrt(2.0) * st.sem[k];
    check.holds(what + ": relaxes toward the theory from below",
                halves.late <= th + tol &&
                    (th - halves.late <= tol || th - halves.late <= th - halves.early + noise),
                "theory " + ClaimCheck::format(th) + ", first half " +
                    ClaimCheck::format(halves.early) + ", second half " +
                    ClaimCheck::format(halves.late) + " (not above theory + tol " +
                    ClaimCheck::format(tol) +
                    "; within tol, or the gap not growing beyond "
                    "2 sqrt(2) SEM)");
  } else if (x > 1.0) {
    check.report(what + " vs theory at the run's (E, P)", st.mean[k], th,
                 "near onset: finite T lags the stationary state (critical slowing)");
  }
  if (x > 1.0) {
    check.report(what + " vs the paper's line (sigma0, U0 = 0)", st.mean[k], st.nominal[k],
                 "the paper's solid line; differs from ours by the sample's sigma0 and U0");
  }
}

// Above onset each replica's continued state has a larger <R>_t at every step of K. Per replica:
// the two points are one trajectory's consecutive windows, so their noise is each window's
// batch-means SEM (the replicas' spread includes where each trajectory happens to be, common to
// both). Restarted points rise too: check_sweep_continues is what tells a sweep apart.
void check_sweep_rises(ClaimCheck& check, const std::string& name, const std::vector<double>& x,
                       const SimulationResult& sim) {
  bool rises = true;
  double smallest = INFINITY;  // the smallest increment in units of its se
  for (std::size_t k = 1; k < x.size(); ++k) {
    if (x[k - 1] <= 1.0) continue;
    const PointResult &now = sim.points[k], &before = sim.points[k - 1];
    for (std::size_t b = 0; b < now.R_mean.size(); ++b) {
      const double step = now.R_mean[b] - before.R_mean[b];
      const double ratio = step / std::hypot(now.R_sem[b], before.R_sem[b]);
      rises = rises && ratio > 3.0;
      smallest = std::min(smallest, ratio);
    }
  }
  check.holds(name + ": every replica's <R>_t rises with K above onset", rises,
              "smallest increment " + ClaimCheck::format(smallest) + " se (> 3 required)");
}

// The paper's protocol: each K starts from the state the previous one left. Above onset a
// restart would begin at the incoherent floor; a continued state begins where the last one
// ended. Checked per replica: R at a segment's first record (record_stride steps in) is above
// the floor plus half of (R at the previous segment's last record - floor).
void check_sweep_continues(ClaimCheck& check, const std::string& name, const std::vector<double>& x,
                           const SimulationParameters& p, const SimulationResult& sim,
                           double floor) {
  const std::size_t B = p.replicas.size();
  const TimeSeries& ts = sim.series;
  bool continues = true;
  double lowest = INFINITY;  // (first - floor) / (previous last - floor)
  for (std::size_t i = 1; i < ts.K.size(); ++i) {
    if (ts.K[i] == ts.K[i - 1]) continue;  // i: the first record of a new segment
    const auto k =
        static_cast<std::size_t>(std::find(p.K.begin(), p.K.end(), ts.K[i - 1]) - p.K.begin());
    if (k >= x.size() || x[k] <= 1.0) continue;
    for (std::size_t b = 0; b < B; ++b) {
      const double ratio = (ts.R[i * B + b] - floor) / (ts.R[(i - 1) * B + b] - floor);
      continues = continues && ratio > 0.5;
      lowest = std::min(lowest, ratio);
    }
  }
  check.holds(name + ": each K continues from the state the previous one left", continues,
              "(R at a segment's first record - floor) / (R at the previous one's last - floor) "
              ">= " +
                  ClaimCheck::format(lowest) + " (> 0.5 required; a restart gives ~0)");
}

// One schedule on the panel's network: the restart-each-K points (continue_state = false, the
// theory's E and P are those of the fresh start) or the paper's sweep (continue_state = true:
// each K continues from the state the previous one left, header: Protocol).
SimulationParameters schedule(const Panel& panel, double Kc, const std::vector<double>& x,
                              const Scale& sc, bool sweep) {
  SimulationParameters p;
  p.h = sc.h;
  p.duration = sweep ? sc.sweep_duration : sc.duration;
  p.transient = sweep ? sc.sweep_transient : sc.transient;
  const bool per_k_steps = sweep || sc.pipeline_steps;
  for (const double k : x) {
    p.K.push_back(k * Kc);
    if (per_k_steps) {
      p.steps.push_back(
          verification::pipeline_step(k, panel.sigma0, p.duration, p.transient, panel.family));
    }
  }
  p.replicas.clear();
  for (int b = 0; b < sc.replicas; ++b) {
    p.replicas.push_back({6.0, panel.sigma0, static_cast<std::uint64_t>(100 + b)});
  }
  p.record_stride = 100;
  p.continue_state = sweep;
  // All K in one pass over the network (replica_lanes.hpp: the same bits); per-K steps and the
  // sweep need a pass each.
  p.K_across_replicas = !per_k_steps;
  return p;
}

// The figure's rows: K/K_c and the columns named in check_panel.
std::vector<double> point_rows(const std::vector<double>& x, const SimulationParameters& p,
                               const PointStats& st, double G) {
  std::vector<double> table;
  for (std::size_t k = 0; k < x.size(); ++k) {
    for (const double v : {x[k], p.K[k], st.mean[k], st.sem[k], st.sd[k], st.theory[k],
                           st.nominal[k], onset_order_parameter(G, x[k])}) {
      table.push_back(v);
    }
  }
  return table;
}

const std::vector<std::string> k_point_columns{
    "K/K_c", "K", "R", "SEM", "replica sd", "theory (E, P)", "theory (sigma0)", "G sqrt(dK/K_c)"};

// Step 3 for one panel: the restart-each-K points and the sweep, the theory per replica, the
// checks and the figure data.
void check_panel(ClaimCheck& check, const Panel& panel, const Scale& sc) {
  const DistributedNetwork d(panel.net);
  const PerronResult perron = perron_eigenpair(d);
  const double Kc = critical_coupling(panel.sigma0, panel.net.size(), perron.lambda);
  const double G = onset_amplitude(perron.lambda, mean_degree(panel.net), perron.u);
  const auto force = app::choose_force("auto", "float64", d);
  double floor = NAN;
  for (const bool sweep : {false, true}) {
    const std::vector<double>& x = sweep ? sc.sweep : sc.K_over_Kc;
    const std::string name = panel.name + (sweep ? " sweep" : "");
    const SimulationParameters p = schedule(panel, Kc, x, sc, sweep);
    const SimulationResult sim = simulate(d, panel.net.degrees(), *force, p);
    verification::account(check, p, sim);
    std::printf("  INFO  %s: lambda %.2f, K_c %.4g, G %.3f; %zu K, %.0f s of integration\n",
                name.c_str(), perron.lambda, Kc, G, x.size(), sim.integration_seconds);
    const PointStats st = point_statistics(panel, perron, p, sim);
    check.holds(name + ": every eq:rSigmaBesselMain solve converged", st.converged,
                "relative residual <= 1e-10");
    if (!sweep) {
      floor = st.mean[0];
      std::printf("  INFO  %s: finite-size floor <R>_t(K_c/2) = %.4f (1/sqrt(<d>) = %.4f)\n",
                  panel.name.c_str(), floor, 1.0 / std::sqrt(mean_degree(panel.net)));
    }
    for (std::size_t k = 0; k < x.size(); ++k) {
      compare_point(check, name, x[k], st, k, floor, half_means(sim, p, k), sweep);
    }
    if (sweep) {
      check_sweep_rises(check, name, x, sim);
      check_sweep_continues(check, name, x, p, sim, floor);
    }
    check.data(panel.name + (sweep ? "_sweep" : "_points"), point_rows(x, p, st, G), x.size(),
               k_point_columns);
  }
  // The theory curve on a fine grid (nominal sigma0, c0 = 0: the paper's solid line).
  std::vector<double> Ks, curve;
  for (int i = 0; i <= 80; ++i) Ks.push_back(Kc * (1.0 + 0.0005 + 3.5 * i / 80.0));
  const SelfConsistentSystem nominal(panel.net, perron.lambda, panel.sigma0, 0.0, perron.u);
  const auto sol = nominal.sweep(Ks, {});
  for (std::size_t i = 0; i < Ks.size(); ++i) {
    for (const double v : {Ks[i] / Kc, sol[i].R, onset_order_parameter(G, Ks[i] / Kc)}) {
      curve.push_back(v);
    }
  }
  check.data(panel.name + "_theory", curve, Ks.size(), {"K/K_c", "theory", "G sqrt(dK/K_c)"});
  check.data(panel.name + "_constants", {{"K_c", Kc},
                                         {"lambda", perron.lambda},
                                         {"G", G},
                                         {"sigma0", panel.sigma0},
                                         {"floor", floor}});
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("simulation_vs_theory",
                   "simulated <R>_t follows eq:rSigmaBesselMain above onset (Fig. "
                   "R_vs_K_theoretical)",
                   argc, argv);
  // Step 1: scale.
  // The sweep: 17 K from 0 to 4.5 K_c (Fig. R_vs_K_theoretical's range), denser near onset.
  const std::vector<double> sweep{0,   0.3, 0.6, 0.9, 1.1, 1.3, 1.5, 1.8, 2.1,
                                  2.4, 2.7, 3.0, 3.3, 3.6, 3.9, 4.2, 4.5};
  const Scale sc =
      check.full()
          ? Scale{10000, {0.5, 2, 3, 4}, 1000.0, 500.0, 0.01, 4, true, sweep, 1000.0, 500.0}
          : Scale{2000, {0.5, 2, 3, 4}, 600.0, 300.0, 0.02, 2, false, sweep, 80.0, 40.0};
  check.note("steps", verification::pipeline_step_note());
  check.note("alpha", "panel (b): alpha = 2.8 (Table II), caption says 2.5 with d_min = 33");
  // Step 2: the two networks, ||d|| = 100.
  const double q = erdos_renyi_probability(sc.n, 100.0);
  const double d_min = power_law_d_min_for_mean(2.8, 100.0);
  const std::vector<Panel> panels{
      {"ER", erdos_renyi({sc.n, q, 1}), std::sqrt(0.12), verification::SceneFamily::erdos_renyi},
      {"SF",
       chung_lu(power_law_targets(sc.n, {2.8, d_min, sc.n - 1.0}, 1), LinkProbability::capped, 1),
       1.0, verification::SceneFamily::scale_free}};
  // Step 3: simulate, solve, compare.
  for (const Panel& panel : panels) check_panel(check, panel, sc);
  return check.exit_code();
}
