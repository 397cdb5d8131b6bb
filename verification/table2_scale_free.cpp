// Verification: Table II of the paper (tab:booktabs2), scale-free networks.
//
// Claims: (a) d_min = 33, 44, 52, 60, 64 gives ||d|| = 100 for alpha = 2.5, 2.8, 3.1, 3.5, 3.8
//   (eq:powerlaw, continuum mean d_min (alpha-1)/(alpha-2));
//   (b) lambda falls as alpha rises (paper: 299, 243, 201, 162, 140);
//   (c) the networks are disassortative, most strongly for the smallest alpha (paper: rho = 0.52,
//   0.81, 0.84, 0.93, 0.99), because Chung-Lu probabilities d_n d_m / sum d above 1 are capped;
//   (d) Fig. PLcorr: degree-preserving rewiring that raises rho raises lambda (paper: rho 0.78,
//   0.97, 1.09 with lambda 282, 364, 459).
// The paper's lambda and rho are one realisation each; we check that they lie inside the 3-sigma
// band of our ensemble (mean over seeds +- 3 sd sqrt(1 + 1/n)), which holds if our generator
// draws from the paper's ensemble. The generator is the variant docs/chung_lu_table2.md found
// closest (capped min(1, w w'/S), continuum d_min, targets capped at N-1); we never tune it to
// hit them. The bands are wide (rho fluctuates by +-0.05-0.1 between seeds at alpha <= 2.8).
// Rewiring: from our alpha = 2.5 networks the swaps saturate below the paper's rho = 0.97 and
// 1.09 (the hubs of degree ~N/2 fix whom most nodes link to), so (d) is checked with targets
// rho0 + 0.05 and rho0 + 0.10, reachable on every seed studied, and the paper's values reported.
// Run:   verification_table2_scale_free [--scale ci|full]   (ctest -L verification)
//        Seeds 1-3 (ci) or 1-10 (full); lambda and rho are reported as mean +- seed sd.
// Tolerance: (a) 0.5, the paper rounds d_min to integers; lambda, rho: the 3-sigma band above;
//   (b)-(d) are orderings, whose margins
//   (lambda differs by > 15% between neighbouring alpha) are far above realisation spread (~2%).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/rewiring.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/claim_check.hpp"
#include "support/sample_statistics.hpp"

using namespace hmfnet;

namespace {

using verification::mean_sd;
using verification::MeanSd;

double largest_eigenvalue(const Network& net) {
  const DistributedNetwork distributed(net);
  return perron_eigenpair(distributed).lambda;
}

std::string describe(const MeanSd& ours, double paper) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "ours %.4g +- %.2g (seed sd), paper %.4g: %+.1f%%, %.1f sd",
                ours.mean, ours.sd, paper, 100.0 * (ours.mean - paper) / paper,
                ours.sd > 0 ? (ours.mean - paper) / ours.sd : 0.0);
  return buffer;
}

// The paper's number is one realisation of (we assume) the same ensemble, so it should lie
// within 3 sd sqrt(1 + 1/n) of our mean over n seeds (sd: our seed-to-seed spread; the sqrt adds
// the error of our mean): a 3-sigma band, passed by 99.7% of realisations.
void check_one_realisation(verification::ClaimCheck& check, const std::string& what,
                           const MeanSd& ours, int seeds, double paper) {
  const double band = 3.0 * ours.sd * std::sqrt(1.0 + 1.0 / seeds);
  check.within_abs(what + " (mean of " + std::to_string(seeds) + " seeds) vs paper", ours.mean,
                   paper, band, "3 seed sd: the paper's value is one realisation");
}

void check_alpha_family(verification::ClaimCheck& check, int seeds) {
  const double alpha[] = {2.5, 2.8, 3.1, 3.5, 3.8};
  const double paper_dmin[] = {33, 44, 52, 60, 64};
  const double paper_lambda[] = {299, 243, 201, 162, 140};
  const double paper_rho[] = {0.52, 0.81, 0.84, 0.93, 0.99};
  std::vector<double> lambda, rho, rows;
  for (int k = 0; k < 5; ++k) {
    // Step 1: d_min for ||d|| = 100; Step 2: capped Chung-Lu over seeds; Step 3: lambda, rho.
    const double d_min = power_law_d_min_for_mean(alpha[k], 100.0);
    const std::string tag = "alpha " + verification::ClaimCheck::format(alpha[k]);
    check.holds(tag + " d_min", std::abs(d_min - paper_dmin[k]) <= 0.5,
                verification::ClaimCheck::format(d_min) + " vs printed " +
                    verification::ClaimCheck::format(paper_dmin[k]) + " (rounded to integers)");
    std::vector<double> l, r, d;
    for (int s = 1; s <= seeds; ++s) {
      const auto seed = static_cast<std::uint64_t>(s);
      const Network net = chung_lu(power_law_targets(10000, {alpha[k], d_min, 9999}, seed),
                                   LinkProbability::capped, seed);
      l.push_back(largest_eigenvalue(net));
      r.push_back(degree_correlation(net));
      d.push_back(mean_degree(net));
    }
    const MeanSd ml = mean_sd(l), mr = mean_sd(r), md = mean_sd(d);
    std::printf("  INFO  %s realised <d> %.1f; lambda %s; rho %s\n", tag.c_str(), md.mean,
                describe(ml, paper_lambda[k]).c_str(), describe(mr, paper_rho[k]).c_str());
    check_one_realisation(check, tag + " lambda", ml, seeds, paper_lambda[k]);
    check_one_realisation(check, tag + " rho", mr, seeds, paper_rho[k]);
    lambda.push_back(ml.mean);
    rho.push_back(mr.mean);
    rows.insert(rows.end(), {alpha[k], d_min, paper_dmin[k], md.mean, ml.mean, ml.sd,
                             paper_lambda[k], mr.mean, mr.sd, paper_rho[k]});
  }
  check.data("alpha_family", rows, 5,
             {"alpha", "d_min", "paper d_min", "realised mean degree", "lambda mean",
              "lambda seed sd", "paper lambda", "rho mean", "rho seed sd", "paper rho"});
  bool falling = true;
  for (std::size_t k = 1; k < lambda.size(); ++k) falling = falling && lambda[k] < lambda[k - 1];
  check.holds("lambda falls as alpha rises (seed means)", falling, "see the lambda lines above");
  check.holds("disassortative, most for alpha = 2.5 (seed means)", rho[0] < 0.8 && rho[0] < rho[4],
              "rho(2.5) = " + verification::ClaimCheck::format(rho[0]) +
                  ", rho(3.8) = " + verification::ClaimCheck::format(rho[4]));
}

void check_rewiring(verification::ClaimCheck& check, std::uint64_t seed) {
  const double d_min = 33.3;  // Table II, Fig. PLcorr row
  Network net =
      chung_lu(power_law_targets(10000, {2.5, d_min, 9999}, seed), LinkProbability::capped, seed);
  const double rho0 = degree_correlation(net);
  std::vector<double> lambda{largest_eigenvalue(net)};
  check.report("rewiring start: rho", rho0, 0.78, "(paper's initial network; one seed)");
  check.report("rewiring start: lambda", lambda[0], 282, "(one seed)");
  std::vector<double> rewired{rho0, lambda[0]};
  for (const double step : {0.05, 0.10}) {
    // Each network is rewired from the previous one, as the paper's sequence was.
    const RewiringResult r = rewire_to_correlation(net, {rho0 + step, seed + 1, 0});
    net = r.network;
    lambda.push_back(largest_eigenvalue(net));
    std::printf("  INFO  rewired to rho %.4f (%lld swaps): lambda %.2f\n", r.final_rho,
                static_cast<long long>(r.swaps), lambda.back());
    rewired.insert(rewired.end(), {r.final_rho, lambda.back()});
  }
  check.data("rewired", rewired, 3, {"rho", "lambda"});
  check.note("rewired_rows", "start, then rewired to rho0 + 0.05 and + 0.10");
  const double paper_rho[] = {0.97, 1.09}, paper_lambda[] = {364, 459};
  for (int k = 0; k < 2; ++k) {
    check.report("rewired network " + std::to_string(k + 1) + ": rho",
                 rewired[2 * static_cast<std::size_t>(k) + 2], paper_rho[k],
                 "(not reachable: swaps saturate, see header)");
    check.report("rewired network " + std::to_string(k + 1) + ": lambda",
                 rewired[2 * static_cast<std::size_t>(k) + 3], paper_lambda[k],
                 "(at our lower rho)");
  }
  std::printf(
      "  INFO  paper: rho 0.78, 0.97, 1.09 with lambda 282, 364, 459 (not reachable here)\n");
  check.holds("rewiring to higher rho raises lambda (Fig. PLcorr)",
              lambda[0] < lambda[1] && lambda[1] < lambda[2],
              verification::ClaimCheck::format(lambda[0]) + " < " +
                  verification::ClaimCheck::format(lambda[1]) + " < " +
                  verification::ClaimCheck::format(lambda[2]));
}

}  // namespace

int main(int argc, char** argv) {
  ParallelSession session(&argc, &argv);
  verification::ClaimCheck check(
      "table2_scale_free", "Table II: scale-free networks, and Fig. PLcorr rewiring", argc, argv);
  const bool full = check.full();
  check_alpha_family(check, full ? 10 : 3);
  check_rewiring(check, 1);
  return check.exit_code();
}
