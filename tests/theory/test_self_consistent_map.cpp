// The map of eq:rSigmaBesselMain in (r, eta) form (self_consistent_map.hpp).
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "network/erdos_renyi.hpp"
#include "theory/bessel_ratio.hpp"
#include "theory/self_consistent_map.hpp"

using namespace hmfnet;

namespace {

std::vector<double> random_r(NodeIndex n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> u(0.0, 0.02);
  std::vector<double> r(static_cast<std::size_t>(n));
  for (auto& x : r) x = u(engine);
  return r;
}

}  // namespace

TEST_CASE("The map is the right side of eq:rSigmaBesselMain with the index corrected [ER N=300]",
          "[theory]") {
  const Network net = erdos_renyi({300, 0.05, 3});
  const std::vector<double> r = random_r(300, 4);
  const double eta = 0.003, offset = 0.001;
  std::vector<double> r_out;
  double eta_out = 0.0;
  SelfConsistentMap(net, offset).apply(r, eta, r_out, eta_out);
  double energy = 0.0;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    double sum = 0.0;
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      sum += bessel_ratio(r[std::size_t(net.col(k))] / eta);
    }
    REQUIRE_THAT(r_out[std::size_t(i)], Catch::Matchers::WithinRel(sum / 300.0, 1e-14));
    // The variance line sums r_n v(r_n / eta): node n's own r (the erratum), not a neighbour's.
    energy += r[std::size_t(i)] * bessel_ratio(r[std::size_t(i)] / eta);
  }
  REQUIRE_THAT(eta_out, Catch::Matchers::WithinRel(offset + energy / 300.0, 1e-14));
}

TEST_CASE("The map gives bit-identical results on 1 and 2 threads [ER N=2000]", "[theory]") {
  const Network net = erdos_renyi({2000, 0.01, 5});
  const std::vector<double> r = random_r(2000, 6);
  const SelfConsistentMap map(net, 0.002);
  std::vector<double> one, two;
  double eta_one = 0.0, eta_two = 0.0;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  map.apply(r, 0.004, one, eta_one);
  omp_set_num_threads(2);
  map.apply(r, 0.004, two, eta_two);
  omp_set_num_threads(threads);
  REQUIRE(one == two);
  REQUIRE(eta_one == eta_two);
}

TEST_CASE("R = sum r_n / ||d|| (eq:globalOrderParam) [hand-made r]", "[theory]") {
  REQUIRE(global_order_parameter({0.1, 0.2, 0.3}, 2.0) == Approx(0.3));
  REQUIRE(solve_status_name(SolveStatus::incoherent) == "incoherent");
}
