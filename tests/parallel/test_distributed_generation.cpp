// Generating by rows over the ranks (parallel/distributed_generation.hpp) and writing the blocks
// into one file (parallel/distributed_network_file.hpp): at 1, 2 and 3 ranks (label mpi) every
// rank's block is exactly its rows of the serial network, cut as a reader cuts them, and the
// file equals the one written serially; a bad destination or blocks that do not tile end every
// rank with one message and leave no file.
#include <catch2/catch.hpp>
#include <filesystem>

#include "core/error.hpp"
#include "io/network_hdf5.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "network/random_regular.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/distributed_generation.hpp"
#include "parallel/distributed_network_file.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"
#include "support/shared_file.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::collective_message;
using hmfnet::test::SharedFile;

namespace {

// This rank's block against the serial network: the same cut and the same rows.
void check_block(const RowBlock& block, const Network& net) {
  INFO("rank " << ParallelSession::rank() << " of " << ParallelSession::ranks());
  const auto starts = balanced_row_starts(net.row_ptr(), ParallelSession::ranks());
  const auto me = static_cast<std::size_t>(ParallelSession::rank());
  CHECK(check_row_block(block).empty());
  CHECK(block.n == net.size());
  CHECK(block.first_row == starts[me]);
  CHECK(block.rows() == starts[me + 1] - starts[me]);
  const RowBlock serial = slice_rows(net, starts[me], starts[me + 1] - starts[me]);
  CHECK(test::bit_difference(block.row_ptr, serial.row_ptr) == "");
  CHECK(test::bit_difference(block.cols, serial.cols) == "");
  CHECK_FALSE(block.weighted());
}

}  // namespace

TEST_CASE("Each rank generates exactly its rows of the serial network (ER, Chung-Lu, SBM, regular)",
          "[distributed][generation]") {
  const auto er = erdos_renyi_source({2000, 0.02, 21});
  const PowerLaw law{2.5, power_law_d_min_for_mean(2.5, 15.0)};
  const auto sf = chung_lu_source(power_law_targets(3000, law, 22), LinkProbability::capped, 22);
  const auto sbm = two_block_sbm_source({300, 0.08, 0.01, 23});
  const auto regular = random_regular_source({1000, 12, 24});  // one global pairing per rank
  for (const EdgeSource* source : {er.get(), sf.get(), sbm.get(), regular.get()}) {
    const Network net = network_from_source(*source);
    // A chunk of 257 edges: many rounds, so ranks with fewer rounds take part with empty sends.
    check_block(generate_distributed(*source, 257), net);
    check_block(generate_distributed(*source), net);
  }
}

TEST_CASE("Row blocks written by all ranks make the file written serially",
          "[distributed][generation]") {
  const auto source = erdos_renyi_source({1500, 0.03, 31});
  const Network net = network_from_source(*source);
  const SharedFile file("hmfnet_generated_blocks");
  write_distributed_network_hdf5(file.path(), generate_distributed(*source), "{\"test\": 1}");
  const Network read = read_network_hdf5(file.path()).network;
  CHECK(test::bit_difference(read.row_ptr(), net.row_ptr()) == "");
  CHECK(test::bit_difference(read.cols(), net.cols()) == "");
  CHECK(read.edges() == net.edges());
  CHECK_FALSE(read.weighted());
}

TEST_CASE("Writing row blocks fails on every rank, leaving no file, for a bad destination",
          "[distributed][generation]") {
  const auto source = erdos_renyi_source({300, 0.05, 41});
  const RowBlock block = generate_distributed(*source);
  const std::string missing = "/nonexistent_hmfnet_dir/net.h5";
  CHECK_THAT(collective_message([&] { write_distributed_network_hdf5(missing, block); }),
             Contains("nonexistent_hmfnet_dir"));

  // Blocks that do not tile the rows: every rank drops its first row.
  const Network net = network_from_source(*source);
  const RowBlock shifted =
      slice_rows(net, block.first_row + (block.rows() > 0 ? 1 : 0), std::max(block.rows() - 1, 0));
  const SharedFile file("hmfnet_untiled_blocks");
  CHECK_THAT(collective_message([&] { write_distributed_network_hdf5(file.path(), shifted); }),
             Contains("do not tile"));
  CHECK_FALSE(std::filesystem::exists(file.path()));
}

TEST_CASE("Generation leaves ranks without rows or units when there is little to share",
          "[distributed][generation]") {
  // One edge, no edges, and fewer nodes than ranks at 3 ranks.
  for (const auto& params : {ErdosRenyiParameters{2, 1.0, 1}, ErdosRenyiParameters{5, 0.0, 1},
                             ErdosRenyiParameters{1, 0.5, 1}}) {
    INFO("N = " << params.n << ", q = " << params.q);
    const auto source = erdos_renyi_source(params);
    check_block(generate_distributed(*source, 1), network_from_source(*source));
  }
}

TEST_CASE("Weighted row blocks written by all ranks make the file written serially",
          "[distributed][generation]") {
  const Network net = test::weighted_ring(31);
  const auto starts = balanced_row_starts(net.row_ptr(), ParallelSession::ranks());
  const auto me = static_cast<std::size_t>(ParallelSession::rank());
  const RowBlock block = slice_rows(net, starts[me], starts[me + 1] - starts[me]);
  const SharedFile file("hmfnet_weighted_blocks");
  write_distributed_network_hdf5(file.path(), block);
  const Network read = read_network_hdf5(file.path()).network;
  CHECK(test::bit_difference(read.row_ptr(), net.row_ptr()) == "");
  CHECK(test::bit_difference(read.cols(), net.cols()) == "");
  CHECK(test::bit_difference(read.weights(), net.weights()) == "");
}
