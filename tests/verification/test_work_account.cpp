// A driver's simulation cost (verification/support/work_account.hpp, simulation_cost.hpp): the
// kernel work counts stored entries x lanes over the evaluations made, so a schedule run across
// replicas in one pass costs what the same schedule run one K after another costs.
#include <catch2/catch.hpp>

#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/simulation.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/simulation_runs.hpp"
#include "support/work_account.hpp"

using namespace hmfnet;
using hmfnet::verification::cost_of;
using hmfnet::verification::SimulationCost;

TEST_CASE("cost_of: kernel work is entries x lanes x evaluations, whatever the lane layout",
          "[work_account]") {
  const Network net = erdos_renyi({300, 0.05, 4});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = test::short_run();  // 3 K, T = 4 each
  p.replicas = {{6.0, 1.0, 11}, {5.0, 0.5, 12}};
  p.continue_state = false;
  const SimulationResult seq = simulate(d, net.degrees(), force, p);
  const SimulationCost a = cost_of(p, seq);
  REQUIRE(a.simulated_time == 12.0);
  REQUIRE(a.evaluations == static_cast<double>(seq.force_evaluations));
  REQUIRE(seq.nnz_per_evaluation == net.nnz());
  REQUIRE(a.kernel_work ==
          static_cast<double>(seq.force_evaluations) * static_cast<double>(net.nnz()) * 2.0);

  p.K_across_replicas = true;  // one pass, 6 lanes
  const SimulationResult once = simulate(d, net.degrees(), force, p);
  const SimulationCost b = cost_of(p, once);
  REQUIRE(once.force_evaluations * 3 == seq.force_evaluations);
  REQUIRE(b.simulated_time == a.simulated_time);
  REQUIRE(b.evaluations == a.evaluations);  // counted as the sequential schedule's
  REQUIRE(b.kernel_work == a.kernel_work);  // the same entries x lanes, in a third of the passes
}

TEST_CASE("cost_of: the rank-one force's work is its rows", "[work_account]") {
  const CompleteGraph graph = CompleteGraph::make(200, false);
  const DistributedNetwork d(graph);
  RankOneForce force(complete_graph_structure(graph), d.first_row(), d.local_size());
  SimulationParameters p = test::short_run();
  p.K = {1.0};
  const SimulationResult r = simulate(d, std::vector<double>(200, graph.degree()), force, p);
  REQUIRE(cost_of(p, r).kernel_work == static_cast<double>(r.force_evaluations) * 200.0);
}

TEST_CASE("SimulationCost adds up and keeps the most threads", "[work_account]") {
  SimulationCost total;
  total += SimulationCost{10.0, 100.0, 1e6, 0.5, 2};
  total += SimulationCost{5.0, 50.0, 2e6, 0.25, 1};
  CHECK(total.simulated_time == 15.0);
  CHECK(total.evaluations == 150.0);
  CHECK(total.kernel_work == 3e6);
  CHECK(total.kernel_seconds == 0.75);
  CHECK(total.threads == 2);
}
