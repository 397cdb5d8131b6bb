// Measurement: the gap between simulation and the self-consistent theory (eq:rSigmaBesselMain) on
// networks that break the theory's assumptions, beside an ER control (where each method
// fails; the paper tests only ER and scale-free networks).
//
// What breaks: the onset analysis (Sec. approxOnsetSynchrony, eq:criticalKFirstOrder) assumes a
//   simple, isolated Perron eigenvalue with a positive eigenvector; the self-consistent state
//   assumes every rotor sees a local field summed over many neighbours (Assumptions 1-3).
//   - two weakly linked communities (two-block SBM, p_out = p_in / 25): lambda_2 / lambda ~ 0.93,
//     a second mode goes unstable at ~1.08 K_c;
//   - two disconnected communities (p_out = 0): A reducible, one threshold per community;
//   - a star: bipartite (-lambda is an eigenvalue), and each leaf has one neighbour, so its local
//     field is a single rotor, not an average.
// Claims checked: each of these is detected and reported by `hmfnet spectrum`'s summary
//   (analysis/network_summary.hpp: near-degenerate lambda, connected components, bipartite),
//   and the ER control is not flagged. The gaps are measured and reported, not judged: they are
//   what a user of the theory on such a network should expect.
// Protocol: as simulation_vs_theory.cpp: every K from the incoherent state, the theory at each
//   replica's own conserved E and P (support/run_variance.hpp). ci: N = 2000 (star 2000, SBMs
//   2 x 1000, ER ||d|| = 50; p_in = 50 / 1000), K/K_c = 1.5 and 3, T2 = 400, T1 = 200,
//   h = 0.02, 2 replicas; full: N = 10^4, ||d|| = 100, T2 = 1000, T1 = 500, h = 0.01.
// Reported per network and K: <R>_t (replica mean, SEM), the theory, their relative gap, and
//   the finite-size floor 1/sqrt(<d>) for scale (the star's is O(1)).
// Measured (ci): the gaps on the two-community networks equal the ER control's (-12 to -15% at
//   1.5 K_c, -2 to -4% at 3 K_c): with lambda per component (theory/self_consistent.cpp) the
//   theory is as good there as on ER, and what remains is the near-onset lag common to all
//   networks (onset_sweep.hpp). On the star the simulation is 18% *above* the theory at 1.5 K_c:
//   each leaf's local field is one rotor, R_leaf = 1/N exactly, so R = sum R_n / ||d|| >= 1/2
//   whatever the phases (||d|| ~ 2), while the theory's r_leaf = v(K r_hub / mu) / N < 1/N: the
//   order parameter itself is degenerate there.
// Run:   verification_theory_breaking_networks [--scale ci|full] [--output F.h5]
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "analysis/network_summary.hpp"
#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/run_variance.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;
using verification::ClaimCheck;

namespace {

constexpr double k_sigma0 = 0.35;
const double k_x[] = {1.5, 3.0};

struct Scale {
  NodeIndex n;
  double degree, duration, transient, h;
  int replicas;
};

struct Case {
  std::string name;
  Network net;
  std::string expected_warning;  ///< text the summary must contain; empty: no warning at all
};

Network star(NodeIndex n) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 1; i < n; ++i) e.emplace_back(0, i);
  return Network::from_undirected_edges(n, e);
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// Step 2: detection by the summary `hmfnet spectrum` prints.
PerronResult check_detection(ClaimCheck& check, const Case& c, const DistributedNetwork& d) {
  PerronOptions options;
  options.second_eigenvalue = true;
  PerronResult perron = perron_eigenpair(d, options);
  const NetworkSummary s = summarise(c.net, perron, k_sigma0);
  std::string all;
  for (const auto& w : s.warnings) all += (all.empty() ? "" : "; ") + w;
  const bool ok =
      c.expected_warning.empty() ? s.warnings.empty() : mentions(s.warnings, c.expected_warning);
  check.holds(c.name + ": detected and reported by the network summary", ok,
              (c.expected_warning.empty() ? "no warning expected"
                                          : "expects '" + c.expected_warning + "'") +
                  "; warnings: " + (all.empty() ? "none" : all));
  return perron;
}

// Step 3: the simulation and the theory at each replica's (E, P).
std::vector<double> measure_gap(ClaimCheck& check, const Case& c, const DistributedNetwork& d,
                                const PerronResult& perron, const Scale& sc) {
  const double Kc = critical_coupling(k_sigma0, c.net.size(), perron.lambda);
  SimulationParameters p;
  p.h = sc.h;
  p.duration = sc.duration;
  p.transient = sc.transient;
  for (const double x : k_x) p.K.push_back(x * Kc);
  p.replicas.clear();
  for (int b = 0; b < sc.replicas; ++b)
    p.replicas.push_back({6.0, k_sigma0, static_cast<std::uint64_t>(300 + b)});
  p.record_stride = 100;
  p.continue_state = false;
  p.K_across_replicas = true;  // both K in one pass (replica_lanes.hpp: the same bits)
  const auto force = app::choose_force("auto", "float64", d);
  const SimulationResult sim = simulate(d, c.net.degrees(), *force, p);
  verification::account(check, p, sim);
  const double n = static_cast<double>(c.net.size());
  const auto B = static_cast<std::size_t>(sc.replicas);
  std::vector<double> rows;
  for (std::size_t k = 0; k < p.K.size(); ++k) {
    double mean = 0.0, sem2 = 0.0, theory = 0.0;
    for (std::size_t b = 0; b < B; ++b) {
      const double mu0 = verification::incoherent_variance(sim, p.K[k], b, n);
      const double c0 = (k_sigma0 * k_sigma0 - mu0) / p.K[k];
      const SelfConsistentSystem system(c.net, perron.lambda, k_sigma0, c0, perron.u);
      const SelfConsistentSolution sol = system.solve(p.K[k]);
      theory += (sol.status == SolveStatus::failed ? NAN : sol.R) / static_cast<double>(B);
      mean += sim.points[k].R_mean[b] / static_cast<double>(B);
      sem2 += sim.points[k].R_sem[b] * sim.points[k].R_sem[b];
    }
    const double sem = std::sqrt(sem2) / static_cast<double>(B);
    const double floor = 1.0 / std::sqrt(mean_degree(c.net));
    std::printf("  INFO  %s: K/K_c %g: <R>_t %.4f +- %.4f, theory %.4f, floor 1/sqrt(<d>) %.3f\n",
                c.name.c_str(), k_x[k], mean, sem, theory, floor);
    check.report(c.name + ": <R>_t vs eq:rSigmaBesselMain at K/K_c = " + ClaimCheck::format(k_x[k]),
                 mean, theory,
                 "(SEM " + ClaimCheck::format(sem) +
                     ", finite-size floor 1/sqrt(<d>) = " + ClaimCheck::format(floor) + ")");
    rows.insert(rows.end(), {k_x[k], mean, sem, theory, floor});
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  ClaimCheck check("theory_breaking_networks",
                   "networks that break the theory's assumptions are flagged; the simulation-"
                   "theory gap on them is measured",
                   argc, argv);
  // Step 1: the networks.
  const bool full = check.full();
  const Scale sc =
      full ? Scale{10000, 100.0, 1000.0, 500.0, 0.01, 2} : Scale{2000, 50.0, 400.0, 200.0, 0.02, 2};
  const NodeIndex half = sc.n / 2;
  const double p_in = sc.degree / half;
  std::vector<Case> cases;
  cases.push_back(
      {"ER control", erdos_renyi({sc.n, erdos_renyi_probability(sc.n, sc.degree), 2}), ""});
  cases.push_back({"two communities (SBM p_out = p_in / 25)",
                   two_block_sbm({half, p_in, p_in / 25.0, 2}), "near-degenerate lambda"});
  cases.push_back({"two disconnected communities", two_block_sbm({half, p_in, 0.0, 2}),
                   "connected components"});
  cases.push_back({"star", star(sc.n), "bipartite"});
  std::vector<double> table;
  std::string labels = "[";
  for (const Case& c : cases) {
    const DistributedNetwork d(c.net);
    const PerronResult perron = check_detection(check, c, d);
    const std::vector<double> rows = measure_gap(check, c, d, perron, sc);
    table.insert(table.end(), rows.begin(), rows.end());
    labels += (labels.size() > 1 ? ", \"" : "\"") + c.name + "\"";
  }
  check.data("gaps", table, table.size() / 5,
             {"K/K_c", "<R>_t", "SEM", "theory at the runs' (E, P)", "1/sqrt(<d>)"});
  check.note("gaps_rows", "per network (in the order of `networks`) and K");
  check.note("networks", labels + "]");
  return check.exit_code();
}
