// The column indices in 16 bits (dynamics/narrow_columns.hpp): the copy holds the CSR's indices
// (none once moved from), taking them gives the 4-byte array's pages back and empties it, only
// networks of at most 2^16 columns fit; and the sparse force whose unblocked walk reads them gives
// the bits of the walk over the 32-bit indices, for float64 and float32, 0/1 and weighted rows, 1
// to 13 replicas, 1 and 2 threads, with the network's indices kept or taken (before or after the
// first walk), and across a trial's switch to column segments and back.
#include <catch2/catch.hpp>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "dynamics/column_segments.hpp"
#include "dynamics/narrow_columns.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/bit_difference.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using test::bit_difference;

namespace {

struct Evaluation {
  std::vector<double> g, y;
  ForceSums sums;
};

Evaluation evaluate(NetworkForce& force, const RotorState& s) {
  Evaluation e;
  force.prepare(s, e.g, e.sums);
  in_team([&] { force.evaluate(s, e.g, e.sums); });
  e.y = force.local_fields();
  return e;
}

RotorState state(const DistributedNetwork& d, int replicas) {
  std::vector<InitialCondition> ic;
  for (int b = 0; b < replicas; ++b) ic.push_back({6.0, 1.0, static_cast<std::uint64_t>(b + 3)});
  return initial_state(d.first_row(), d.local_size(), ic);
}

// The same bits in g, y and both sums.
void check_same(const Evaluation& a, const Evaluation& b) {
  CHECK(bit_difference(a.g, b.g) == "");
  CHECK(bit_difference(a.y, b.y) == "");
  CHECK(bit_difference(a.sums.order, b.sums.order) == "");
  CHECK(bit_difference(a.sums.coupling, b.sums.coupling) == "");
}

}  // namespace

TEST_CASE("16-bit column indices: the CSR's own, taken or copied, up to 2^16 columns",
          "[narrow_columns]") {
  CHECK(NarrowColumns::fits(k_narrow_segment_columns));
  CHECK_FALSE(NarrowColumns::fits(k_narrow_segment_columns + 1));
  const std::vector<NodeIndex> cols{0, 7, 65535, 3, 65534, 1, 0};
  const NarrowColumns copy(cols, k_narrow_segment_columns);
  REQUIRE(copy.size() == cols.size());
  CHECK(copy.bytes() == 2 * cols.size());
  CHECK(copy.data()[2] == 65535);
  CHECK(copy.widened() == cols);
  std::vector<NodeIndex> taken = cols;
  const NarrowColumns narrow = NarrowColumns::taking(taken, k_narrow_segment_columns);
  CHECK(taken.empty());
  CHECK(narrow.widened() == cols);
  CHECK(NarrowColumns().empty());
  NarrowColumns from = NarrowColumns(cols, k_narrow_segment_columns);
  const NarrowColumns to = std::move(from);
  CHECK(to.widened() == cols);
  CHECK(from.empty());      // NOLINT(bugprone-use-after-move): what a moved-from copy reports
  CHECK(from.size() == 0);  // NOLINT(bugprone-use-after-move)
  NarrowColumns assigned;
  assigned = NarrowColumns(cols, k_narrow_segment_columns);
  CHECK(assigned.widened() == cols);
  CHECK_THROWS_AS(NarrowColumns(cols, k_narrow_segment_columns + 1), ParameterError);
}

TEST_CASE("16-bit column indices taken on 2 threads give the 4-byte pages back [1.2 M entries]",
          "[narrow_columns]") {
  // ~4.8 MB of 4-byte indices: each thread's block passes the 1 MiB step of the page release,
  // from a start that is not on a page boundary; what it released must not be read again.
  const Network net = erdos_renyi({30'000, 0.0013, 5});
  REQUIRE(net.cols().size() > 1'000'000);
  const ThreadCountScope two(2);
  std::vector<NodeIndex> taken = net.cols();
  const NarrowColumns narrow = NarrowColumns::taking(taken, net.size());
  CHECK(taken.empty());
  const bool same = narrow.widened() == net.cols();  // (a failure prints no 10^6 values)
  CHECK(same);
}

TEST_CASE("The unblocked walk over 16-bit column indices gives the bits of the 32-bit one",
          "[narrow_columns]") {
  const Network plain = erdos_renyi({700, 0.04, 5});
  const Network heavy = test::pair_weighted(plain);
  for (const Network* net : {&plain, &heavy}) {
    const DistributedNetwork d(*net);
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      for (const int replicas : {1, 2, 3, 4, 8, 13}) {
        for (const int threads : {1, 2}) {
          INFO(to_string(precision) << (net->weighted() ? ", weighted" : ", 0/1")
                                    << ", B = " << replicas << ", " << threads << " threads");
          const ThreadCountScope scope(threads);
          const RotorState s = state(d, replicas);
          NetworkForce narrow(d, precision, k_unsegmented);
          NetworkForce wide(d, precision, k_unsegmented, false);
          const Evaluation a = evaluate(narrow, s), b = evaluate(wide, s);
          CHECK(narrow.narrow_columns());
          CHECK_FALSE(wide.narrow_columns());
          check_same(a, b);
        }
      }
    }
  }
  // More columns than 16 bits hold (a rank's owned and ghost columns: on 2 ranks each owns
  // 70,000): the 32-bit walk.
  const DistributedNetwork large(erdos_renyi({140'000, 2.0 / 140'000, 3}));
  REQUIRE(large.local_adjacency().columns > k_narrow_segment_columns);
  NetworkForce force(large, ForcePrecision::float64, k_unsegmented);
  evaluate(force, state(large, 1));
  CHECK_FALSE(force.narrow_columns());
}

TEST_CASE("A force that takes the indices narrows them, and widens them for segments it tries",
          "[narrow_columns][column_segments]") {
  // test_step_trial.cpp's case: ER N = 2000, mean degree 27, float64 with 4 replicas, caches of
  // 8 KiB L2 and a 32 KiB core complex's L3, where the rule leaves the rows unblocked and offers
  // 4 segments to try.
  const Network net = erdos_renyi({2000, 27.0 / 2000.0, 5});
  const CacheSizes caches{std::size_t{8} << 10, std::size_t{32} << 10, 1, true};
  const ThreadCountScope one(1);
  const DistributedNetwork reference(net);
  NetworkForce wide(reference, ForcePrecision::float64, k_unsegmented, false);
  DistributedNetwork taker(net);
  NetworkForce force(taker);
  force.read_caches_as(caches);
  const RotorState s = state(reference, 4);
  const Evaluation whole = evaluate(wide, s);
  SECTION("taken before the first walk") {
    force.take_columns(taker);
    check_same(evaluate(force, s), whole);
    CHECK(force.narrow_columns());
    CHECK_THROWS_WITH(taker.local_adjacency(), Catch::Contains("given to the sparse force"));
  }
  SECTION("taken after a walk over a 16-bit copy of the network's own (a library caller's order)") {
    // The copy is dropped when the indices are taken, not widened over them.
    check_same(evaluate(force, s), whole);
    CHECK(force.narrow_columns());
    CHECK_NOTHROW(taker.local_adjacency());
    force.take_columns(taker);
  }
  CHECK(force.segments() == 1);
  REQUIRE(force.segment_candidates() == std::vector<int>{1, 4});
  force.use_segments(4);
  check_same(evaluate(force, s), whole);
  CHECK(force.segments() == 4);
  CHECK_FALSE(force.narrow_columns());
  CHECK_THROWS_WITH(taker.local_adjacency(), Catch::Contains("given to the sparse force"));
  force.use_segments(1);
  check_same(evaluate(force, s), whole);
  CHECK(force.segments() == 1);
  CHECK(force.narrow_columns());
}
