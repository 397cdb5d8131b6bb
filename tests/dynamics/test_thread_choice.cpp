// The default thread count follows the work per step (thread_choice.hpp): tested as a rule, by
// its choice for a few sizes, never by timing; and a run reports the count it used.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/simulation.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "support/simulation_runs.hpp"

using namespace hmfnet;

TEST_CASE("The default thread count follows the work per step and the wait policy", "[threads]") {
  constexpr auto spinning = WaitPolicy::spinning, passive = WaitPolicy::passive;
  // The karate club (156 stored entries): one thread, however many are offered, however threads
  // wait.
  CHECK(default_threads(156, 2, spinning) == 1);
  CHECK(default_threads(156, 64, passive) == 1);
  // ER N = 100, d = 5 (500 entries), where 2 spinning threads ran at 0.8x of one: one.
  CHECK(default_threads(500, 2, spinning) == 1);
  // ER N = 300, d = 10 (3000 entries): two when spinning (1.1-1.2x), one when passive (0.2x).
  CHECK(default_threads(3'000, 2, spinning) == 2);
  CHECK(default_threads(3'000, 2, passive) == 1);
  // ER N = 1000, d = 10 (10^4 entries): two when spinning (1.4-1.5x), one when passive (0.6x).
  CHECK(default_threads(10'000, 2, spinning) == 2);
  CHECK(default_threads(10'000, 2, passive) == 1);
  // ER N = 10^4, d = 10 (10^5 entries), where 2 passive threads ran 1.5x faster: two.
  CHECK(default_threads(100'000, 2, passive) == 2);
  // ER N = 10^6, degree 100 (10^8 entries): every thread offered, and never more.
  CHECK(default_threads(100'000'000, 2, passive) == 2);
  CHECK(default_threads(100'000'000, 1, spinning) == 1);
  CHECK(default_threads(100'000'000, 16, spinning) == 16);
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
  CHECK(simulate(d, net.degrees(), force, p).threads == 1);  // ~2000 entries: one thread
  CHECK(omp_get_max_threads() == offered);                   // restored after the run
  p.threads = 2;
  CHECK(simulate(d, net.degrees(), force, p).threads == 2);
  p.threads = -1;
  CHECK_THROWS_AS(validate(p), ParameterError);
}
