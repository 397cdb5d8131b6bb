// A schedule run across replicas (K_across_replicas, replica_lanes.hpp) against the same schedule
// run one K after another from the initial condition: equal bit for bit, on any rank count, for
// every force and method; resumable; refused with the reason where it cannot apply.
#include <catch2/catch.hpp>
#include <filesystem>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/replica_lanes.hpp"
#include "dynamics/simulation.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/simulation_runs.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using hmfnet::test::short_run;
using hmfnet::test::temp_path;

namespace {

// Three K x two replicas, each K from the initial condition.
SimulationParameters sweep() {
  SimulationParameters p = short_run();
  p.replicas = {{6.0, 1.0, 11}, {5.0, 0.5, 12}};
  p.continue_state = false;
  return p;
}

SimulationParameters across(SimulationParameters p) {
  p.K_across_replicas = true;
  return p;
}

void require_same_results(const SimulationResult& a, const SimulationResult& b) {
  REQUIRE(a.points.size() == b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    INFO("point " << k);
    REQUIRE(a.points[k].K == b.points[k].K);
    REQUIRE(a.points[k].integrator == b.points[k].integrator);
    REQUIRE(a.points[k].h == b.points[k].h);
    REQUIRE(a.points[k].R_mean == b.points[k].R_mean);
    REQUIRE(a.points[k].R_sem == b.points[k].R_sem);
    REQUIRE(a.points[k].energy_rel_error_max == b.points[k].energy_rel_error_max);
    REQUIRE(a.points[k].momentum_drift == b.points[k].momentum_drift);
  }
  REQUIRE(a.series.t == b.series.t);
  REQUIRE(a.series.K == b.series.K);
  REQUIRE(a.series.R == b.series.R);
  REQUIRE(a.series.energy == b.series.energy);
  REQUIRE(a.series.momentum == b.series.momentum);
}

}  // namespace

TEST_CASE("Lane m R + r is replica r at K_m", "[replica_lanes]") {
  const SimulationParameters p = across(sweep());
  const SimulationParameters one = lane_parameters(p);
  REQUIRE(lanes(p) == 6);
  REQUIRE(one.K.size() == 1);
  REQUIRE(one.replicas.size() == 6);
  REQUIRE_FALSE(one.K_across_replicas);
  REQUIRE(lane_couplings(p) == std::vector<double>{20.0, 20.0, 60.0, 60.0, 120.0, 120.0});
  for (std::size_t lane = 0; lane < 6; ++lane)
    REQUIRE(one.replicas[lane].seed == p.replicas[lane % 2].seed);
}

TEST_CASE("K across replicas equals the restart-each-K run bit for bit [ER N=300, 3 K x 2]",
          "[replica_lanes]") {
  const Network net = erdos_renyi({300, 0.05, 4});
  const DistributedNetwork d(net);
  for (const char* method : {"leapfrog", "yoshida4", "rk4"}) {
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      INFO(method << ", precision " << static_cast<int>(precision));
      NetworkForce force(d, precision);
      SimulationParameters p = sweep();
      p.integrator = method;
      const SimulationResult one_by_one = simulate(d, net.degrees(), force, p);
      const SimulationResult at_once = simulate(d, net.degrees(), force, across(p));
      require_same_results(at_once, one_by_one);
      // One pass: the steps of one K, each step serving every lane.
      REQUIRE(at_once.lanes == 6);
      REQUIRE(one_by_one.lanes == 2);
      REQUIRE(at_once.steps * 3 == one_by_one.steps);
    }
  }
}

TEST_CASE("K across replicas equals the restart-each-K run with the rank-one force [K_N]",
          "[replica_lanes]") {
  const Network net = test::complete(90);
  const DistributedNetwork d(net);
  auto structure = detect_rank_one(d);
  REQUIRE(structure.has_value());
  RankOneForce force(*structure, d.first_row(), d.local_size());
  SimulationParameters p = sweep();
  p.K = {0.5, 2.0, 6.0, 10.0};
  p.steps = std::vector<StepChoice>(4, StepChoice{"blanes_moan", 0.05});
  require_same_results(simulate(d, net.degrees(), force, across(p)),
                       simulate(d, net.degrees(), force, p));
}

TEST_CASE("A run across replicas resumes bit-identical to an uninterrupted one [ER N=300]",
          "[replica_lanes]") {
  const Network net = erdos_renyi({300, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = across(sweep());
  const SimulationResult whole = simulate(d, net.degrees(), force, p);
  p.checkpoint_path = temp_path("hmfnet_test_lanes_checkpoint");
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
  ParallelSession::max(0.0);
  p.checkpoint_seconds = 0.0;
  p.resume = true;
  for (const std::int64_t stop : {70, 0}) {
    p.stop_after_steps = stop;
    const SimulationResult part = simulate(d, net.degrees(), force, p);
    REQUIRE(part.interrupted == (stop != 0));
    if (stop == 0) {
      REQUIRE(part.resumed);
      require_same_results(part, whole);
      REQUIRE(part.force_evaluations == whole.force_evaluations);
    }
  }
  // The checkpoint names the whole schedule: the sequential run does not take it.
  p.K_across_replicas = false;
  p.stop_after_steps = 0;
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
  ParallelSession::max(0.0);
  SimulationParameters q = across(sweep());
  q.checkpoint_path = p.checkpoint_path;
  q.checkpoint_seconds = 0.0;
  q.stop_after_steps = 70;
  simulate(d, net.degrees(), force, q);
  REQUIRE_THROWS_WITH(simulate(d, net.degrees(), force, p),
                      Catch::Contains("checkpoint belongs to another run ("));
  ParallelSession::max(0.0);
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
}

TEST_CASE("K across replicas is refused where it cannot apply, with the reason",
          "[replica_lanes]") {
  SimulationParameters p = across(sweep());
  SECTION("each K continuing from the previous one") {
    p.continue_state = true;
    REQUIRE_THROWS_WITH(validate(p), Catch::Contains("cannot continue each other"));
  }
  SECTION("a step that differs between K values") {
    p.steps = {{"leapfrog", 0.02}, {"leapfrog", 0.02}, {"leapfrog", 0.01}};
    REQUIRE_THROWS_WITH(validate(p), Catch::Contains("steps[2] differs from steps[0]"));
  }
  SECTION("per-node statistics") {
    p.node_data = true;
    REQUIRE_THROWS_WITH(validate(p), Catch::Contains("node_data"));
  }
  SECTION("more than 64 lanes") {
    p.K = std::vector<double>(33, 10.0);
    REQUIRE_THROWS_WITH(
        validate(p), Catch::Contains("33 K x 2 replicas") && Catch::Contains("at most 64 lanes"));
    p.K.resize(32);
    REQUIRE_NOTHROW(validate(p));
  }
}
