// Anasazi's Perron pair against closed forms and Eigen's dense solver. Every test is collective:
// under `mpirun -np 2` (label mpi) each rank runs the same sequence.
#include <catch2/catch.hpp>
#include <cmath>

#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
PerronResult solve(const Network& net) {
  const DistributedNetwork d(net);
  return perron_eigenpair(d);
}
}  // namespace

TEST_CASE("Perron eigenvalue matches closed forms: star / K_ab / complete / d-regular",
          "[perron]") {
  struct Case {
    const char* name;
    Network net;
    double lambda;
  };
  const Case cases[] = {
      {"star N=401", test::star(401), 20.0},
      {"K_{9,16}", test::complete_bipartite(9, 16), 12.0},
      {"complete N=60", test::complete(60), 59.0},
      {"complete N=60 with self-loops", test::complete(60, true), 60.0},
      {"circulant 8-regular N=500", test::circulant(500, 4), 8.0},
  };
  for (const auto& c : cases) {
    const PerronResult r = solve(c.net);
    INFO(c.name << ": lambda " << r.lambda << " residual " << r.residual);
    REQUIRE_THAT(r.lambda, WithinRel(c.lambda, test::k_eigenvalue_rel));
    REQUIRE(r.residual < 1e-9);
    REQUIRE(r.nonnegative);
  }
}

TEST_CASE("Perron pair matches Eigen's dense solver [ER N=1500 / SF N=1500]", "[perron]") {
  const Network er = erdos_renyi({1500, 0.02, 4});
  const Network sf = chung_lu(power_law_targets(1500, {2.5, 10.0}, 4), LinkProbability::capped, 4);
  for (const Network* net : {&er, &sf}) {
    const PerronResult r = solve(*net);
    const test::DenseSpectrum dense = test::dense_spectrum(*net);
    INFO("lambda " << r.lambda << " dense " << dense.eigenvalues.back());
    REQUIRE_THAT(r.lambda, WithinRel(dense.eigenvalues.back(), test::k_eigenvalue_rel));
    REQUIRE(r.u.size() == dense.perron.size());
    double max_diff = 0.0;
    for (std::size_t k = 0; k < r.u.size(); ++k) {
      max_diff = std::max(max_diff, std::abs(r.u[k] - dense.perron[k]));
    }
    INFO("max |u - u_dense| = " << max_diff);
    REQUIRE(max_diff < test::k_eigenvector_abs);
  }
}

TEST_CASE("Perron vector is unit-norm and non-negative with the residual it reports", "[perron]") {
  const Network net = erdos_renyi({3000, 0.01, 8});
  const PerronResult r = solve(net);
  double norm2 = 0.0, worst = 0.0;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    norm2 += r.u[std::size_t(i)] * r.u[std::size_t(i)];
    double au = 0.0;
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k)
      au += r.u[std::size_t(net.col(k))];
    worst = std::max(worst, std::abs(au - r.lambda * r.u[std::size_t(i)]));
  }
  REQUIRE_THAT(norm2, WithinRel(1.0, 1e-12));
  REQUIRE(*std::min_element(r.u.begin(), r.u.end()) >= 0.0);
  INFO("max |Au - lambda u| = " << worst << ", reported relative residual " << r.residual);
  REQUIRE(worst / r.lambda <= r.residual * 1.0000001);  // max-norm <= 2-norm
  REQUIRE(r.residual < 1e-9);
}

TEST_CASE("Largest *real* eigenvalue on a bipartite network / not -lambda", "[perron]") {
  // Star: eigenvalues +-sqrt(N-1) tie in magnitude; "LR" must return the positive one.
  const PerronResult r = solve(test::star(101));
  REQUIRE_THAT(r.lambda, WithinRel(10.0, test::k_eigenvalue_rel));
  REQUIRE(r.nonnegative);
}

TEST_CASE("Disconnected network: lambda of the largest clique / u supported on it", "[perron]") {
  const PerronResult r = solve(test::two_cliques(5, 12));
  REQUIRE_THAT(r.lambda, WithinRel(11.0, test::k_eigenvalue_rel));
  for (int k = 0; k < 5; ++k) REQUIRE_THAT(r.u[std::size_t(k)], WithinAbs(0.0, 1e-8));
}

TEST_CASE("Weighted network: lambda scales with a uniform weight", "[perron]") {
  const Network unit = test::circulant(200, 3);
  std::vector<double> w(std::size_t(unit.nnz()), 2.5);
  const Network weighted = Network::from_csr(unit.size(), unit.row_ptr(), unit.cols(), w);
  REQUIRE_THAT(solve(weighted).lambda, WithinRel(15.0, test::k_eigenvalue_rel));
}
