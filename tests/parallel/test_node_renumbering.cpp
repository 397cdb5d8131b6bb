// Renumbering a network distributed by rows (parallel/node_renumbering.hpp) and partitioning it
// with Zoltan2 (parallel/graph_partition.hpp): the renumbered rows equal the serial permutation
// of the network on every rank count; parts become contiguous in their old order; on a two-block
// SBM whose labels were shuffled the partition finds the blocks again (cut no larger than the
// planted one), and on ER no partition cuts much less than half the entries. Run at 1, 2 and 3
// ranks (label mpi).
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>

#include "network/erdos_renyi.hpp"
#include "network/network_builder.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/graph_partition.hpp"
#include "parallel/node_renumbering.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"
#include "support/weighted_networks.hpp"

using namespace hmfnet;
using hmfnet::test::weighted_er;

namespace {

std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }

// The network with node i renamed new_index[i], built serially (weights kept).
Network permuted(const Network& net, const std::vector<NodeIndex>& new_index) {
  std::vector<MatrixEntry> entries;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    for (const auto [j, w] : net.row(i))
      entries.push_back({new_index[at(i)], new_index[at(j)], w, 0});
  }
  return build_network("permuted", net.size(), std::move(entries),
                       {EntrySymmetry::general, AsymmetryPolicy::reject, 0})
      .network;
}

std::vector<NodeIndex> shuffled_labels(NodeIndex n, std::uint64_t seed) {
  std::vector<NodeIndex> p(at(n));
  std::iota(p.begin(), p.end(), 0);
  std::mt19937_64 rng(seed);
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

// This rank's block of the network, cut as a reader cuts it.
RowBlock own_block(const Network& net) {
  const auto starts = balanced_row_starts(net.row_ptr(), ParallelSession::ranks());
  const auto p = at(ParallelSession::rank());
  return slice_rows(net, starts[p], starts[p + 1] - starts[p]);
}

// Fraction of stored entries cut by partitioning `net` (rows as read on this rank count) into
// `parts` with Zoltan2, and the stored entries of the heaviest part over the mean.
struct Cut {
  double fraction;
  double imbalance;
};
Cut partition_cut(const Network& net, int parts) {
  const RowBlock block = own_block(net);
  const std::vector<int> part = partition_rows(block, parts, 1);
  CHECK(partition_rows(block, parts, 1) == part);  // seeded: the same parts again
  const PartOrder order = order_by_part(block, part, parts);
  const RowBlock renumbered = renumber_rows(block, order.new_index);
  std::vector<double> load(at(parts), 0.0);
  for (NodeIndex r = 0; r < block.rows(); ++r)
    load[at(part[at(r)])] += static_cast<double>(block.row(r).size());
  ParallelSession::sum_in_place(load);
  const double mean = static_cast<double>(net.nnz()) / parts;
  return {static_cast<double>(cut_entries(renumbered, order)) / static_cast<double>(net.nnz()),
          *std::max_element(load.begin(), load.end()) / mean};
}

}  // namespace

TEST_CASE("Renumbered rows equal the serial permutation of the network on every rank count",
          "[distributed][renumbering]") {
  const bool weighted = GENERATE(false, true);
  const Network net = weighted ? weighted_er(700, 0.03, 31) : erdos_renyi({700, 0.03, 31});
  const std::vector<NodeIndex> new_index = shuffled_labels(net.size(), 5);
  const RowBlock mine = renumber_rows(own_block(net), new_index);
  const Network expected = permuted(net, new_index);
  const RowBlock serial = slice_rows(expected, mine.first_row, mine.rows());
  INFO("rank " << ParallelSession::rank() << " of " << ParallelSession::ranks() << ", weighted "
               << weighted);
  CHECK(mine.first_row ==
        balanced_row_starts(expected.row_ptr(),
                            ParallelSession::ranks())[at(ParallelSession::rank())]);
  CHECK(test::bit_difference(mine.row_ptr, serial.row_ptr) == "");
  CHECK(test::bit_difference(mine.cols, serial.cols) == "");
  CHECK(test::bit_difference(mine.weights, serial.weights) == "");
  CHECK(mine.weighted() == weighted);
}

TEST_CASE("order_by_part: parts contiguous, each in its old order, a permutation",
          "[distributed][renumbering]") {
  const Network net = erdos_renyi({500, 0.02, 32});
  const RowBlock block = own_block(net);
  std::vector<int> part(at(block.rows()));
  for (NodeIndex r = 0; r < block.rows(); ++r) part[at(r)] = (block.first_row + r) % 3;
  const PartOrder order = order_by_part(block, part, 3);
  REQUIRE(order.new_index.size() == 500);
  CHECK(order.part_start == std::vector<NodeIndex>{0, 167, 334, 500});
  for (NodeIndex i = 0; i < 500; ++i) {
    // Node i is the (i / 3)-th node of part i % 3.
    CHECK(order.new_index[at(i)] == order.part_start[at(i % 3)] + i / 3);
  }
}

TEST_CASE("Zoltan2 finds the blocks of a shuffled two-block SBM, and ER stays cut",
          "[distributed][renumbering][partition]") {
  // SBM: 2 x 600 nodes, degree ~30 inside and ~1.2 across; labels shuffled, so that the two row
  // halves of the file as given cut about half of all entries.
  const Network planted = two_block_sbm({600, 0.05, 0.002, 33});
  const Network sbm = permuted(planted, shuffled_labels(planted.size(), 34));
  double planted_cut = 0.0;
  double halves_cut = 0.0;
  for (NodeIndex i = 0; i < planted.size(); ++i) {
    for (const auto [j, w] : planted.row(i)) planted_cut += (i < 600) != (j < 600) ? 1.0 : 0.0;
    for (const auto [j, w] : sbm.row(i)) halves_cut += (i < 600) != (j < 600) ? 1.0 : 0.0;
  }
  planted_cut /= static_cast<double>(planted.nnz());
  halves_cut /= static_cast<double>(sbm.nnz());
  const Cut found = partition_cut(sbm, 2);
  INFO("SBM: cut " << found.fraction << " (planted " << planted_cut << ", the file's halves "
                   << halves_cut << "), imbalance " << found.imbalance << " on "
                   << ParallelSession::ranks() << " rank(s)");
  // The ghosts of a rank are the far ends of its cut entries. PHG finds the planted partition
  // here (measured at 1-3 ranks: 0.037945 both); a heuristic owes no optimum, so the claim is
  // that it cuts at most 1.5x the planted entries (a tenth of the file's halves' cut) and, the
  // planted cut being near the minimum at this separation, not far below it.
  CHECK(found.fraction <= 1.5 * planted_cut);
  CHECK(found.fraction >= 0.9 * planted_cut);
  // Parts of equal work (vertex weight 1 + stored entries), Zoltan's default imbalance
  // tolerance 1.1 on those weights.
  CHECK(found.imbalance <= 1.1);

  // ER, mean degree d ~ 20: the smallest bisection still cuts a fraction ~1/2 - P*/sqrt(d) of
  // the edges, P* = 0.7632 (Dembo, Montanari & Sen, Ann. Probab. 45 (2017) 1190): ~0.33; the
  // bound 0.25 leaves room for finite N, where the extremal cut fluctuates.
  const Network er = erdos_renyi({1200, 20.0 / 1199.0, 35});
  const Cut er_cut = partition_cut(er, 2);
  INFO("ER: cut " << er_cut.fraction);
  CHECK(er_cut.fraction >= 0.25);
  CHECK(er_cut.fraction <= 0.5);
}
