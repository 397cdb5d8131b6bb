// Verification: Fig. ERPLnet, the onset of synchrony lines up in lambda K.
//
// Claim: for ER networks of mean degree 100, 50, 30, 20, 10 and capped Chung-Lu scale-free
//   networks (alpha = 2.5, 2.8, 3.1, 3.5, 3.8, ||d|| = 100), <R>_t rises at the same lambda K,
//   i.e. K_c = 2 sigma0^2 N / lambda (eq:criticalKFirstOrder), and the curves nearly collapse
//   against lambda K (sigma0 = 0.35, Omega = 6).
// Run:   verification_onset_er_sf [--scale ci|full] [--output F.h5]   (ctest -L verification)
//        ci: N = 1000, segments of T2 = 100, T1 = 50, h = 0.05, 3 replicas, 1600 time units per
//        network (~90 s on one core); full: N = 10^4, T2 = 300, T1 = 150, 3 replicas,
//        the method per grid point of support/pipeline_step.hpp (leap-frog h = 0.32 / 0.16 up
//        to x = 1.5, blanes_moan 0.16 above; the work-precision choice) (the paper's T2 = 1000,
//        h = 0.01 on ten networks does not fit in 20 min on 2 cores). The
//        grid is given in x = K / K_c (support/onset_sweep.hpp), the same for every network, i.e.
//        a common grid in lambda K; K is raised from 0, each K continuing from the current state.
// Equilibration (support/onset_sweep.hpp): a segment at x > 1 counts only if the time already
//   spent at that K is >= 15 / gamma(x) (eq:gammaKKc; the measured approach time is 6-9 /
//   gamma); points near K_c get up to 4 repeated segments (ci, sigma0 = 0.35: x = 1.2 x4,
//   1.35 x3, 1.5 x2, 2 x2); x = 1.1 would need 6 and is shown but not fitted.
// Onset (support/onset_sweep.hpp): x_on = zero of the weighted line through (x, <R>^2 - R0^2)
//   over the equilibrated grid points with excess sqrt(<R>^2 - R0^2) in [0.1, 0.35], R0 = <R>_t
//   at K = 0 (the finite-size floor); the same fit (points, weights) on the self-consistent curve
//   of the same network (eq:rSigmaBesselMain) gives x_on(theory).
// Checks (support/onset_checks.hpp): per network, the onset is resolved (>= 3 equilibrated
//   points in the fit window, after at most one refinement of the grid by the rule of
//   support/onset_grid.hpp: at full scale ER <d> = 10, 20 and SF alpha 3.8 need it); x_on against 1
//   (eq:criticalKFirstOrder) and against x_on(theory) are reported (see "Not reproduced" below).
//   (b) lines up: within each family the range of x_on <= the range of x_on(theory) (the
//   collapse the theory itself predicts; G differs between networks) + 2 sqrt(2) max se (two
//   independent onsets differ by <= 2 sqrt(2) se at ~95%); se is the fit's standard error
//   (per-point error = larger of replica sd and batch-means SEM, over sqrt(B)).
//   (c) discriminating: the max/min ratio of K_on (ER) or ||d|| K_on (SF; ||d|| = 100 for all)
//   must exceed that of lambda K_on, i.e. lambda is the better scale; checked only where the
//   axes differ by more than the noise (scale factor ratio - 1 > 2 sqrt(2) max se), else
//   reported as not resolvable (the SF family at ci: lambda 128-143 at N = 1000).
// Step size (ci): h = 0.05 instead of 0.01. Measured on ER <d> = 100, N = 1000, T2 = 100, three
//   replicas, x = 0.9 ... 2: every difference of <R>_t between h = 0.05 and h = 0.01 is below
//   the per-point error (largest 0.013 against 0.016-0.03), mean difference -0.006 (about 0.03 in
//   x_on through the fit); with 8 replicas at x = 0, 1.2, 2: 0.000, -0.001, +0.009 against
//   errors 0.0008, 0.010, 0.009.
// Replicas: 3 at both scales. With 1 replica (the full preset until b4de98a) a point's error is
//   the batch-means SEM of one trajectory alone, and the fit se (0.002-0.012) missed most of the
//   run-to-run spread of x_on: the same networks and seeds run at h = 0.01 and at the steps of
//   support/pipeline_step.hpp moved x_on by -0.078 ... +0.070 over the 17 curves of the three
//   onset drivers (no common sign; rms 0.035, i.e. sd ~0.025 per run, ~5x the median se), and
//   check (b) failed for ER and SF here and in onset_sigma0. Replica 1 keeps its seed, so the
//   3-replica run contains the 1-replica trajectory; the pipeline steps pay for the other two.
// Not reproduced (ci), not a lag: even equilibrated (and with 600 time units per K, ER <d> = 50:
//   <R> 0.213, 0.30, 0.36 at x = 1.2, 1.35, 1.5 against theory 0.258, 0.321, 0.364) the
//   simulated excess near onset stays below eq:rSigmaBesselMain and rises nearly linearly in
//   R^2, while the theory's R^2 is concave there: the rule gives x_on ~ 1.0-1.13 but
//   x_on(theory) ~ 0.87-0.92, 0.1-0.25 apart (reported). At x >= 2 simulation and theory agree.
//   Likely the HMF quasi-stationary state near threshold (cf. simulation_vs_theory.cpp) and/or
//   finite N; not resolved at ci scale.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/parallel_session.hpp"
#include "support/claim_check.hpp"
#include "support/onset_checks.hpp"

using namespace hmfnet;
using verification::ClaimCheck;
using verification::OnsetCurve;

namespace {

constexpr double k_sigma0 = 0.35;

verification::SweepProtocol protocol(bool full) {
  verification::SweepProtocol p;
  p.x = {0.0, 0.5, 0.9, 1.1, 1.2, 1.35, 1.5, 2.0, 3.0};
  p.h = 0.05;               // ci (header: Step size)
  p.pipeline_steps = full;  // paper scale: support/pipeline_step.hpp
  p.duration = full ? 300.0 : 100.0;
  p.transient = full ? 150.0 : 50.0;
  p.replicas = 3;  // both scales: the replica spread is part of se (header: Replicas)
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("onset_er_sf",
                   "Fig. ERPLnet: onset of <R>_t at the same lambda K for ER and SF networks "
                   "(eq:criticalKFirstOrder)",
                   argc, argv);
  const bool full = check.full();
  const NodeIndex n = full ? 10000 : 1000;
  const verification::SweepProtocol p = protocol(full);
  verification::SweepProtocol p_sf = p;
  p_sf.family = verification::SceneFamily::scale_free;
  // Step 1: ER family (each network from its own seed).
  std::vector<OnsetCurve> er;
  const double degrees[] = {100, 50, 30, 20, 10};
  for (int i = 0; i < 5; ++i) {
    const Network net =
        erdos_renyi({n, erdos_renyi_probability(n, degrees[i]), static_cast<std::uint64_t>(i + 1)});
    er.push_back(verification::check_onset(check, "ER <d> " + ClaimCheck::format(degrees[i]), net,
                                           k_sigma0, p));
  }
  verification::check_lines_up(check, "ER", er, std::vector<double>(5, 1.0), "lambda K");
  verification::add_onset_figure_data(
      check, "er", er, R"(["<d> = 100", "<d> = 50", "<d> = 30", "<d> = 20", "<d> = 10"])");
  // Step 2: SF family (capped Chung-Lu, targets capped at N - 1 as in table2_scale_free).
  std::vector<OnsetCurve> sf;
  std::vector<double> mean_degrees;
  const double alphas[] = {2.5, 2.8, 3.1, 3.5, 3.8};
  for (int i = 0; i < 5; ++i) {
    const auto seed = static_cast<std::uint64_t>(i) + 1;
    const PowerLaw law{alphas[i], power_law_d_min_for_mean(alphas[i], 100.0),
                       static_cast<double>(n - 1)};
    const Network net = chung_lu(power_law_targets(n, law, seed), LinkProbability::capped, seed);
    mean_degrees.push_back(mean_degree(net));
    sf.push_back(verification::check_onset(check, "SF alpha " + ClaimCheck::format(alphas[i]), net,
                                           k_sigma0, p_sf));
  }
  verification::check_lines_up(check, "SF", sf, mean_degrees, "lambda K");
  verification::add_onset_figure_data(
      check, "sf", sf,
      R"(["alpha = 2.5", "alpha = 2.8", "alpha = 3.1", "alpha = 3.5", "alpha = 3.8"])");
  if (full) check.note("steps", verification::pipeline_step_note());
  check.note("protocol", "{\"sigma0\": 0.35, \"omega\": 6, \"N\": " + std::to_string(n) + "}");
  return check.exit_code();
}
