// DistributedNetwork: the Tpetra matrix reproduces the serial CSR product on any rank count.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"

using namespace hmfnet;

TEST_CASE("Distributed A x equals the serial CSR product on every rank count [ER N=2000]",
          "[distributed]") {
  const Network net = erdos_renyi({2000, 0.01, 6});
  const DistributedNetwork d(net);
  REQUIRE(d.global_size() == net.size());
  REQUIRE(d.global_nnz() == net.nnz());
  REQUIRE(ParallelSession::sum(static_cast<double>(d.local_size())) == net.size());

  std::vector<double> x(std::size_t(net.size()));
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * double(i));
  const std::vector<double> x_local(x.begin() + d.first_row(),
                                    x.begin() + d.first_row() + d.local_size());
  std::vector<double> y_local;
  d.apply(x_local, y_local);
  const std::vector<double> y = d.gather(y_local);
  double worst = 0.0;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    double s = 0.0;
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) s += x[std::size_t(net.col(k))];
    worst = std::max(worst, std::abs(s - y[std::size_t(i)]));
  }
  INFO("ranks " << ParallelSession::ranks() << ", max |y - y_serial| = " << worst);
  // Same terms; only the summation order may differ: <= degree * eps * max|x| per row.
  REQUIRE(worst < 1e-12);
}

TEST_CASE("Gather assembles each rank's block exactly", "[distributed]") {
  const Network net = erdos_renyi({777, 0.02, 2});
  const DistributedNetwork d(net);
  std::vector<double> mine(std::size_t(d.local_size()));
  for (std::size_t r = 0; r < mine.size(); ++r) mine[r] = double(d.first_row()) + double(r) + 0.25;
  const auto all = d.gather(mine);
  for (std::size_t i = 0; i < all.size(); ++i) REQUIRE(all[i] == double(i) + 0.25);
}

TEST_CASE("K_N held implicitly has the stored graph's row blocks and no stored rows [N = 301]",
          "[distributed][complete]") {
  for (const bool loops : {false, true}) {
    const CompleteGraph graph = CompleteGraph::make(301, loops);
    const DistributedNetwork implicit(graph);
    const DistributedNetwork stored(graph.materialise());
    INFO("ranks " << ParallelSession::ranks() << ", self-loops " << loops);
    CHECK_FALSE(implicit.stores_rows());
    CHECK(stored.stores_rows());
    CHECK(implicit.global_size() == stored.global_size());
    CHECK(implicit.first_row() == stored.first_row());
    CHECK(implicit.local_size() == stored.local_size());
    CHECK(implicit.global_nnz() == stored.global_nnz());
    std::vector<double> x(static_cast<std::size_t>(implicit.local_size()), 1.0), y;
    CHECK_THROWS_WITH(implicit.apply(x, y), Catch::Matchers::Contains("held without stored rows"));
    CHECK_THROWS_AS(implicit.local_adjacency(), ParameterError);
    CHECK(implicit.gather(x).size() == 301);
  }
}
