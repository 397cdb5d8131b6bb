// An evaluation of g alone (ForceOutputs::force_only, coupling_force.hpp), which the integrators
// ask for where no record reads the sums: g must have the bits of a full evaluation and the sums
// must keep the values they had, for the rank-one force (one replica, an AVX-512 or AVX2 group
// of 8, a group and a tail, two groups; with and without the diagonal) and the sparse force
// (float64 and float32, unsegmented and cut into segments; 1, 4 and 8 replicas), in teams of
// one and two threads. Under HMFNET_SINCOS_ISA=baseline (unit.baseline_row_loops) the same
// cases run the baseline loops.
#include <algorithm>
#include <catch2/catch.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/host_stepper.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

RotorState replicas(NodeIndex first_row, NodeIndex rows, int count) {
  std::vector<InitialCondition> ic;
  for (int b = 0; b < count; ++b)
    ic.push_back({1.0 + 0.5 * b, 0.4 + 0.1 * b, static_cast<std::uint64_t>(60 + b)});
  return initial_state(first_row, rows, ic);
}

// g of a full evaluation, then g alone (after the state's phases moved and back, so that a force
// that skipped its passes would keep stale buffers, not the right ones): the same g and local
// fields y_n, and the sums as they were before the second evaluation.
void check_force_only(CouplingForce& force, const RotorState& s, int threads) {
  const ThreadCountScope scope(threads);
  std::vector<double> g_full, g_only;
  ForceSums full, only;
  force.prepare(s, g_full, full);
  in_team([&] { force.evaluate(s, g_full, full); });
  const std::vector<double> y_full = force.local_fields();
  RotorState moved = s;
  for (double& theta : moved.theta) theta += 0.7;
  force.prepare(moved, g_only, only);
  in_team([&] { force.evaluate(moved, g_only, only); });
  const double sentinel = std::numeric_limits<double>::max();
  std::fill(only.order.begin(), only.order.end(), sentinel);
  std::fill(only.coupling.begin(), only.coupling.end(), sentinel);
  in_team([&] { force.evaluate(s, g_only, only, ForceOutputs::force_only); });
  CHECK(test::bit_difference(g_only, g_full) == "");
  CHECK(test::bit_difference(force.local_fields(), y_full) == "");
  CHECK(test::bit_difference(only.order, std::vector<double>(full.order.size(), sentinel)) == "");
  CHECK(test::bit_difference(only.coupling, std::vector<double>(full.coupling.size(), sentinel)) ==
        "");
}

}  // namespace

TEST_CASE("The rank-one force's g alone has the bits of a full evaluation", "[force_outputs]") {
  const NodeIndex n = 2500;  // more than one block of the ordered sums (2048 rows)
  for (const bool diagonal : {true, false}) {
    for (const int count : {1, 8, 9, 16}) {
      for (const int threads : {1, 2}) {
        INFO((diagonal ? "with" : "without")
             << " the diagonal, " << count << " replicas, " << threads << " threads");
        RankOneForce force(RankOneStructure{std::vector<double>(n, 1.0), diagonal}, 0, n);
        check_force_only(force, replicas(0, n, count), threads);
      }
    }
  }
}

TEST_CASE("The sparse force's g alone has the bits of a full evaluation", "[force_outputs]") {
  const DistributedNetwork d(erdos_renyi({1200, 0.02, 5}));
  for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
    for (const NodeIndex width : {k_unsegmented, NodeIndex{128}}) {
      for (const int count : {1, 4, 8}) {
        for (const int threads : {1, 2}) {
          INFO(to_string(precision) << ", segment width " << width << ", " << count << " replicas, "
                                    << threads << " threads");
          NetworkForce force(d, precision, width);
          check_force_only(force, replicas(d.first_row(), d.local_size(), count), threads);
        }
      }
    }
  }
}

TEST_CASE("A force evaluation says whether its sums are the last evaluation's", "[force_outputs]") {
  const NodeIndex n = 100;
  RankOneForce force(RankOneStructure{std::vector<double>(n, 1.0), false}, 0, n);
  const RotorState s = replicas(0, n, 2);
  ForceEvaluation f(force);
  CHECK_FALSE(f.sums_current());
  f.update(s);
  CHECK(f.sums_current());
  f.update(s, ForceOutputs::force_only);
  CHECK_FALSE(f.sums_current());
  f.update(s, ForceOutputs::force_and_sums);
  CHECK(f.sums_current());
}

namespace {

// An integrator whose step ends with an evaluation of g alone, which none of the library's does:
// what a record would read after it are sums of an earlier state.
class SkipsSums : public Integrator {
 public:
  int order() const override { return 1; }
  std::string name() const override { return "skips-sums"; }
  int evaluations_per_step() const override { return 1; }
  double stability_limit() const override { return 1.0; }

 private:
  void advance(RotorState& state, double /*h*/, const std::vector<double>& /*K*/,
               ForceEvaluation& f) const override {
    f.update(state, ForceOutputs::force_only);
  }
};

}  // namespace

TEST_CASE("The CPU stepper refuses sums that its last evaluation skipped", "[force_outputs]") {
  const NodeIndex n = 100;
  RankOneForce force(RankOneStructure{std::vector<double>(n, 1.0), false}, 0, n);
  HostStepper stepper(force);
  stepper.set_state(replicas(0, n, 2));
  CHECK_NOTHROW(stepper.sums());
  const std::vector<double> K(2, 1.0);
  for (const std::string name : {"leapfrog", "yoshida4", "blanes_moan", "rk4"}) {
    INFO(name);
    stepper.advance(*make_integrator(name), 0.01, K, 3, nullptr);
    CHECK_NOTHROW(stepper.sums());
  }
  stepper.advance(SkipsSums(), 0.01, K, 1, nullptr);
  CHECK_THROWS_AS(stepper.sums(), std::logic_error);
}
