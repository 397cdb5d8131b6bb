#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/network_summary.hpp"
#include "network/erdos_renyi.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/distributed_network.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

namespace {
NetworkSummary summary_of(const Network& net, double sigma0 = 0.0) {
  const DistributedNetwork d(net);
  PerronOptions options;
  options.second_eigenvalue = true;  // as `hmfnet spectrum`
  return summarise(net, perron_eigenpair(d, options), sigma0);
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("Summary JSON has every key the CLI promises", "[summary]") {
  const auto j = nlohmann::json::parse(to_json(summary_of(erdos_renyi({500, 0.05, 1}), 0.35)));
  for (const char* key : {"n", "edges", "nnz", "self_loops", "mean_degree", "lambda",
                          "lambda_residual", "lambda2", "second_mode_ratio",
                          "eigenvector_error_bound", "rho", "G", "components", "bipartite", "Kc"}) {
    INFO(key);
    REQUIRE(j.contains(key));
  }
  REQUIRE(j["Kc"].get<double>() == Approx(2 * 0.35 * 0.35 * 500 / j["lambda"].get<double>()));
}

TEST_CASE("Summary reports a disconnected and a bipartite network as such", "[summary]") {
  const NetworkSummary two = summary_of(test::two_cliques(4, 7));
  REQUIRE(two.components == 2);
  REQUIRE(two.warnings.size() >= 1);
  const NetworkSummary star = summary_of(test::star(50));
  REQUIRE(star.bipartite);
  REQUIRE_FALSE(star.warnings.empty());
  const NetworkSummary ring = summary_of(test::circulant(101, 2));
  // A ring's spectrum is near-degenerate (lambda_2 = 2 cos(2 pi / 101) + 2 cos(4 pi / 101)
  // = 3.9807 against lambda = 4, a degenerate cosine pair): that and nothing else is reported.
  REQUIRE(ring.warnings.size() == 1);
  REQUIRE(mentions(ring.warnings, "near-degenerate lambda"));
  REQUIRE(ring.lambda2 ==
          Approx(2 * std::cos(2 * M_PI / 101) + 2 * std::cos(4 * M_PI / 101)).epsilon(1e-6));
  REQUIRE(ring.G == Approx(std::sqrt(0.4)).epsilon(1e-8));  // regular: G = sqrt(2/5)
}

TEST_CASE("Near-degenerate lambda of two weakly linked communities is detected and reported",
          "[summary]") {
  // Blocks of 300, p_in = 0.1, p_out = 0.003: lambda ~ 30.9, lambda_2 ~ 29.1 (ratio ~ 1.06).
  const Network sbm = two_block_sbm({300, 0.1, 0.003, 5});
  const NetworkSummary s = summary_of(sbm);
  const test::DenseSpectrum dense = test::dense_spectrum(sbm);
  const double lambda2 = dense.eigenvalues[dense.eigenvalues.size() - 2];
  INFO("lambda " << s.lambda << ", lambda_2 " << s.lambda2 << " (dense " << lambda2 << ")");
  CHECK(s.components == 1);
  CHECK(s.lambda2 == Approx(lambda2).epsilon(test::k_eigenvalue_rel));
  CHECK(s.second_mode_ratio < k_near_degenerate_ratio);
  CHECK(mentions(s.warnings, "near-degenerate lambda"));
  // Davis-Kahan: the computed Perron vector is within the reported bound of the dense one.
  const DistributedNetwork d(sbm);
  const std::vector<double> u = perron_eigenpair(d).u;
  // Chordal distance ||u - u_dense||_2 = 2 sin(theta / 2) <= sqrt(2) sin(theta) <= sqrt(2) x the
  // bound (both unit norm, sum > 0), plus the dense solver's own error (~N eps, 1e-12 here).
  double dist2 = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k)
    dist2 += (u[k] - dense.perron[k]) * (u[k] - dense.perron[k]);
  INFO("||u - u_dense|| " << std::sqrt(dist2) << ", bound " << s.eigenvector_error_bound);
  CHECK(std::sqrt(dist2) <= std::sqrt(2.0) * s.eigenvector_error_bound + 1e-12);

  // The same construction with strong links between the blocks is not near-degenerate.
  const NetworkSummary mixed = summary_of(two_block_sbm({300, 0.1, 0.08, 5}));
  INFO("mixed: lambda / lambda_2 " << mixed.second_mode_ratio);
  CHECK(mixed.second_mode_ratio > k_near_degenerate_ratio);
  CHECK_FALSE(mentions(mixed.warnings, "near-degenerate lambda"));
  CHECK(mixed.warnings.empty());
}

TEST_CASE("K_N's closed-form summary equals the stored graph's, field by field [N = 300]",
          "[summary][complete]") {
  using Catch::Matchers::WithinAbs;
  using Catch::Matchers::WithinRel;
  for (const bool loops : {false, true}) {
    const CompleteGraph graph = CompleteGraph::make(300, loops);
    const NetworkSummary a = summarise(graph, 0.35);
    const NetworkSummary b = summary_of(graph.materialise(), 0.35);
    INFO("self-loops " << loops);
    CHECK(a.n == b.n);
    CHECK(a.edges == b.edges);
    CHECK(a.nnz == b.nnz);
    CHECK(a.self_loops == b.self_loops);
    CHECK(a.weighted == b.weighted);
    CHECK(a.mean_degree == b.mean_degree);
    CHECK(a.max_degree == b.max_degree);
    CHECK_THAT(a.rho, WithinRel(b.rho, 1e-12));
    CHECK(a.components == b.components);
    CHECK(a.largest_component == b.largest_component);
    CHECK(a.bipartite == b.bipartite);
    // Anasazi's residual tolerance is 1e-10 relative; its lambda lands within 1e-12 here.
    CHECK_THAT(a.lambda, WithinRel(b.lambda, 1e-12));
    CHECK_THAT(a.G, WithinRel(b.G, 1e-12));
    CHECK_THAT(a.Kc, WithinRel(b.Kc, 1e-12));
    CHECK(a.warnings == b.warnings);
    // lambda_2 = 0 has multiplicity N - 1 with self-loops: Anasazi may report no second pair.
    if (std::isfinite(b.lambda2)) CHECK_THAT(a.lambda2, WithinAbs(b.lambda2, 1e-9 * b.lambda));
    // With self-loops lambda_2 = 0: no finite ratio (the JSON leaves it out, not null).
    CHECK(std::isfinite(a.second_mode_ratio) == !loops);
  }
}
