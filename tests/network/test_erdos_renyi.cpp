#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "network/erdos_renyi.hpp"
#include "support/bit_difference.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

namespace {
double pairs(NodeIndex n) { return 0.5 * n * (n - 1.0); }
}  // namespace

TEST_CASE("Erdos-Renyi output satisfies every CSR invariant [N=2000 / q=0.05]", "[erdos_renyi]") {
  const Network net = erdos_renyi({2000, 0.05, 11});
  REQUIRE(Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights()).empty());
  REQUIRE(net.self_loops() == 0);
  REQUIRE_FALSE(net.weighted());
}

TEST_CASE("Erdos-Renyi edge count is binomial within 4 sigma over seeds [N=3000]",
          "[erdos_renyi]") {
  for (const double q : {0.001, 0.01, 0.3}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const NodeIndex n = 3000;
      const Network net = erdos_renyi({n, q, seed});
      const double mean = pairs(n) * q, sd = std::sqrt(pairs(n) * q * (1 - q));
      INFO("q " << q << " seed " << seed << " edges " << net.edges() << " expected " << mean
                << " +- " << sd);
      REQUIRE(std::abs(static_cast<double>(net.edges()) - mean) < test::k_sigmas * sd);
    }
  }
}

TEST_CASE("Erdos-Renyi links pairs independently: degree variance is (N-1)q(1-q) [N=4000]",
          "[erdos_renyi]") {
  const NodeIndex n = 4000;
  const double q = 0.02;
  const Network net = erdos_renyi({n, q, 5});
  const auto d = net.degrees();
  double m = 0.0, v = 0.0;
  for (const double x : d) m += x;
  m /= n;
  for (const double x : d) v += (x - m) * (x - m);
  v /= n - 1;
  const double expected = (n - 1) * q * (1 - q);
  // The sample variance of N (weakly dependent) near-Poisson degrees has relative sd ~ sqrt(2/N).
  INFO("variance " << v << " expected " << expected);
  REQUIRE(std::abs(v / expected - 1.0) < test::k_sigmas * std::sqrt(2.0 / n));
}

TEST_CASE("Erdos-Renyi edge probability is uniform over the matrix: early and late pairs alike",
          "[erdos_renyi]") {
  // Geometric skipping errors show up as a bias between the first and last rows.
  const NodeIndex n = 4000;
  const double q = 0.05;
  const Network net = erdos_renyi({n, q, 9});
  double first = 0.0, last = 0.0;
  for (NodeIndex i = 0; i < 200; ++i)
    first += static_cast<double>(net.row_end(i) - net.row_begin(i));
  for (NodeIndex i = n - 200; i < n; ++i)
    last += static_cast<double>(net.row_end(i) - net.row_begin(i));
  const double mean = 200 * (n - 1) * q, sd = std::sqrt(200 * (n - 1) * q * (1 - q));
  INFO("first rows " << first << " last rows " << last << " expected " << mean);
  REQUIRE(std::abs(first - mean) < test::k_sigmas * sd);
  REQUIRE(std::abs(last - mean) < test::k_sigmas * sd);
}

TEST_CASE("Erdos-Renyi is reproducible and independent of the thread count", "[erdos_renyi]") {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Network one = erdos_renyi({5000, 0.01, 3});
  omp_set_num_threads(2);
  const Network two = erdos_renyi({5000, 0.01, 3});
  omp_set_num_threads(saved);
  REQUIRE(test::bit_difference(one.row_ptr(), two.row_ptr()) == "");
  REQUIRE(test::bit_difference(one.cols(), two.cols()) == "");
  const Network other = erdos_renyi({5000, 0.01, 4});
  REQUIRE(other.cols() != one.cols());
}

TEST_CASE("Erdos-Renyi limits: q = 0 gives no edges / q = 1 the complete graph", "[erdos_renyi]") {
  REQUIRE(erdos_renyi({50, 0.0, 1}).nnz() == 0);
  const Network full = erdos_renyi({50, 1.0, 1});
  REQUIRE(full.edges() == 50 * 49 / 2);
}

TEST_CASE("Erdos-Renyi parameters are range-checked", "[erdos_renyi]") {
  REQUIRE_THROWS_AS(erdos_renyi({100, 1.5, 1}), ParameterError);
  REQUIRE_THROWS_AS(erdos_renyi({0, 0.5, 1}), ParameterError);
  REQUIRE_THROWS_AS(erdos_renyi_probability(100, 100.0), ParameterError);
  REQUIRE(erdos_renyi_probability(10001, 100.0) == Approx(0.01));
}
