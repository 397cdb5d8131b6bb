// Verification: G of eq:globalOrderRInDeltaK for the two networks of Fig. R_vs_K_theoretical.
//
// Claim: "We find G = 0.633 for the Erdos-Renyi network, larger than G = 0.354 for the scale-free
//   network, as we would expect" (N = 10^4, ||d|| = 100). Which scale-free network is unclear:
//   the figure caption says alpha = 2.5, d_min = 33; Table II assigns alpha = 2.8, d_min = 44 to
//   Fig. R_vs_K_theoretical(b). We compute both.
// Run:   verification_onset_amplitude_networks [--scale ci|full]   (ctest -L verification)
//        ci: ER seeds 1-2, SF seeds 1-3 per network and generator variant; full: 10, 10, 6.
// Reference: the paper's G = 0.633 (ER) and 0.354 (SF).
// Generator: capped Chung-Lu, targets <= N-1, continuum d_min (the variant that reproduces Table
//   II's lambda within 2%, docs/chung_lu_table2.md).
// Tolerances:
//   ER 2%: G = sqrt(2/5) (lambda/||d||) (1 + O(1/||d||)); seed sd ~2e-5 (er_onset_amplitude).
//   SF: measured over seeds 1-10, G = 0.325 +- 0.009 for alpha = 2.8 and 0.425 +- 0.014 for
//   alpha = 2.5: the paper's 0.354 is 3 sd above the first and 5 sd below the second, so neither
//   reproduces it within the seed spread. G of a scale-free network also depends on how the
//   Chung-Lu graph is drawn, which the paper leaves open: over four variants that all give
//   ||d|| ~ 85-98 (step 3; 6 seeds each) G spans 0.287-0.356 for alpha = 2.8, i.e. up to 11% from
//   our generator's value, and 0.385-0.43 for alpha = 2.5. We therefore check alpha = 2.8 (Table
//   II's assignment) at 15% = that 11% generator systematic + 2 sd of a 3-seed mean (3%), and
//   alpha = 2.5 (the caption's) is reported: it is 20% off, outside every variant. That the
//   paper's value is closer to alpha = 2.8 than to 2.5 is checked too, and the ordering
//   G_SF < G_ER for both alphas (margins > 30%).
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/sample_statistics.hpp"
#include "theory/onset_amplitude.hpp"

using namespace hmfnet;

namespace {

using verification::mean_sd;
using verification::MeanSd;

double onset_amplitude_of(const Network& net) {
  const DistributedNetwork distributed(net);
  const PerronResult perron = perron_eigenpair(distributed);
  return onset_amplitude(perron.lambda, mean_degree(net), perron.u);
}

struct Variant {
  const char* name;
  LinkProbability link;
  double cutoff;
};

MeanSd scale_free_G(double alpha, const Variant& v, int seeds) {
  const double d_min = power_law_d_min_for_mean(alpha, 100.0);
  std::vector<double> G;
  for (int s = 1; s <= seeds; ++s) {
    const auto seed = static_cast<std::uint64_t>(s);
    G.push_back(onset_amplitude_of(
        chung_lu(power_law_targets(10000, {alpha, d_min, v.cutoff}, seed), v.link, seed)));
  }
  return mean_sd(G);
}

std::string format(const MeanSd& m) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f +- %.4f", m.mean, m.sd);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check(
      "onset_amplitude_networks",
      "G = 0.633 (ER) > G = 0.354 (SF) for the networks of Fig. R_vs_K_theoretical "
      "(eq:globalOrderRInDeltaK)",
      argc, argv);
  const bool full = check.full();

  // Step 1: ER, q = 0.01.
  std::vector<double> er;
  for (int s = 1; s <= (full ? 10 : 2); ++s) {
    er.push_back(onset_amplitude_of(erdos_renyi({10000, 0.01, static_cast<std::uint64_t>(s)})));
  }
  const MeanSd G_er = mean_sd(er);
  std::printf("  INFO  ER q = 0.01: G = %s over %zu seeds\n", format(G_er).c_str(), er.size());
  check.within_rel("G (ER, seed mean)", G_er.mean, 0.633, 0.02, "O(1/||d||) corrections");

  // Step 2: SF with the generator that reproduces Table II, both candidate alphas.
  const double inf = std::numeric_limits<double>::infinity();
  const Variant reference{"capped, targets <= N-1", LinkProbability::capped, 9999.0};
  const int seeds = full ? 10 : 3;
  const MeanSd G_25 = scale_free_G(2.5, reference, seeds);
  const MeanSd G_28 = scale_free_G(2.8, reference, seeds);
  std::printf("  INFO  SF alpha 2.5 (caption): G = %s; alpha 2.8 (Table II): G = %s (%d seeds)\n",
              format(G_25).c_str(), format(G_28).c_str(), seeds);
  check.report("G (SF alpha 2.5, the caption's network)", G_25.mean, 0.354,
               "outside the generator-variant spread (step 3)");
  check.within_rel("G (SF alpha 2.8, Table II's network)", G_28.mean, 0.354, 0.15,
                   "Chung-Lu variant spread 11% + 2 seed sd; see the header");
  check.holds("the paper's 0.354 is nearer alpha 2.8 (Table II) than 2.5 (caption)",
              std::abs(G_28.mean - 0.354) < std::abs(G_25.mean - 0.354),
              "|" + verification::ClaimCheck::format(G_28.mean) + " - 0.354| < |" +
                  verification::ClaimCheck::format(G_25.mean) + " - 0.354|");
  check.holds("G_SF < G_ER for both alphas (heterogeneity flattens the onset)",
              G_25.mean < 0.7 * G_er.mean && G_28.mean < 0.7 * G_er.mean,
              verification::ClaimCheck::format(G_25.mean) + ", " +
                  verification::ClaimCheck::format(G_28.mean) + " < 0.7 * " +
                  verification::ClaimCheck::format(G_er.mean));

  // Step 3: how much G depends on the Chung-Lu variant (all give ||d|| ~ 85-98).
  const Variant variants[] = {reference,
                              {"capped, no target cap", LinkProbability::capped, inf},
                              {"Poisson link", LinkProbability::poisson, 9999.0},
                              {"odds link", LinkProbability::odds, 9999.0}};
  for (const double alpha : {2.5, 2.8}) {
    double lo = 1.0, hi = 0.0;
    for (const Variant& v : variants) {
      const MeanSd g = scale_free_G(alpha, v, full ? 6 : 3);
      lo = std::min(lo, g.mean);
      hi = std::max(hi, g.mean);
      std::printf("  INFO  alpha %.1f, %-22s: G = %s\n", alpha, v.name, format(g).c_str());
    }
    std::printf("  INFO  alpha %.1f: G over variants %.3f - %.3f; paper 0.354 %s\n", alpha, lo, hi,
                (0.354 >= lo && 0.354 <= hi) ? "inside" : "outside");
  }
  return check.exit_code();
}
