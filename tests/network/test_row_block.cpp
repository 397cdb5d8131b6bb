// Row blocks: the balanced cut tiles the rows with about equal stored entries, slices are the
// network's rows, and the per-row checks name the global row.
#include <catch2/catch.hpp>

#include "network/erdos_renyi.hpp"
#include "network/row_block.hpp"
#include "support/bit_difference.hpp"
#include "support/io_helpers.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;

namespace {

EdgeOffset max_row(const Network& net) {
  EdgeOffset m = 0;
  for (NodeIndex i = 0; i < net.size(); ++i) m = std::max(m, net.row_end(i) - net.row_begin(i));
  return m;
}

}  // namespace

TEST_CASE(
    "Balanced row blocks tile the rows with at most one row above nnz / parts "
    "[ER N=1000, 1-9 parts]",
    "[row_block]") {
  const Network net = erdos_renyi({1000, 0.02, 3});
  const EdgeOffset nnz = net.nnz();
  for (int parts = 1; parts <= 9; ++parts) {
    const auto starts = balanced_row_starts(net.row_ptr(), parts);
    REQUIRE(starts.size() == std::size_t(parts) + 1);
    CHECK(starts.front() == 0);
    CHECK(starts.back() == net.size());
    for (int p = 0; p < parts; ++p) {
      const auto first = starts[std::size_t(p)], last = starts[std::size_t(p) + 1];
      REQUIRE(first <= last);
      const EdgeOffset held = net.row_ptr()[std::size_t(last)] - net.row_ptr()[std::size_t(first)];
      INFO("parts " << parts << ", block " << p << " holds " << held << " of " << nnz);
      // The cut at ceil(p nnz / P) is overshot by less than one row on each side.
      CHECK(held <= (nnz + parts - 1) / parts + max_row(net));
      CHECK(held >= nnz / parts - max_row(net));
    }
  }
}

TEST_CASE("A hub's row is never split: it fills its block alone [star N=1000, 2 and 3 parts]",
          "[row_block]") {
  const Network star = test::star(1000);  // node 0 holds 999 of the 1998 entries
  CHECK(balanced_row_starts(star.row_ptr(), 2) == std::vector<NodeIndex>{0, 1, 1000});
  const auto three = balanced_row_starts(star.row_ptr(), 3);
  CHECK(three[1] == 1);  // the hub alone: more than a third of the entries
  CHECK(three[2] > 1);
  CHECK(three[2] < 1000);
}

TEST_CASE(
    "With no stored entries the rows are split evenly, and more parts than rows leave "
    "empty blocks",
    "[row_block]") {
  const auto none = balanced_row_starts(10, 4, [](NodeIndex) { return EdgeOffset{0}; });
  CHECK(none == std::vector<NodeIndex>{0, 2, 5, 7, 10});
  const Network pair = Network::from_undirected_edges(2, {{0, 1}});
  const auto many = balanced_row_starts(pair.row_ptr(), 4);
  CHECK(many.front() == 0);
  CHECK(many.back() == 2);
  CHECK(std::is_sorted(many.begin(), many.end()));
  CHECK_THROWS_AS(balanced_row_starts(pair.row_ptr(), 0), ParameterError);
}

TEST_CASE(
    "Slices are the network's rows: concatenated they give back the CSR, degrees and "
    "self-loops [weighted with loops]",
    "[row_block]") {
  const Network net = test::awkward_weighted_network();
  const auto starts = balanced_row_starts(net.row_ptr(), 3);
  std::vector<NodeIndex> cols;
  std::vector<double> weights, degrees;
  EdgeOffset loops = 0;
  for (int p = 0; p < 3; ++p) {
    const RowBlock b = slice_rows(net, starts[std::size_t(p)],
                                  starts[std::size_t(p) + 1] - starts[std::size_t(p)]);
    CHECK(check_row_block(b).empty());
    CHECK(b.first_row == starts[std::size_t(p)]);
    for (NodeIndex r = 0; r < b.rows(); ++r) {
      CHECK(b.row(r).size() == net.row(b.first_row + r).size());
    }
    cols.insert(cols.end(), b.cols.begin(), b.cols.end());
    weights.insert(weights.end(), b.weights.begin(), b.weights.end());
    const auto d = b.degrees();
    degrees.insert(degrees.end(), d.begin(), d.end());
    loops += b.self_loops();
  }
  CHECK(test::bit_difference(cols, net.cols()) == "");
  CHECK(test::bit_difference(weights, net.weights()) == "");
  CHECK(test::bit_difference(degrees, net.degrees()) == "");
  CHECK(loops == net.self_loops());
  CHECK_THROWS_AS(slice_rows(net, 2, net.size()), ParameterError);
}

TEST_CASE("Row block checks name the global row of a bad entry [rows 10-11 of 20]", "[row_block]") {
  RowBlock b;
  b.n = 20;
  b.first_row = 10;
  b.row_ptr = {0, 2, 4};
  b.cols = {3, 7, 1, 19};
  CHECK(check_row_block(b).empty());
  RowBlock out = b;
  out.cols[3] = 20;
  CHECK_THAT(check_row_block(out), Contains("column index 20 in row 11 out of range [0,20)"));
  RowBlock unsorted = b;
  unsorted.cols[1] = 3;
  CHECK_THAT(check_row_block(unsorted), Contains("row 10 has unsorted or duplicate column 3"));
  RowBlock weighted = b;
  weighted.weights = {1.0, 2.0, -1.0, 1.0};
  CHECK_THAT(check_row_block(weighted), Contains("entry (11,1) has weight"));
  RowBlock outside = b;
  outside.first_row = 19;
  CHECK_THAT(check_row_block(outside), Contains("outside the 20 nodes"));
  RowBlock pointers = b;
  pointers.row_ptr = {0, 5, 4};
  CHECK_THAT(check_row_block(pointers), Contains("row_ptr of row 10"));
}
