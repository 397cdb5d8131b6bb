// The default thread count follows the work per step (thread_choice.hpp): tested as a rule, by
// its choice for a few sizes, never by timing; and a run reports the count it used.
#include <omp.h>

#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/simulation.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/simulation_runs.hpp"

using namespace hmfnet;

TEST_CASE("The default thread count follows the work per step", "[threads]") {
  // The karate club (156 stored entries): one thread, however many are offered.
  CHECK(default_threads(156, 2) == 1);
  CHECK(default_threads(156, 64) == 1);
  // ER N = 1000, degree 10 (10^4 entries), where 2 threads ran slower: one.
  CHECK(default_threads(10'000, 2) == 1);
  // ER N = 10^4, degree 10 (10^5 entries), where 2 threads ran faster: two.
  CHECK(default_threads(100'000, 2) == 2);
  // ER N = 10^6, degree 100 (10^8 entries): every thread offered, and never more.
  CHECK(default_threads(100'000'000, 2) == 2);
  CHECK(default_threads(100'000'000, 1) == 1);
  CHECK(default_threads(100'000'000, 16) == 16);
  // One thread per k_work_per_thread, at the boundary.
  CHECK(default_threads(2 * k_work_per_thread - 1, 8) == 1);
  CHECK(default_threads(2 * k_work_per_thread, 8) == 2);
  CHECK(default_threads(0, 8) == 1);
  CHECK(default_threads(k_work_per_thread, 0) == 1);
}

TEST_CASE("A run reports the threads it used: the rule's, or the count it was given", "[threads]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = test::short_run();
  const int offered = omp_get_max_threads();
  CHECK(simulate(d, net.degrees(), force, p).threads == 1);  // ~2000 entries: one thread
  CHECK(omp_get_max_threads() == offered);                   // restored after the run
  p.threads = 2;
  CHECK(simulate(d, net.degrees(), force, p).threads == 2);
  p.threads = -1;
  CHECK_THROWS_AS(validate(p), ParameterError);
}
