#pragma once
// How many OpenMP threads a simulation step uses when the user does not say. A step is one
// parallel region (team.hpp) with a few barriers; a thread that joins a step of little work costs
// more at those barriers than it computes, and far more when OMP_WAIT_POLICY=PASSIVE puts waiting
// threads to sleep (a futex wake at every barrier). So the default gives each thread at least
// work_per_thread(policy) of a step's work: gathers plus each row's own work, times the replicas
// (step_work; measured: bench/thread_rule.sh, docs/performance.md "Threads").
#include <cstdint>

namespace hmfnet {

/// How waiting OpenMP threads wait: spinning for a while (unset, ACTIVE) or asleep (PASSIVE).
enum class WaitPolicy { spinning, passive };

/// The policy of this process: PASSIVE when OMP_WAIT_POLICY says so (any case), else spinning.
WaitPolicy wait_policy_from_environment();

/// Work (step_work) per thread of a step. Measured on the 2-core development machine (AMD EPYC;
/// one idle run, `bash bench/thread_rule.sh`: ER and the complete graph, 2 threads against 1;
/// work in parentheses):
///  - spinning (unset, ACTIVE): 0.3x at ER N = 100, d = 5 (4.5 10^3), 0.6x at N = 300, d = 10
///    (1.5 10^4), 1.0x at N = 1000, d = 10 (5 10^4) and on K_N N = 1000 (4 10^4), 0.9x on K_N
///    N = 200 with 16 replicas (1.3 10^5), 1.4-1.9x from 5 10^5 on (ER N = 10^4, d = 10; K_N
///    N = 1600 with 16 replicas, N = 2 10^4): a second thread from 2 10^5 on;
///  - PASSIVE: 0.6-0.7x at 5 10^5 .. 10^6 (ER N = 10^4, d = 10; K_N N = 2 10^4; K_N N = 1600 with
///    16 replicas), 1.08x and 1.27x (two runs) at ER N = 10^4, d = 100 (1.4 10^6), 1.4-1.9x from
///    4 10^6 on (K_N N = 10^5, ER N = 10^5, d = 20 and 100): a second thread from 1.2 10^6 on.
///    The margin below is wider than the work says: k_row_work is a sparse row's cost, and a
///    rank-one row with 16 replicas costs ~0.6 of it, so K_N N = 1600's 1.02 10^6 is ~6 10^5.
inline constexpr std::int64_t k_work_per_thread_spinning = 100'000;
inline constexpr std::int64_t k_work_per_thread_passive = 600'000;

/// A row's own work in a step, in gathers of the sparse kernel (one stored entry's [cos, sin]
/// read and multiply-add): the row's sin/cos, kick and drift and its terms of the ordered sums
/// (and, on the complete graph, the rank-one force's two passes over the rows). Without it the
/// rule counted stored entries only, which undercounted a step of a sparse network of low degree
/// and of the complete graph (no stored entries: its rows were counted as entries); and since the
/// vectorised sin/cos a step of the same work takes less time, so the thresholds above grew.
/// Measured with one thread (bench/thread_rule.sh, AMD EPYC): ER N = 10^4 takes 239 us a step at
/// d = 10 and 654 us at d = 100, so a gather costs 0.46 ns and a row 19 ns besides its gathers,
/// ~41 gathers; ER N = 10^5, d = 20 says 19 ns too; the complete graph took 18 ns a row with one
/// replica (N = 2 10^4 and 10^5) and 10.7 ns a row and replica with 16 (N = 1600). Since the
/// rank-one force's fused passes (measured on an Intel Xeon) those are ~9 and ~8 ns, so the
/// rule counts a rank-one row as about twice its cost; bench/thread_rule.sh's complete-graph rows,
/// re-run then, kept the default within 1.2x of the best count except in two rows where default
/// and --threads 1 ran the same single thread (noise; docs/performance.md "Threads").
inline constexpr std::int64_t k_row_work = 40;

/// A row and replica of the complete graph's rank-one force in the same units: its sin/cos, its
/// share of the two passes (Z; g with the order and coupling sums), kick and drift. Chosen by the
/// measured two-thread choices, not derived (the per-row times come from different machines and
/// loads: 8-9 ns idle on the Intel Xeon before the AVX-512 sin/cos, 7.3 ns after it under load,
/// against a sparse row's 19 ns plus 0.46 ns a gather on the AMD EPYC). Counted at k_row_work,
/// K_N N = 400 with 16 replicas (2.6 10^5) took two threads and ran 1.28x slower than with one
/// (AMD EPYC); at 12 it takes one, and a second thread comes at N = 1100 with 16 replicas
/// (2 10^5) and N = 16,700 with one (spinning), keeping bench/thread_rule.sh's measured gains
/// (1.4x at N = 1600 with 16, 1.9x at N = 2 10^4 with one). RankOneForce::row_work gives it.
inline constexpr std::int64_t k_rank_one_row_work = 12;

/// The rule's work of one step on this rank: (gathers + row_work x rows) x replica lanes.
std::int64_t step_work(std::int64_t gathers, std::int64_t rows, std::int64_t lanes,
                       std::int64_t row_work = k_row_work);

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
