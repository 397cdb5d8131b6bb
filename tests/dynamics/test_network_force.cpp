// The sparse force kernel in float32 against float64 (dynamics/network_force.hpp): the error
// bound of its header, bit-identical results for any thread count, and B replicas in one pass
// equal to B separate passes, as for float64.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "dynamics/network_force.hpp"
#include "dynamics/team.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/bit_difference.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

constexpr double k_unit_roundoff_f32 = 0x1p-24;

struct Evaluation {
  std::vector<double> g;
  ForceSums sums;
};

Evaluation evaluate(const DistributedNetwork& d, ForcePrecision p, const RotorState& s) {
  NetworkForce force(d, p);
  Evaluation e;
  // Inside a step's team, as the integrators call it (outside one it runs on one thread).
  force.prepare(s, e.g, e.sums);
  in_team([&] { force.evaluate(s, e.g, e.sums); });
  return e;
}

RotorState state(const DistributedNetwork& d, int replicas) {
  std::vector<InitialCondition> ic;
  for (int b = 0; b < replicas; ++b) ic.push_back({6.0, 1.0, static_cast<std::uint64_t>(b + 3)});
  return initial_state(d.first_row(), d.local_size(), ic);
}

}  // namespace

TEST_CASE("float32 force within its rounding bound of float64 and not equal to it",
          "[network_force]") {
  const Network base = erdos_renyi({800, 0.05, 11});
  for (const bool is_weighted : {false, true}) {
    const Network net = is_weighted ? test::pair_weighted(base) : base;
    const DistributedNetwork d(net);
    for (const int B : {1, 3, 4}) {
      const RotorState s = state(d, B);
      const Evaluation e64 = evaluate(d, ForcePrecision::float64, s);
      const Evaluation e32 = evaluate(d, ForcePrecision::float32, s);
      double worst_ratio = 0.0, largest = 0.0;
      for (NodeIndex r = 0; r < d.local_size(); ++r) {
        const NodeIndex row = d.first_row() + r;
        double W = 0.0;  // sum_m |A_nm|
        for (EdgeOffset k = net.row_begin(row); k < net.row_end(row); ++k)
          W += is_weighted ? net.weights()[static_cast<std::size_t>(k)] : 1.0;
        const double d_n = static_cast<double>(net.row_end(row) - net.row_begin(row));
        // |dg| <= (|cos| |dys| + |sin| |dyc|) / N <= 2 (d_n + 3) u W / N (network_force.hpp).
        const double bound = 2.0 * (d_n + 3.0) * k_unit_roundoff_f32 * W / net.size();
        for (int b = 0; b < B; ++b) {
          const std::size_t i = static_cast<std::size_t>(r * B + b);
          const double diff = std::abs(e32.g[i] - e64.g[i]);
          worst_ratio = std::max(worst_ratio, diff / bound);
          largest = std::max(largest, diff);
        }
      }
      INFO("weighted " << is_weighted << ", B = " << B << ": largest |dg| " << largest
                       << ", worst |dg| / bound " << worst_ratio);
      CHECK(worst_ratio <= 1.0);
      CHECK(largest > 0.0);  // the float32 path is really taken
    }
  }
}

TEST_CASE("float32 force is bit-identical for 1 and 2 threads and per replica", "[network_force]") {
  const Network net = test::pair_weighted(erdos_renyi({700, 0.04, 5}));
  const DistributedNetwork d(net);
  const RotorState s4 = state(d, 4);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Evaluation one = evaluate(d, ForcePrecision::float32, s4);
  omp_set_num_threads(2);
  const Evaluation two = evaluate(d, ForcePrecision::float32, s4);
  omp_set_num_threads(threads);
  CHECK(test::bit_difference(one.g, two.g) == "");
  CHECK(test::bit_difference(one.sums.order, two.sums.order) == "");
  // Replica b of the 4-replica pass against a one-replica pass from the same initial condition.
  for (int b = 0; b < 4; ++b) {
    const RotorState s1 = initial_state(d.first_row(), d.local_size(),
                                        {{6.0, 1.0, static_cast<std::uint64_t>(b + 3)}});
    const Evaluation single = evaluate(d, ForcePrecision::float32, s1);
    bool same = true;
    for (NodeIndex r = 0; r < d.local_size(); ++r)
      same = same && single.g[static_cast<std::size_t>(r)] ==
                         one.g[static_cast<std::size_t>(r) * 4 + static_cast<std::size_t>(b)];
    CHECK(same);
  }
}

TEST_CASE("Every replica kernel equals one-replica passes bit for bit [B = 2 to 24]",
          "[network_force]") {
  // Each B takes another kernel shape (the baseline loops' partials per pass: B = 2 four, B = 4
  // two in float64 and four in float32, B = 8 one and two, others the run-time width; with AVX2
  // the wide loops of wide_rows.hpp for B = 2, 4, 8 and in groups for the others (3 = 2 + 1,
  // 13 = 8 + 4 + 1, 24 = 8 + 8 + 8), the baseline ones in the test unit.baseline_row_loops), on
  // 0/1 and weighted rows whose degrees are not all multiples of 4 (the tail goes to partial 0).
  const Network plain = erdos_renyi({500, 0.05, 9});
  const Network heavy = test::pair_weighted(plain);
  for (const Network* net : {&plain, &heavy}) {
    const DistributedNetwork d(*net);
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      std::vector<Evaluation> singles;
      for (int b = 0; b < 24; ++b) {
        singles.push_back(evaluate(d, precision,
                                   initial_state(d.first_row(), d.local_size(),
                                                 {{6.0, 1.0, static_cast<std::uint64_t>(b + 3)}})));
      }
      for (const int replicas : {2, 3, 4, 8, 13, 24}) {
        const Evaluation all = evaluate(d, precision, state(d, replicas));
        const auto width = static_cast<std::size_t>(replicas);
        bool same = true;
        for (std::size_t b = 0; b < width; ++b) {
          for (std::size_t r = 0; r < static_cast<std::size_t>(d.local_size()); ++r) {
            same = same && all.g[r * width + b] == singles[b].g[r];
          }
          same = same && all.sums.order[b] == singles[b].sums.order[0] &&
                 all.sums.coupling[b] == singles[b].sums.coupling[0];
        }
        INFO("B = " << replicas << ", " << to_string(precision)
                    << (net->weighted() ? ", weighted" : ", 0/1"));
        CHECK(same);
      }
    }
  }
}

TEST_CASE("force precision names parse and refuse others", "[network_force]") {
  CHECK(parse_force_precision("float32") == ForcePrecision::float32);
  CHECK(parse_force_precision("float64") == ForcePrecision::float64);
  CHECK_THROWS_WITH(parse_force_precision("half"), Catch::Contains("(allowed: float64, float32)"));
  CHECK(std::string(to_string(ForcePrecision::float32)) == "float32");
}
