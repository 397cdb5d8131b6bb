#include <catch2/catch.hpp>
#include <cstddef>
#include <vector>

#include "core/random.hpp"
#include "network/erdos_renyi.hpp"
#include "network/network.hpp"
#include "network/sparse_product.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

namespace {

// The product written out against the dense matrix, summed over all N columns (zeros too), an
// order independent of the CSR storage.
std::vector<double> dense_product(const Network& net, const std::vector<double>& x) {
  const auto n = static_cast<std::size_t>(net.size());
  std::vector<double> a(n * n, 0.0), y(n, 0.0);
  for (NodeIndex i = 0; i < net.size(); ++i)
    for (EdgeOffset k = net.row_ptr()[static_cast<std::size_t>(i)];
         k < net.row_ptr()[static_cast<std::size_t>(i) + 1]; ++k) {
      const auto col = static_cast<std::size_t>(net.cols()[static_cast<std::size_t>(k)]);
      a[static_cast<std::size_t>(i) * n + col] = net.weight(k);
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) y[i] += a[i * n + j] * x[j];
  return y;
}

}  // namespace

TEST_CASE("A x on a hand-checked weighted path with a self-loop, and on its 0/1 pattern",
          "[sparse_product]") {
  // A = [[0 2 0] [2 0 3] [0 3 5]], x = (1, 10, 100).
  const Network weighted =
      Network::from_csr(3, {0, 1, 3, 5}, {1, 0, 2, 1, 2}, {2.0, 2.0, 3.0, 3.0, 5.0});
  std::vector<double> y;
  multiply(weighted, {1.0, 10.0, 100.0}, y);
  REQUIRE(y == std::vector<double>{20.0, 302.0, 530.0});
  const Network pattern = Network::from_csr(3, {0, 1, 3, 5}, {1, 0, 2, 1, 2});
  multiply(pattern, {1.0, 10.0, 100.0}, y);
  REQUIRE(y == std::vector<double>{10.0, 101.0, 110.0});
}

TEST_CASE("A x equals the dense product and, bit for bit, the row-view sum [ER N=300]",
          "[sparse_product]") {
  const Network net = erdos_renyi({300, 0.05, 11});
  Rng rng(12);
  std::vector<double> x(300);
  for (double& v : x) v = rng.uniform() - 0.5;
  std::vector<double> y;
  multiply(net, x, y);
  const std::vector<double> dense = dense_product(net, x);
  REQUIRE(y.size() == 300);
  for (NodeIndex i = 0; i < net.size(); ++i) {
    const auto u = static_cast<std::size_t>(i);
    double row_sum = 0.0;
    for (const auto [j, w] : net.row(i)) row_sum += w * x[static_cast<std::size_t>(j)];
    INFO("row " << i << ": sparse " << y[u] << ", dense " << dense[u]);
    REQUIRE(y[u] == row_sum);  // same terms in the same (storage) order
    // |x_j| <= 0.5 and ~15 terms a row: sums of order 1, so the relative bound is absolute here.
    REQUIRE_THAT(y[u], Catch::Matchers::WithinAbs(dense[u], test::k_sum_rel));
  }
}
