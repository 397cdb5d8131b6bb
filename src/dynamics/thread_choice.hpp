#pragma once
// How many OpenMP threads a simulation step uses when the user does not say. A step is one
// parallel region (team.hpp) with a few barriers; a thread that joins a step of little work costs
// more at those barriers than it computes, and far more when OMP_WAIT_POLICY=PASSIVE puts waiting
// threads to sleep (a futex wake at every barrier). So the default gives each thread at least
// work_per_thread(policy) stored entries x replicas of a force evaluation (measured:
// bench/thread_rule.sh, README "Threads").
#include <cstdint>

namespace hmfnet {

/// How waiting OpenMP threads wait: spinning for a while (unset, ACTIVE) or asleep (PASSIVE).
enum class WaitPolicy { spinning, passive };

/// The policy of this process: PASSIVE when OMP_WAIT_POLICY says so (any case), else spinning.
WaitPolicy wait_policy_from_environment();

/// Stored entries x replicas per thread of a step. Measured on the 2-core development machine
/// with one region per step (one idle run each, ER, `hmfnet simulate --threads 1|2`):
///  - spinning (unset, ACTIVE): 2 threads 0.8x of 1 at 500 entries (N = 100, d = 5), 1.1-1.2x at
///    3000 (N = 300, d = 10), 1.4-1.5x at 10^4, 1.7-1.8x at 10^6: a second thread from 3000 on;
///  - PASSIVE: 2 threads 0.1-0.2x of 1 at 500-3000 entries, 0.6x at 10^4, 1.4-1.5x at 10^5 and
///    at 10^6: a second thread from 5 x 10^4 on (between the last loss and the first gain).
inline constexpr std::int64_t k_work_per_thread_spinning = 1'500;
inline constexpr std::int64_t k_work_per_thread_passive = 25'000;

/// floor(work / work per thread of `policy`) threads, at least 1 and at most `available` (>= 1).
int default_threads(std::int64_t work, int available,
                    WaitPolicy policy = wait_policy_from_environment());

/// Sets the OpenMP thread count for a scope and restores the previous one at its end.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads);
  ~ThreadCountScope();
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int m_previous;
};

}  // namespace hmfnet
