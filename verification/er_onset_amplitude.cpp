// Verification: G of eq:globalOrderRInDeltaK for the Erdos-Renyi network of
// Fig. R_vs_K_theoretical(a).
//
// Claim: "We find G = 0.633 for the Erdos-Renyi network" (N = 10^4, q = 0.01, ||d|| = 100).
// Run:   verification_er_onset_amplitude [--scale ci|full]   (ctest -L verification)
// Reference: the paper's G = 0.633.
// Tolerance: 2%. For ER, G = sqrt(2/5) (lambda/||d||) (1 + O(1/||d||)): the Perron
//   vector follows the Poisson(100) degrees, whose relative spread 1/sqrt(||d||) = 0.1 enters the
//   moment ratio at second order (~1%); between realisations G varies by ~1e-4, which we measure
//   and print over 3 seeds. At full scale, 10 seeds.
#include <cmath>
#include <cstdio>

#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "theory/onset_amplitude.hpp"

using namespace hmfnet;

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check("er_onset_amplitude",
                                 "G = 0.633 for ER N = 10^4, q = 0.01 (eq:globalOrderRInDeltaK)",
                                 argc, argv);
  const int seeds = check.full() ? 10 : 3;
  double sum = 0.0, sum2 = 0.0;
  for (int s = 1; s <= seeds; ++s) {
    // Step 1: the paper's ER network; Step 2: lambda and u; Step 3: G from the moments of u.
    const Network net = erdos_renyi({10000, 0.01, static_cast<std::uint64_t>(s)});
    const DistributedNetwork distributed(net);
    const PerronResult perron = perron_eigenpair(distributed);
    const double G = onset_amplitude(perron.lambda, mean_degree(net), perron.u);
    sum += G;
    sum2 += G * G;
    check.within_rel("G seed " + std::to_string(s), G, 0.633, 0.02,
                     "O(1/||d||) corrections; paper prints 3 digits");
  }
  const double mean = sum / seeds;
  std::printf("  G over %d seeds: mean %.5f, sd %.2e; regular-graph value sqrt(2/5) = %.5f\n",
              seeds, mean, std::sqrt(std::max(0.0, sum2 / seeds - mean * mean)), std::sqrt(0.4));
  return check.exit_code();
}
