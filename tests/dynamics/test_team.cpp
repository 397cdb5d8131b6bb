// One parallel region per step (dynamics/team.hpp): an error on the master thread leaves the
// region as an exception (no hang, no termination), the ordered sums of a team equal the serial
// ones bit for bit, and both forces give the same g and sums in a team of 2 as on one thread.
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dynamics/network_force.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/bit_difference.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

struct Evaluation {
  std::vector<double> g;
  ForceSums sums;
  std::vector<double> y;
};

Evaluation in_a_team(CouplingForce& force, const RotorState& s) {
  Evaluation e;
  force.prepare(s, e.g, e.sums);
  in_team([&] { force.evaluate(s, e.g, e.sums); });
  e.y = force.local_fields();
  return e;
}

// The force evaluated in a team of one thread and in a team of two, each by a force of its own
// (`make_force()`), so that no buffer filled by the first run can stand in for the second's.
template <typename MakeForce>
std::pair<Evaluation, Evaluation> one_and_two_threads(MakeForce make_force, const RotorState& s) {
  std::pair<Evaluation, Evaluation> e;
  {
    const ThreadCountScope one(1);
    auto force = make_force();
    e.first = in_a_team(force, s);
  }
  const ThreadCountScope two(2);
  auto force = make_force();
  e.second = in_a_team(force, s);
  return e;
}

void check_identical(const Evaluation& one, const Evaluation& two) {
  CHECK(test::bit_difference(one.g, two.g) == "");
  CHECK(test::bit_difference(one.y, two.y) == "");
  CHECK(test::bit_difference(one.sums.order, two.sums.order) == "");
  CHECK(test::bit_difference(one.sums.coupling, two.sums.coupling) == "");
}

RotorState three_replicas(const DistributedNetwork& d) {
  return initial_state(d.first_row(), d.local_size(),
                       {{6.0, 1.0, 21}, {6.0, 0.3, 22}, {6.0, 2.0, 23}});
}

}  // namespace

TEST_CASE("An error on the master thread leaves the team as an exception after the region",
          "[team]") {
  const ThreadCountScope two(2);
  std::atomic<int> finished{0};
  int exchanges_after_failure = 0;
  const auto failing_step = [&] {
    in_team([&] {
      on_master([] { throw std::runtime_error("rank 1: import failed"); });
      on_master([&] { ++exchanges_after_failure; });  // skipped: no exchange after a failed one
      // The team goes on through its later barriers: a thread that skipped them would hang.
#pragma omp barrier
      ++finished;
    });
  };
  REQUIRE_THROWS_WITH(failing_step(), "rank 1: import failed");
  CHECK(finished == 2);  // both threads reached the end of the region
  CHECK(exchanges_after_failure == 0);
  // Outside a region on_master is a plain call.
  REQUIRE_THROWS_WITH(on_master([] { throw std::runtime_error("serial"); }), "serial");
}

namespace {

// The documented order written out: blocks of 2048 rows, each summed from 0 in row order, the
// block sums added in block order.
std::vector<double> documented_sums(const std::vector<double>& values, std::size_t rows,
                                    std::size_t width) {
  std::vector<double> out(width, 0.0);
  for (std::size_t b = 0; b < width; ++b) {
    double total = 0.0;
    for (std::size_t first = 0; first < rows; first += 2048) {
      double block = 0.0;
      for (std::size_t r = first; r < std::min(rows, first + 2048); ++r)
        block += values[r * width + b];
      total += block;
    }
    out[b] = total;
  }
  return out;
}

// Values of mixed sign and magnitude (1 to 10^12), so that another order of the additions
// changes the bits.
std::vector<double> mixed_values(std::size_t count) {
  std::vector<double> v(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double sign = k % 3 == 0 ? -1.0 : 1.0;
    v[k] = sign * (1.0 / (1.0 + static_cast<double>(k)) + static_cast<double>(k % 7) * 1e11 +
                   static_cast<double>(k % 13) * 0.1);
  }
  return v;
}

}  // namespace

TEST_CASE("Ordered sums in a team of 1, 2 or 3 equal the documented order bit for bit", "[team]") {
  // Widths with a grouped kernel (1, 2, 4, 8, 16 columns: several blocks summed side by side)
  // and without (3, 70: past the 64 columns summed at once); row counts with one short block,
  // exactly full blocks, and more blocks than a group (20 000 rows: 10 blocks).
  for (const std::size_t width : std::initializer_list<std::size_t>{1, 2, 3, 4, 8, 16, 70}) {
    for (const std::size_t rows :
         std::initializer_list<std::size_t>{0, 1, 2047, 2048, 4097, 5000, 20000}) {
      const std::vector<double> values = mixed_values(rows * width);
      const std::vector<double> expected = documented_sums(values, rows, width);
      for (const int threads : {1, 2, 3}) {
        INFO("width " << width << ", rows " << rows << ", threads " << threads);
        const ThreadCountScope scope(threads);
        std::vector<double> free_call;
        ordered_column_sums(values, rows, static_cast<int>(width), free_call);
        CHECK(test::bit_difference(free_call, expected) == "");
        OrderedColumnSums sums;
        sums.prepare(rows, static_cast<int>(width));
        std::vector<double> team(width, -1.0);
        int team_size = 0;
        in_team([&] {
          sums.sum(values.data(), team.data());
#pragma omp master
          team_size = omp_get_num_threads();
        });
        CHECK(team_size == threads);  // the region really ran that many threads
        CHECK(test::bit_difference(team, expected) == "");
      }
    }
  }
}

TEST_CASE("Sparse and rank-one forces: a team of 2 gives what one thread gives, bit for bit",
          "[team]") {
  const Network net = erdos_renyi({600, 0.05, 4});
  const DistributedNetwork d(net);
  const RotorState s = three_replicas(d);
  const auto [one, two] = one_and_two_threads([&] { return NetworkForce(d); }, s);
  check_identical(one, two);

  // The all-to-all force without self-loops (rank one, a = 1) on 5000 rotors: three sum
  // blocks. Built from its structure alone (a complete network of that size would hold 2.5e7
  // entries); each rank takes every row, which changes Z but not the comparison.
  RankOneStructure all_to_all;
  all_to_all.a.assign(5000, 1.0);
  all_to_all.diagonal = false;
  const RotorState sc = initial_state(0, 5000, {{6.0, 1.0, 21}, {6.0, 0.3, 22}, {6.0, 2.0, 23}});
  const auto [r1, r2] = one_and_two_threads([&] { return RankOneForce(all_to_all, 0, 5000); }, sc);
  check_identical(r1, r2);
}

TEST_CASE("The rank-one force in a team of 2 is the sparse force of the complete graph", "[team]") {
  const ThreadCountScope two(2);
  const Network complete = test::complete(400, false);
  const DistributedNetwork d(complete);
  auto structure = detect_rank_one(d);
  REQUIRE(structure.has_value());
  RankOneForce rank_one(*structure, d.first_row(), d.local_size());
  NetworkForce sparse(d);
  const RotorState s = three_replicas(d);
  const Evaluation fast = in_a_team(rank_one, s), reference = in_a_team(sparse, s);
  // Same sums in another order: g is O(1) and 400 terms of O(1) differ by a few ulps each.
  double worst = 0.0;
  for (std::size_t k = 0; k < fast.g.size(); ++k)
    worst = std::max(worst, std::abs(fast.g[k] - reference.g[k]));
  CHECK(worst < 1e-12);
}
