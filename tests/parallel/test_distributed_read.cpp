// Reading a network by row blocks over the ranks: equal to the replicated network on every rank
// count, and an error found by one rank (a corrupted entry in its block, an asymmetric pair
// across blocks) ends every rank with that one message. Run at 1, 2 and 3 ranks (label mpi).
#include <catch2/catch.hpp>
#include <cmath>

#include "io/network_hdf5.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_read.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/bit_difference.hpp"
#include "support/hdf5_corruption.hpp"
#include "support/shared_file.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::collective_message;
using hmfnet::test::SharedFile;

TEST_CASE(
    "A network read by row blocks equals the replicated one on every rank count "
    "[ER N=3000]",
    "[distributed][read]") {
  const Network net = erdos_renyi({3000, 0.01, 12});
  const SharedFile file("hmfnet_read_blocks");
  file.write(net, [] {});
  const DistributedInput input = read_distributed_input(file.path());
  // CHECK, not REQUIRE, before anything collective: a rank that left the test early would leave
  // the others waiting in the next collective.
  CHECK(input.network);
  CHECK_FALSE(input.complete.has_value());
  const DistributedNetwork& read = *input.network;
  const DistributedNetwork replicated(net);
  INFO("rank " << ParallelSession::rank() << " of " << ParallelSession::ranks());
  CHECK(read.first_row() == replicated.first_row());
  CHECK(read.local_size() == replicated.local_size());
  CHECK(read.global_nnz() == net.nnz());
  CHECK(read.global_self_loops() == net.self_loops());
  const auto& a = read.local_adjacency();
  const auto& b = replicated.local_adjacency();
  CHECK(test::bit_difference(a.row_ptr, b.row_ptr) == "");
  CHECK(a.cols.size() == b.cols.size());
  // The rows' global columns are the network's own, ascending.
  bool same = a.cols.size() == b.cols.size();
  for (NodeIndex r = 0; r < read.local_size(); ++r) {
    const RowView row = net.row(read.first_row() + r);
    auto k = static_cast<std::size_t>(a.row_ptr[std::size_t(r)]);
    for (const auto entry : row) {
      same = same && k < a.cols.size() && read.global_column(a.cols[k]) == entry.col;
      ++k;
    }
  }
  CHECK(same);
  const auto degrees = read.gather(read.local_degrees());
  CHECK(test::bit_difference(degrees, net.degrees()) == "");
  // The Perron pair through the adjacency operator on the blocks, checked against the serial
  // product of the whole network (the same on every rank count): the relative residual the
  // solver is asked for (PerronOptions::tolerance 1e-10) bounds it.
  const PerronResult perron = perron_eigenpair(read);
  double residual2 = 0.0, norm2 = 0.0;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    double au = 0.0;
    for (const auto [j, w] : net.row(i)) au += w * perron.u[std::size_t(j)];
    const double e = au - perron.lambda * perron.u[std::size_t(i)];
    residual2 += e * e;
    norm2 += perron.u[std::size_t(i)] * perron.u[std::size_t(i)];
  }
  INFO("lambda " << perron.lambda << ", serial residual " << std::sqrt(residual2 / norm2));
  CHECK(std::sqrt(residual2 / norm2) <= 1e-10 * perron.lambda);
}

TEST_CASE("A corrupted entry in the last rank's block ends every rank with that rank's message",
          "[distributed][read]") {
  const Network net = erdos_renyi({600, 0.05, 5});
  const SharedFile file("hmfnet_read_corrupt");
  file.write(net, [&] {
    std::vector<std::int32_t> cols = net.cols();
    cols.back() = 600;  // the last row's last column, one past the last node
    test::overwrite_dataset(file.path(), "/network/col", cols, H5T_NATIVE_INT32);
  });
  const std::string message = collective_message([&] { read_distributed_input(file.path()); });
  INFO("rank " << ParallelSession::rank() << ": " << message);
  CHECK_THAT(message, Contains(file.path()) && Contains("column index 600 in row 599"));
  if (ParallelSession::ranks() > 1) {
    CHECK_THAT(message, Contains("(on rank " + std::to_string(ParallelSession::ranks() - 1)));
  }
}

TEST_CASE("An entry without its transpose across blocks is refused on every rank, naming a node",
          "[distributed][read]") {
  const Network net = erdos_renyi({600, 0.05, 5});
  const SharedFile file("hmfnet_read_asymmetric");
  // Row 0's last column moved one node up (kept sorted and in range unless already taken):
  // (0, j) loses its transpose (j, 0), and (0, j + 1) has none, whichever blocks they sit in.
  std::vector<std::int32_t> cols = net.cols();
  const auto last_of_row_0 = static_cast<std::size_t>(net.row_end(0) - 1);
  REQUIRE(cols[last_of_row_0] + 1 < 600);
  REQUIRE_FALSE(net.has_entry(0, cols[last_of_row_0] + 1));
  cols[last_of_row_0] += 1;
  file.write(net,
             [&] { test::overwrite_dataset(file.path(), "/network/col", cols, H5T_NATIVE_INT32); });
  const std::string message = collective_message([&] { read_distributed_input(file.path()); });
  INFO("rank " << ParallelSession::rank() << ": " << message);
  CHECK_THAT(message, Contains(file.path()) && Contains("not symmetric") &&
                          Contains("row 0 and column 0 differ"));
}

TEST_CASE("agree: a failure on one rank reaches every rank, and no failure gives no error",
          "[distributed][read]") {
  CHECK_NOTHROW(ParallelSession::agree([] {}));
  const int last = ParallelSession::ranks() - 1;
  const std::string message = collective_message([&] {
    ParallelSession::agree([&] {
      if (ParallelSession::rank() == last) throw std::runtime_error("only the last rank fails");
    });
  });
  CHECK_THAT(message, Contains("only the last rank fails"));
}
