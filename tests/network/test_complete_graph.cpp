// K_N held in O(1): every closed form against the stored (materialised) graph, and its one-node
// quotient against eq:rSigmaBesselMain solved on the stored graph and against the all-to-all
// curve (theory/all_to_all.hpp), to round-off.
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "network/complete_graph.hpp"
#include "network/degree_statistics.hpp"
#include "network/structure.hpp"
#include "support/dense_spectrum.hpp"
#include "support/tolerances.hpp"
#include "theory/all_to_all.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// Both solves converge to a relative residual of 1e-13; near K/K_c = 1.2 the solution's relative
// error is about residual / (2 (K/K_c - 1)) = 2.5e-13 (self_consistent_map.hpp), so 1e-12.
constexpr double k_solve_tolerance = 1e-13;
constexpr double k_same_solution_rel = 1e-12;

}  // namespace

TEST_CASE("Complete graph closed forms equal the stored graph [N = 2, 3, 7, 300, loops or not]",
          "[network][complete]") {
  for (const NodeIndex n : {2, 3, 7, 300}) {
    for (const bool loops : {false, true}) {
      const CompleteGraph graph = CompleteGraph::make(n, loops);
      const Network stored = graph.materialise();
      INFO("N = " << n << ", self-loops " << loops);
      REQUIRE(stored.size() == n);
      CHECK(graph.nnz() == stored.nnz());
      CHECK(graph.edges() == stored.edges());
      CHECK((loops ? n : 0) == stored.self_loops());
      for (const double d : stored.degrees()) CHECK(d == graph.degree());
      CHECK(mean_degree(stored) == graph.degree());
      CHECK(degree_correlation(stored) == Approx(1.0).epsilon(test::k_eps * 16));
      CHECK(connected_components(stored).count == 1);
      CHECK(is_bipartite(stored) == graph.bipartite());
      const std::vector<double> eigenvalues = test::dense_spectrum(stored).eigenvalues;
      CHECK_THAT(eigenvalues.back(), WithinAbs(graph.lambda(), 1e-12 * graph.lambda()));
      CHECK_THAT(eigenvalues[eigenvalues.size() - 2], WithinAbs(graph.lambda2(), 1e-12 * n));
    }
  }
}

TEST_CASE("Complete graph refuses N outside 2..2^31-1, naming --n [bad input]",
          "[network][complete]") {
  for (const std::int64_t n : {std::int64_t{-1}, std::int64_t{0}, std::int64_t{1},
                               std::int64_t{std::numeric_limits<NodeIndex>::max()} + 1}) {
    INFO("N = " << n);
    CHECK_THROWS_WITH(CompleteGraph::make(n, false),
                      Contains("--n") && Contains("2 <= N <= 2147483647"));
  }
  const CompleteGraph largest = CompleteGraph::make(std::numeric_limits<NodeIndex>::max(), true);
  CHECK(largest.nnz() == std::int64_t{2147483647} * 2147483647);
  CHECK_THROWS_AS(largest.materialise(), ParameterError);
}

TEST_CASE(
    "Complete graph's one-node quotient solves eq:rSigmaBesselMain as the stored graph does "
    "[N = 300, Gaussian, 1.2 to 4 K_c]",
    "[network][complete][theory]") {
  const double sigma0 = 0.35;
  for (const bool loops : {false, true}) {
    const CompleteGraph graph = CompleteGraph::make(300, loops);
    const Network stored = graph.materialise();
    const Network quotient = graph.quotient();
    const double lambda_q = quotient.weights().front();
    INFO("self-loops " << loops);
    // The same K_c from K_N's N / lambda and from the quotient's 1 / weight.
    const double Kc = critical_coupling(sigma0, graph.n, graph.lambda());
    CHECK_THAT(critical_coupling(sigma0, 1, lambda_q), WithinRel(Kc, 4 * test::k_eps));

    SelfConsistentOptions options;
    options.tolerance = k_solve_tolerance;
    const std::vector<double> Ks = {1.2 * Kc, 1.5 * Kc, 2 * Kc, 4 * Kc};
    const SelfConsistentSystem full(stored, graph.lambda(), sigma0);
    const SelfConsistentSystem one(quotient, lambda_q, sigma0);
    const auto a = full.sweep(Ks, options);
    const auto b = one.sweep(Ks, options);
    for (std::size_t k = 0; k < Ks.size(); ++k) {
      INFO("K / K_c = " << Ks[k] / Kc);
      REQUIRE(a[k].status == SolveStatus::converged);
      REQUIRE(b[k].status == SolveStatus::converged);
      CHECK_THAT(b[k].R, WithinRel(a[k].R, k_same_solution_rel));
      CHECK_THAT(b[k].sigma2, WithinRel(a[k].sigma2, k_same_solution_rel));
      // Every d-regular graph sits on one curve R(K/K_c) (theory/all_to_all.hpp).
      CHECK_THAT(b[k].R, WithinRel(all_to_all_order_parameter(Ks[k] / Kc), k_same_solution_rel));
    }
    const LargeKLimit la = solve_large_k_limit(stored, options);
    const LargeKLimit lb = solve_large_k_limit(quotient, options);
    REQUIRE(lb.status == SolveStatus::converged);
    CHECK_THAT(lb.R_hat, WithinRel(la.R_hat, k_same_solution_rel));
    CHECK_THAT(degree_approximation_R_hat(quotient.degrees()),
               WithinRel(degree_approximation_R_hat(stored.degrees()), k_same_solution_rel));
  }
}
