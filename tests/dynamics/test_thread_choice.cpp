// The default thread count follows the work per step (thread_choice.hpp): tested as a rule, by
// its choice for a few sizes, never by timing; and a run reports the count it used.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/simulation.hpp"
#include "dynamics/thread_choice.hpp"
#include "dynamics/wide_rows.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/simulation_runs.hpp"

using namespace hmfnet;

TEST_CASE("The default thread count follows the work per step and the wait policy", "[threads]") {
  constexpr auto spinning = WaitPolicy::spinning, passive = WaitPolicy::passive;
  // Each row's own work counts k_row_work gathers, once per replica.
  CHECK(step_work(0, 0, 8) == 0);
  CHECK(step_work(1'000'000, 10'000, 1) == 1'000'000 + 10'000 * k_row_work);
  CHECK(step_work(500, 100, 16) == 16 * (500 + 100 * k_row_work));
  // The networks of bench/thread_rule.sh (thread_choice.hpp: 2 threads against 1 there).
  // The karate club (156 stored entries, N = 34): one thread, however many are offered.
  CHECK(default_threads(step_work(156, 34, 1), 2, spinning) == 1);
  CHECK(default_threads(step_work(156, 34, 1), 64, passive) == 1);
  // ER N = 100, d = 5 and N = 300, d = 10 (0.3x, 0.6x); N = 1000, d = 10 (1.0x): one.
  CHECK(default_threads(step_work(500, 100, 1), 2, spinning) == 1);
  CHECK(default_threads(step_work(3'000, 300, 1), 2, spinning) == 1);
  CHECK(default_threads(step_work(10'000, 1'000, 1), 2, spinning) == 1);
  // ER N = 2000, d = 10 and N = 1500, d = 30 (0.6-0.8x, 0.9x): one; N = 1000, d = 100 (1.47x),
  // which the rule in units of a 40-gather row gave one (0.68x of the best): two.
  CHECK(default_threads(step_work(20'000, 2'000, 1), 2, spinning) == 1);
  CHECK(default_threads(step_work(45'000, 1'500, 1), 2, spinning) == 1);
  CHECK(default_threads(step_work(100'000, 1'000, 1), 2, spinning) == 2);
  // ER N = 10^4, d = 10: two when spinning (1.9x, AMD EPYC), one when passive (0.7x).
  CHECK(default_threads(step_work(100'000, 10'000, 1), 2, spinning) == 2);
  CHECK(default_threads(step_work(100'000, 10'000, 1), 2, passive) == 1);
  // ER N = 10^4, d = 100 (999,058 stored entries in bench/thread_rule.sh): two under either
  // policy (passive: 1.08x and 1.27x in two runs on the AMD EPYC, 1.02x on the Intel Xeon).
  CHECK(default_threads(step_work(999'058, 10'000, 1), 2, passive) == 2);
  // ER N = 10^5, d = 20: two under either policy (1.6-1.7x when passive).
  CHECK(default_threads(step_work(2'000'000, 100'000, 1), 2, passive) == 2);
  // Eight float64 replicas in the wide row loops (a lane's gather at wide_lane_gather_cost,
  // 0.44): ER N = 1500, d = 100 under PASSIVE, one (two ran 0.72x: counted whole, the rule gave
  // two); N = 2500 and 4000, d = 100, two (1.02-1.16x and 1.17-1.25x).
  const auto eight = [](std::int64_t n, std::int64_t entries) {
    const auto gathers = static_cast<std::int64_t>(
        std::llround(static_cast<double>(entries) * wide_lane_gather_cost(false, 8)));
    return step_work(gathers, n, 8);
  };
  CHECK(default_threads(step_work(150'000, 1'500, 8), 2, passive) == 2);
  CHECK(default_threads(eight(1'500, 150'000), 2, passive) == 1);
  CHECK(default_threads(eight(2'500, 250'000), 2, passive) == 2);
  CHECK(default_threads(eight(4'000, 400'000), 2, passive) == 2);
  // The complete graph (no gathers; rows at k_rank_one_row_work): N = 200 and 400 with 16
  // replicas, one (0.9x; 0.78-0.85x at N = 400, which k_row_work gave two); N = 1600 with 16 and
  // N = 2 10^4 with one, two when spinning (1.4x and 1.9x on the AMD EPYC, 1.23x and 1.68x on
  // the Intel Xeon) and one when passive (0.6x, 0.65x); N = 10^5, two under either policy
  // (passive: 1.4x on the AMD EPYC, 1.0x on the Intel Xeon).
  const auto rank_one = [](std::int64_t n, std::int64_t replicas) {
    return step_work(0, n, replicas, k_rank_one_row_work);
  };
  CHECK(default_threads(rank_one(200, 16), 2, spinning) == 1);
  CHECK(default_threads(rank_one(400, 16), 2, spinning) == 1);
  CHECK(default_threads(rank_one(1'600, 16), 2, spinning) == 2);
  CHECK(default_threads(rank_one(1'600, 16), 2, passive) == 1);
  CHECK(default_threads(rank_one(20'000, 1), 2, spinning) == 2);
  // One replica: N = 5000 and 6500 (0.95x, 1.12x) either; N = 8000 and 10^4 (1.4x, 1.31x; a
  // rank-one row of 12 units gave N = 10^4 one thread, 0.76x of the best): two; under PASSIVE
  // N = 6 10^4 (0.68x): one.
  CHECK(default_threads(rank_one(5'000, 1), 2, spinning) == 1);
  CHECK(default_threads(rank_one(8'000, 1), 2, spinning) == 2);
  CHECK(default_threads(rank_one(10'000, 1), 2, spinning) == 2);
  CHECK(default_threads(rank_one(60'000, 1), 2, passive) == 1);
  CHECK(default_threads(rank_one(77'000, 1), 2, passive) == 1);
  CHECK(default_threads(rank_one(80'000, 1), 2, passive) == 2);  // 0.84x: within 1.2x
  CHECK(default_threads(rank_one(20'000, 1), 2, passive) == 1);
  CHECK(default_threads(rank_one(100'000, 1), 2, passive) == 2);
  // ER N = 10^6, degree 100: every thread offered, and never more.
  CHECK(default_threads(step_work(100'000'000, 1'000'000, 1), 2, passive) == 2);
  CHECK(default_threads(step_work(100'000'000, 1'000'000, 1), 1, spinning) == 1);
  CHECK(default_threads(step_work(100'000'000, 1'000'000, 1), 16, spinning) == 16);
  // One thread per work-per-thread of the policy, at the boundary.
  CHECK(default_threads(2 * k_work_per_thread_passive - 1, 8, passive) == 1);
  CHECK(default_threads(2 * k_work_per_thread_passive, 8, passive) == 2);
  CHECK(default_threads(2 * k_work_per_thread_spinning - 1, 8, spinning) == 1);
  CHECK(default_threads(2 * k_work_per_thread_spinning, 8, spinning) == 2);
  CHECK(default_threads(0, 8, spinning) == 1);
  CHECK(default_threads(k_work_per_thread_passive, 0, passive) == 1);
}

TEST_CASE("The wait policy is read from OMP_WAIT_POLICY, in any case", "[threads]") {
  const char* saved = std::getenv("OMP_WAIT_POLICY");
  const std::string kept = saved != nullptr ? saved : "";
  setenv("OMP_WAIT_POLICY", "passive", 1);
  CHECK(wait_policy_from_environment() == WaitPolicy::passive);
  setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
  CHECK(wait_policy_from_environment() == WaitPolicy::passive);
  setenv("OMP_WAIT_POLICY", "ACTIVE", 1);
  CHECK(wait_policy_from_environment() == WaitPolicy::spinning);
  unsetenv("OMP_WAIT_POLICY");
  CHECK(wait_policy_from_environment() == WaitPolicy::spinning);
  if (saved != nullptr) setenv("OMP_WAIT_POLICY", kept.c_str(), 1);
}

TEST_CASE("A run reports the threads it used: the rule's, or the count it was given", "[threads]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = test::short_run();
  const int offered = omp_get_max_threads();
  const SimulationResult r = simulate(d, net.degrees(), force, p);
  CHECK(r.threads == 1);  // ~2000 entries and 200 rows: one thread
  CHECK(r.thread_rule_work == step_work(static_cast<std::int64_t>(force.work_per_evaluation()),
                                        static_cast<std::int64_t>(d.local_size()), 1));
  CHECK(omp_get_max_threads() == offered);  // restored after the run
  p.threads = 2;
  CHECK(simulate(d, net.degrees(), force, p).threads == 2);
  p.threads = -1;
  CHECK_THROWS_AS(validate(p), ParameterError);
}

TEST_CASE("The sparse force gives the rule its lanes' gathers at the wide loops' cost",
          "[threads]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  const bool wide = wide_rows_serve<double>(8, sincos_isa());
  CHECK(force.lane_gather_cost(8) == (wide ? wide_lane_gather_cost(false, 8) : 1.0));
  CHECK(force.lane_gather_cost(1) == 1.0);
  // Counts in groups (float64 3 = 2 + 1, 24 = 8 + 8 + 8), where the CPU runs the wide loops;
  // the baseline loop's run-time width otherwise.
  const bool grouped = wide_groups_serve<double>(3, sincos_isa());
  CHECK(force.lane_gather_cost(3) ==
        (grouped ? (2 * wide_lane_gather_cost(false, 2) + 1) / 3 : 1.0));
  CHECK(force.lane_gather_cost(24) == Approx(grouped ? wide_lane_gather_cost(false, 8) : 1.0));
  // The mean over a count's groups in closed form, from the measured costs of 8 and 4 float64
  // lanes (0.44) and 4 and 8 float32 ones (0.40, 0.32); the sums here and in the function differ
  // in the order of a few roundings, hence a relative 1e-15 (a few ulps), not equality.
  CHECK(grouped_lane_gather_cost(false, 13) ==
        Approx((8 * 0.44 + 4 * 0.44 + 1.0) / 13).epsilon(1e-15));
  CHECK(grouped_lane_gather_cost(true, 7) == Approx((4 * 0.40 + 3.0) / 7).epsilon(1e-15));
  CHECK(grouped_lane_gather_cost(true, 16) == Approx(0.32).epsilon(1e-15));
  const NetworkForce narrow(d, ForcePrecision::float32);
  CHECK(narrow.lane_gather_cost(2) == 1.0);  // 16-byte records: the baseline loop
  CHECK(narrow.lane_gather_cost(8) ==
        (wide_rows_serve<float>(8, sincos_isa()) ? wide_lane_gather_cost(true, 8) : 1.0));
  SimulationParameters p = test::short_run();
  p.replicas.assign(8, p.replicas.front());
  const SimulationResult r = simulate(d, net.degrees(), force, p);
  const auto gathers = static_cast<std::int64_t>(
      std::llround(static_cast<double>(force.work_per_evaluation()) * force.lane_gather_cost(8)));
  CHECK(r.thread_rule_work == step_work(gathers, static_cast<std::int64_t>(d.local_size()), 8));
  if (wide) CHECK(r.thread_rule_work < step_work(force.work_per_evaluation(), d.local_size(), 8));
}

TEST_CASE("The rank-one force gives the rule its rows only, at their own weight, once per replica",
          "[threads]") {
  const CompleteGraph graph = CompleteGraph::make(300, false);
  const DistributedNetwork d(graph);
  RankOneForce force(complete_graph_structure(graph), d.first_row(), d.local_size());
  CHECK(force.gathers_per_evaluation() == 0);
  CHECK(force.row_work() == k_rank_one_row_work);
  SimulationParameters p = test::short_run();
  p.K = {1.0};  // K lambda / N = 1: the all-to-all HMF's scale
  p.replicas = {{6.0, 1.0, 11}, {6.0, 1.0, 12}, {6.0, 1.0, 13}};
  const SimulationResult r =
      simulate(d, std::vector<double>(std::size_t{300}, graph.degree()), force, p);
  // This rank's rows (150 each on 2 ranks) at the rank-one weight, for 3 replicas.
  CHECK(r.thread_rule_work ==
        step_work(0, static_cast<std::int64_t>(d.local_size()), 3, k_rank_one_row_work));
}
