// Random d-regular graphs: exact regularity and simplicity on both sides of d = (N - 1) / 2 (the
// pairing and its complement), seeds, the row-by-row source, bad parameters, and the short-cycle
// counts of the uniform model (a biased pairing changes them).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "network/edge_source.hpp"
#include "network/random_regular.hpp"
#include "support/bit_difference.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;

namespace {

// Triangles: per edge {u, v}, u < v, the common neighbours w > v (each triangle once).
std::int64_t triangles(const Network& net) {
  std::int64_t count = 0;
  for (NodeIndex u = 0; u < net.size(); ++u) {
    for (EdgeOffset e = net.row_begin(u); e < net.row_end(u); ++e) {
      const NodeIndex v = net.col(e);
      if (v <= u) continue;
      EdgeOffset a = e + 1, b = net.row_begin(v);
      while (a < net.row_end(u) && b < net.row_end(v)) {
        if (net.col(a) < net.col(b)) {
          ++a;
        } else if (net.col(b) < net.col(a)) {
          ++b;
        } else {
          ++count, ++a, ++b;
        }
      }
    }
  }
  return count;
}

}  // namespace

TEST_CASE("Random regular graphs are simple and exactly d-regular on both sides of (N - 1) / 2",
          "[network][random_regular]") {
  // {5, 2} and {6, 2}: cycles, where an early triangle is a dead end (the restart path).
  for (const auto& [n, d] : {std::pair{1, 0},
                             {10, 0},
                             {2, 1},
                             {5, 2},
                             {6, 2},
                             {50, 3},
                             {300, 20},
                             {101, 50},
                             {102, 61},
                             {60, 41},
                             {40, 39},
                             {1000, 7 * 2}}) {
    INFO("N = " << n << ", d = " << d);
    const Network net = random_regular({n, d, 5});
    REQUIRE(Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights()).empty());
    REQUIRE(net.size() == n);
    REQUIRE(net.self_loops() == 0);
    REQUIRE_FALSE(net.weighted());
    for (NodeIndex u = 0; u < n; ++u) REQUIRE(net.row_end(u) - net.row_begin(u) == d);
  }
}

TEST_CASE("Random regular graphs follow the seed and the row source gives the same network",
          "[network][random_regular]") {
  for (const NodeIndex d : {6, 70}) {  // the pairing, and the complement of a 29-regular graph
    const Network a = random_regular({100, d, 3});
    const Network b = random_regular({100, d, 3});
    const Network c = random_regular({100, d, 4});
    REQUIRE(test::bit_difference(a.cols(), b.cols()) == "");
    REQUIRE(a.cols() != c.cols());
    const Network from_rows = network_from_source(*random_regular_source({100, d, 3}));
    REQUIRE(test::bit_difference(from_rows.row_ptr(), a.row_ptr()) == "");
    REQUIRE(test::bit_difference(from_rows.cols(), a.cols()) == "");
  }
}

TEST_CASE("Random regular graphs refuse impossible parameters, naming them",
          "[network][random_regular]") {
  REQUIRE_THROWS_AS(random_regular({0, 0, 1}), ParameterError);
  REQUIRE_THROWS_WITH(random_regular({2'000'000'000, 0, 1}), Contains("1 <= n <= 20000000"));
  REQUIRE_THROWS_WITH(random_regular({11, 3, 1}), Contains("n d even"));
  REQUIRE_THROWS_WITH(random_regular({10, 10, 1}), Contains("0 <= d <= n - 1 = 9"));
  REQUIRE_THROWS_WITH(random_regular({10, -2, 1}), Contains("degree"));
  REQUIRE_THROWS_WITH(random_regular({2'000'000, 20, 1}), Contains("stored entries"));
  REQUIRE_THROWS_AS(random_regular_source({11, 3, 1}), ParameterError);
}

TEST_CASE("Random regular triangles are Poisson((d - 1)^3 / 6) as in the uniform model [N = 2000]",
          "[network][random_regular]") {
  // Short cycles of a uniform random d-regular graph are asymptotically independent Poisson with
  // mean (d - 1)^k / (2k) (Bollobas 1980; Wormald 1981); at N = 2000 the finite-N correction of
  // the triangle mean is O(d^2 / N) relative (<= 1.8% here). Over 200 graphs the mean's sd is
  // sqrt(mu / 200), so 4 sd is 28% of mu at d = 3 and 6% at d = 6: a pairing biased towards or
  // away from closing triangles by more than that fails.
  for (const NodeIndex d : {3, 6}) {
    const double mu = std::pow(d - 1.0, 3) / 6.0;
    const int graphs = 200;
    double sum = 0.0;
    for (int s = 0; s < graphs; ++s) {
      sum +=
          static_cast<double>(triangles(random_regular({2000, d, static_cast<std::uint64_t>(s)})));
    }
    const double mean = sum / graphs, se = std::sqrt(mu / graphs);
    INFO("d = " << d << ": mean triangles " << mean << ", uniform model " << mu << " +- " << se);
    REQUIRE(std::abs(mean - mu) < test::k_sigmas * se);
  }
}
