#pragma once
// How many OpenMP threads a simulation step uses when the user does not say. A step runs several
// parallel loops (kicks, drifts, sincos, the row pass, the sums), each a fork and a join; a
// thread that joins a loop of little work costs more at the barrier than it computes, and far
// more when OMP_WAIT_POLICY=PASSIVE puts waiting threads to sleep (a futex wake per loop). So the
// default gives each thread at least k_work_per_thread stored entries x replicas of a force
// evaluation (measured: bench/thread_rule.sh, README "Threads").
#include <cstdint>

namespace hmfnet {

/// Stored entries x replicas per thread of a step. Measured on the 2-core development machine
/// (bench/thread_rule.sh, OMP_WAIT_POLICY unset, ACTIVE and PASSIVE, one idle run): ER with 10^4
/// entries ran 0.4-1.2x as fast on 2 threads as on 1 (slower under ACTIVE and PASSIVE), with 10^5
/// entries 1.1-1.7x, with 2 x 10^6 and more 1.4-2.0x; so a second thread from 10^5 on.
inline constexpr std::int64_t k_work_per_thread = 50'000;

/// floor(work / k_work_per_thread) threads, at least 1 and at most `available` (>= 1).
int default_threads(std::int64_t work, int available);

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
