// Verification and measurement: speed against accuracy of the integrators (work-precision
// charts), on the scenes of the paper's figures.
//
// Claims: (a) the energy error of leap-frog falls as h^2 and that of the 4th-order symplectic
//   compositions (yoshida4, blanes_moan) as h^4 (symplectic methods conserve a modified
//   Hamiltonian H + O(h^p)); (b) for <R>_t, the quantity every figure plots, the integration error
//   of the paper's leap-frog h = 0.01 is far below the statistical error of a time average over the
//   paper's window (T2 - T1 = 500), so a cheaper step gives the same figure.
// Scenes: ER at K/K_c = 0.5, 1.5, 3 and scale-free (alpha 2.8, ||d|| = 100) at 3 K_c; sigma0 =
//   0.35, Omega = 6, replicas (seeds 1..B) in one pass. ci: N = 1000, ||d|| = 50, T = 20 with the
//   first 10 discarded, B = 4; full: N = 10^4, ||d|| = 100, T = 100, first 50 discarded, B = 2,
//   and the 4th-order methods from h = 0.02 (at h = 0.01 their energy error is at the round-off
//   floor, ~1e-12, and their <R> error far below the statistical floor: measured at ci scale). Cost
//   of full: T = 200, B = 4 and every step was measured at > 110 min on the 2-core machine (the
//   force evaluations of 4 integrators x 6 steps x 4 scenes at 10^6 stored entries); this scale
//   is ~1/8 of it and keeps the paper's N and degree.
// For every integrator and h in {0.01, 0.02, ..., 0.32} (and the reference): wall time and force
//   evaluations per unit of simulated time, the largest relative energy error, and <R>_t. A run
//   the blow-up guard stops (SimulationBlowUp) is recorded as unstable (NaN).
// Precision: leapfrog and yoshida4 also run with the float32 force kernel (--precision float32;
//   dynamics/network_force.hpp). They need the same force evaluations, so the choice below is
//   made among the float64 methods and the float32 kernel is reported at the chosen step: its
//   wall-time ratio (same run, same machine state) and whether its <R>_t error stays within half
//   the floor. Its energy error includes the float32 evaluation of U itself (~1e-7 |U| / H).
// Reference: yoshida4 at h = 0.005 from the same initial state. Measured: over the windows used
//   here the trajectories stay close (|<R>_h - <R>_ref| ~ 1e-5 << SEM at h = 0.01), so the
//   difference is the step's own error in <R>_t and is used as such.
// Choice: per scene, the cheapest (fewest force evaluations per unit time) method and h whose
//   |<R>_h - <R>_ref| is at most half the paper's floor, the SEM of <R>_t over the paper's
//   averaging window: SEM_ref sqrt(window / 500) (an error of half the floor adds 12% to the
//   error bar in quadrature).
// Energy error: max |H(t) - H(0)| over the run, relative to the energy in the co-moving frame
//   H - P^2/(2N) (H itself is dominated by the exactly conserved rotation N Omega^2 / 2).
// Run:   verification_work_precision [--scale ci|full] [--output F.h5]
// Tolerances: (a) fitted log-log slope of the energy error within 0.3 of the order, on the
//   scene of strongest coupling (ER 3 K_c), over the steps whose error is >= 1e-10: the
//   round-off floor of the co-moving energy error is ~1e-12 (measured: blanes_moan at h <= 0.02),
//   so a fitted point is at least 100x above it and the fit sees the order, not the floor.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "theory/critical_coupling.hpp"

using namespace hmfnet;

namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_paper_window = 500.0;  // T2 - T1 of Sec. numericalExperiments
constexpr double k_fit_floor = 1e-10;     // see the header: orders are fitted above it
// The float64 methods (indices 0-3: the choice is made among them by force evaluations) and
// the float32 kernel with the two symplectic candidates (4-5: same evaluations, cheaper each).
const char* const k_methods[] = {"leapfrog", "yoshida4",         "blanes_moan",
                                 "rk4",      "leapfrog/float32", "yoshida4/float32"};
constexpr int k_float64_methods = 4, k_all_methods = 6;

std::string integrator_of(const std::string& method) { return method.substr(0, method.find('/')); }
// The force's precision as app::choose_force names it (the CLI's --precision).
std::string precision_of(const std::string& method) {
  return method.find("/float32") == std::string::npos ? "float64" : "float32";
}
const double k_steps[] = {0.01, 0.02, 0.04, 0.08, 0.16, 0.32};

struct Scale {
  NodeIndex n;
  double mean_degree, duration, transient;
  int replicas;
  double smallest_high_order_step;  // 4th-order methods skip smaller h (see the header)
};

struct Measurement {
  double seconds_per_time = k_nan, evaluations_per_time = k_nan, energy_error = k_nan;
  double R = k_nan, sem = k_nan;
};

// Mean over replicas and the combined SEM of that mean (independent replicas).
Measurement measure(const DistributedNetwork& d, const Network& net, double K,
                    const std::string& method, double h, const Scale& s) {
  SimulationParameters p;
  p.h = h;
  p.duration = s.duration;
  p.transient = s.transient;
  p.K = {K};
  p.integrator = integrator_of(method);
  p.record_stride = 10;  // the first record gives H and P of the start
  p.replicas.clear();
  for (int b = 1; b <= s.replicas; ++b)
    p.replicas.push_back({6.0, 0.35, static_cast<std::uint64_t>(b)});
  // The sparse kernel by name, not "auto": the study compares its two precisions.
  const auto force = app::choose_force("sparse", precision_of(method), d);
  Measurement m;
  try {
    const SimulationResult r = simulate(d, net.degrees(), *force, p);
    const PointResult& pt = r.points.front();
    const double B = static_cast<double>(pt.R_mean.size());
    double mean = 0.0, var = 0.0, err = 0.0;
    for (std::size_t b = 0; b < pt.R_mean.size(); ++b) {
      mean += pt.R_mean[b] / B;
      var += pt.R_sem[b] * pt.R_sem[b] / (B * B);
      // H is dominated by the exactly conserved N Omega^2 / 2 of the mean rotation: measure the
      // error against the energy in the co-moving frame, H - P^2 / (2N) (both conserved).
      const double H = r.series.energy[b], P = r.series.momentum[b];
      const double comoving = H - P * P / (2.0 * static_cast<double>(net.size()));
      err = std::max(err, pt.energy_rel_error_max[b] * std::abs(H / comoving));
    }
    m = {r.integration_seconds / s.duration, static_cast<double>(r.force_evaluations) / s.duration,
         err, mean, std::sqrt(var)};
  } catch (const SimulationBlowUp&) {
    // Unstable at this h: the guard stopped it; recorded as NaN.
  }
  return m;
}

// Least-squares slope of log(y) against log(x) over the finite points.
double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!(y[k] > 0.0)) continue;
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, n += 1;
  }
  return n < 2 ? k_nan : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

struct Scene {
  std::string name;
  const Network* net;
  double K_over_Kc;
  bool fit_orders;
};

// The float32 kernel at the chosen method and step (when it has a float32 variant): its wall-time
// ratio to float64 in this run (same evaluations, so the ratio is the kernel's) and whether its
// <R>_t error still stays within half the floor.
void report_float32(verification::ClaimCheck& check, const std::string& scene,
                    const std::string& best, double best_h, double floor,
                    const std::vector<Measurement>& measured, const Measurement& ref) {
  for (int m = k_float64_methods; m < k_all_methods; ++m) {
    if (integrator_of(k_methods[m]) != best) continue;
    for (std::size_t j = 0; j < std::size(k_steps); ++j) {
      if (k_steps[j] != best_h) continue;
      const int m64 = best == "leapfrog" ? 0 : 1;
      const Measurement& x64 = measured[static_cast<std::size_t>(m64) * std::size(k_steps) + j];
      const Measurement& x32 = measured[static_cast<std::size_t>(m) * std::size(k_steps) + j];
      const double dR = std::abs(x32.R - ref.R);
      check.report(scene + ": float32 kernel at the chosen step, wall-time speed-up over float64",
                   x64.seconds_per_time / x32.seconds_per_time, 1.0,
                   "(|<R> - <R>_ref| = " + verification::ClaimCheck::format(dR) +
                       (dR <= 0.5 * floor ? " <= " : " > ") + "half the floor " +
                       verification::ClaimCheck::format(0.5 * floor) + ")");
    }
  }
}

void run_scene(verification::ClaimCheck& check, const Scene& scene, const Scale& s, int index) {
  const DistributedNetwork d(*scene.net);
  const double lambda = perron_eigenpair(d).lambda;
  const double K = scene.K_over_Kc * critical_coupling(0.35, scene.net->size(), lambda);
  const Measurement ref = measure(d, *scene.net, K, "yoshida4", 0.005, s);
  const double floor = ref.sem * std::sqrt((s.duration - s.transient) / k_paper_window);
  std::printf("  INFO  %s: K = %.4g; reference <R> = %.5f +- %.5f; paper-window floor %.2e\n",
              scene.name.c_str(), K, ref.R, ref.sem, floor);
  // Rows: method index, h, seconds/time, evaluations/time, energy error, |dR|, sigma_diff.
  std::vector<double> rows;
  Measurement paper;  // leap-frog h = 0.01, measured in the loop
  double best_cost = INFINITY, best_h = k_nan;
  std::string best = "none";
  std::vector<Measurement> measured(k_all_methods * std::size(k_steps));
  for (int m = 0; m < k_all_methods; ++m) {
    std::vector<double> hs, errors;
    for (std::size_t j = 0; j < std::size(k_steps); ++j) {
      const double h = k_steps[j];
      const bool high_order = integrator_of(k_methods[m]) != "leapfrog";
      if (high_order && h < s.smallest_high_order_step) continue;
      const Measurement x = measure(d, *scene.net, K, k_methods[m], h, s);
      measured[static_cast<std::size_t>(m) * std::size(k_steps) + j] = x;
      if (m == 0 && j == 0) paper = x;
      const double dR = std::abs(x.R - ref.R), sigma = std::hypot(x.sem, ref.sem);
      rows.insert(rows.end(), {static_cast<double>(m), h, x.seconds_per_time,
                               x.evaluations_per_time, x.energy_error, dR, sigma});
      if (x.energy_error >= k_fit_floor) hs.push_back(h), errors.push_back(x.energy_error);
      const bool adequate = dR <= 0.5 * floor;
      if (m < k_float64_methods && adequate && x.evaluations_per_time < best_cost) {
        best_cost = x.evaluations_per_time, best_h = h, best = k_methods[m];
      }
    }
    if (scene.fit_orders && m < 3) {  // float64 symplectic methods
      const double order = m == 0 ? 2.0 : 4.0;
      check.within_abs(scene.name + ": energy-error order of " + k_methods[m] + " (" +
                           std::to_string(hs.size()) + " steps fitted)",
                       hs.size() >= 2 ? log_slope(hs, errors) : k_nan, order, 0.3,
                       "modified Hamiltonian H + O(h^p); errors >= 1e-10 fitted");
    }
  }
  report_float32(check, scene.name, best, best_h, floor, measured, ref);
  check.data("scene" + std::to_string(index), rows, rows.size() / 7,
             {"method index", "h", "seconds per unit time", "force evaluations per unit time",
              "max relative energy error", "|<R>_h - <R>_ref|", "sigma_diff"});
  check.data("scene" + std::to_string(index) + "_reference",
             {{"K", K},
              {"<R>_ref", ref.R},
              {"SEM_ref", ref.sem},
              {"paper-window floor", floor},
              {"leap-frog h=0.01 seconds per unit time", paper.seconds_per_time},
              {"leap-frog h=0.01 evaluations per unit time", paper.evaluations_per_time},
              {"leap-frog h=0.01 energy error", paper.energy_error}});
  char note[256];
  std::snprintf(note, sizeof note,
                "{\"name\": \"%s\", \"K_over_Kc\": %g, \"choice\": \"%s\", \"h\": %g, "
                "\"evaluations_per_time\": %g}",
                scene.name.c_str(), scene.K_over_Kc, best.c_str(), best_h, best_cost);
  check.note("scene" + std::to_string(index), note);
  check.report(scene.name + ": speed-up of the chosen " + best +
                   " h = " + verification::ClaimCheck::format(best_h) +
                   " over leap-frog h = 0.01 (force "
                   "evaluations)",
               paper.evaluations_per_time / best_cost, 1.0, "(the paper's method = 1)");
  check.holds(scene.name + ": leap-frog h = 0.01 bias below the statistical resolution",
              std::abs(paper.R - ref.R) <= 2.0 * std::hypot(paper.sem, ref.sem),
              "|dR| = " + verification::ClaimCheck::format(std::abs(paper.R - ref.R)) +
                  " vs 2 sigma_diff = " +
                  verification::ClaimCheck::format(2.0 * std::hypot(paper.sem, ref.sem)));
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check(
      "work_precision",
      "integrator orders in the energy error; <R>_t integration error vs its statistical floor",
      argc, argv);
  const Scale s = check.full() ? Scale{10000, 100.0, 100.0, 50.0, 2, 0.02}
                               : Scale{1000, 50.0, 20.0, 10.0, 4, 0.01};
  const Network er = erdos_renyi({s.n, erdos_renyi_probability(s.n, s.mean_degree), 1});
  const Network sf = chung_lu(
      power_law_targets(
          s.n, {2.8, power_law_d_min_for_mean(2.8, s.mean_degree), static_cast<double>(s.n - 1)},
          1),
      LinkProbability::capped, 1);
  const Scene scenes[] = {{"ER 0.5 K_c", &er, 0.5, false},
                          {"ER 1.5 K_c", &er, 1.5, false},
                          {"ER 3 K_c", &er, 3.0, true},
                          {"SF alpha 2.8 3 K_c", &sf, 3.0, false}};
  std::string methods = "[";
  for (const char* m : k_methods)
    methods += std::string(methods.size() > 1 ? ", " : "") + "\"" + m + "\"";
  check.note("methods", methods + "]");
  for (int k = 0; k < 4; ++k) run_scene(check, scenes[k], s, k);
  return check.exit_code();
}
