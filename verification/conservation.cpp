// Verification: conservation laws of eq:hamiltonianNetworkCase under the paper's integrator.
//
// Claim: H and the total momentum P = sum_n p_n are conserved by the dynamics (A symmetric);
//   the second-order leap-frog with h = 0.01 (Sec. numericalExperiments) keeps the energy error
//   bounded (symplectic: no secular drift) and P to round-off.
// Run:   verification_conservation [--scale ci|full]   (ctest -L verification)
//        ci: ER N = 10^4, q = 0.01, sigma0 = 0.35, Omega = 6, K = 3 K_c, T = 100 (1e4 steps);
//        full: T = 2000.
// Reference: exact conservation.
// Tolerances: momentum drift <= 1e-12 of sum |p_n| (round-off: each step adds forces that sum to
//   zero up to ~nnz eps); energy: the error of a symplectic method oscillates at O(h^2) without
//   growing, so the largest error over the second half of the run may not exceed 2x that over
//   the first half (a drift linear in t would make it >= 3x), and it must stay below 1e-6 of H
//   (O(h^2 K R) / H with K R ~ 50 and H ~ 18 N: ~1e-7 measured).
#include <cmath>
#include <cstdio>

#include "app/force_choice.hpp"
#include "dynamics/simulation.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/work_account.hpp"
#include "theory/critical_coupling.hpp"

using namespace hmfnet;

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check(
      "conservation", "energy and momentum conservation (leap-frog, h = 0.01)", argc, argv);
  const bool full = check.full();
  int status = 0;
  {
    // Step 1: the paper's ER network and K = 3 K_c.
    const Network net = erdos_renyi({10000, 0.01, 1});
    const DistributedNetwork d(net);
    const double lambda = perron_eigenpair(d).lambda;
    const double Kc = critical_coupling(0.35, net.size(), lambda);
    // Step 2: two halves of one run: K, then the same K continued.
    SimulationParameters p;
    p.h = 0.01;
    p.duration = full ? 1000.0 : 50.0;
    p.transient = 0.0;
    p.K = {3.0 * Kc, 3.0 * Kc};
    p.replicas = {{6.0, 0.35, 1}};
    p.record_stride = 10;
    const auto force = app::choose_force("auto", "float64", d);
    const SimulationResult r = simulate(d, net.degrees(), *force, p);
    verification::account(check, p, r);
    // Step 3: energy relative to H at the start of the whole run, per half.
    const double e0 = r.series.energy.front();
    double first = 0.0, second = 0.0;
    const std::size_t half = r.series.energy.size() / 2;
    for (std::size_t k = 0; k < r.series.energy.size(); ++k) {
      const double err = std::abs(r.series.energy[k] - e0) / std::abs(e0);
      (k < half ? first : second) = std::max(k < half ? first : second, err);
    }
    std::printf(
        "  INFO  K = %.4g (3 K_c), %lld steps: max |dH|/H first half %.3e, second half %.3e\n",
        3.0 * Kc, static_cast<long long>(r.steps), first, second);
    check.holds(
        "energy error bounded (no drift)", second <= 2.0 * first,
        "second-half max / first-half max = " + verification::ClaimCheck::format(second / first));
    check.holds("energy error small", std::max(first, second) < 1e-6,
                verification::ClaimCheck::format(std::max(first, second)) + " < 1e-6");
    double drift = 0.0;
    for (const auto& pt : r.points) drift = std::max(drift, pt.momentum_drift[0]);
    check.holds("momentum conserved to round-off", drift <= 1e-12,
                "max |P(t) - P(0)| / sum |p| = " + verification::ClaimCheck::format(drift));
    status = check.exit_code();
  }
  return status;
}
