#pragma once
// How many OpenMP threads a simulation step uses when the user does not say. A step is one
// parallel region (team.hpp) with a few barriers; a thread that joins a step of little work costs
// more at those barriers than it computes, and far more when OMP_WAIT_POLICY=PASSIVE puts waiting
// threads to sleep (a futex wake at every barrier). So the default gives each thread at least
// work_per_thread(policy) of a step's work: gathers plus each row's own work, times the replicas
// (step_work; measured: bench/thread_rule.sh, docs/performance.md "Threads"). A run long enough
// then times its first steps at this count, at 1 and at all the threads offered, and goes on at
// the fastest, every rank alike (step_trial.hpp; simulation.cpp: trial_inputs): this rule is its
// first candidate and the whole choice of short runs.
#include <cstdint>

namespace hmfnet {

/// How waiting OpenMP threads wait: spinning for a while (unset, ACTIVE) or asleep (PASSIVE).
enum class WaitPolicy { spinning, passive };

/// The policy of this process: PASSIVE when OMP_WAIT_POLICY says so (any case), else spinning.
WaitPolicy wait_policy_from_environment();

/// Work (step_work) per thread of a step, and the units of that work (a gather; a row's own
/// work below), set together from two machines' measurements of 2 threads against 1
/// (bench/thread_rule.sh and single `hmfnet simulate` runs; docs/performance.md "Threads" and
/// "Ordered sums side by side"), each a ratio at its work in these units:
///  - spinning (unset, ACTIVE), 2-core Intel Xeon: ER N = 2000, d = 10 0.6-0.8x (6 10^4), ER
///    N = 1500, d = 30 0.9x (7.5 10^4), K_N N = 400 with 16 replicas 0.82-0.85x (9.6 10^4), K_N
///    N = 6500 with one 1.12x (9.75 10^4) and N = 8000 1.4x (1.2 10^5), ER N = 1000, d = 100
///    1.47x (1.2 10^5), K_N N = 10^4 with one 1.31x (1.5 10^5): a second thread from 10^5 on
///    keeps each within 1.2x (the earlier 2 10^5, in units that counted a sparse row as 40 and a
///    rank-one row as 12, gave K_N N = 10^4 and ER N = 1000, d = 100 one thread: 0.76x, 0.68x);
///  - PASSIVE: 0.6-0.7x at 3 .. 4 10^5 (ER N = 10^4, d = 10; K_N N = 2 10^4 with one; K_N
///    N = 1600 with 16; Intel and AMD), 0.68x at K_N N = 6 10^4 with one (9 10^5) and 0.84x at
///    N = 8 10^4 (1.2 10^6), 1.0x at K_N N = 10^5 with one (1.5 10^6; Intel), 1.02x (Intel) and
///    1.08x and 1.27x (two runs, AMD EPYC) at ER N = 10^4, d = 100 (1,199,058 with its 999,058
///    entries), 1.6-2.0x from 4 10^6 on (ER N = 10^5, d = 20 and 100): a second thread from
///    1.16 10^6 on, which keeps ER N = 10^4, d = 100 on two (at 600,000 a thread it fell just
///    below, to one: 0.79x of the AMD's best) and K_N with one replica on one below N = 77,334.
///  Not a bound of every machine: on an AMD EPYC family 23 model 1 (2.0 GHz, KVM) a second
///  PASSIVE thread costs a step ~30 us where the Intel Xeon's costs ~250, a unit of work takes
///  ~0.9 ns where the Intel Xeon's takes ~0.3, and two threads ran 1.4-1.8x one at 1.5 .. 4 10^5:
///  these constants fail 7 of its 30 rows (0.57-0.82; docs/performance.md, "The thread rule on
///  the AMD EPYC"). A rule for both needs those two costs of the machine it runs on.
inline constexpr std::int64_t k_work_per_thread_spinning = 50'000;
inline constexpr std::int64_t k_work_per_thread_passive = 580'000;

/// A sparse row's own work in a step, in gathers (one stored entry's [cos, sin] read and added):
/// the row's sin/cos, kick and drift, its row finish and its terms of the ordered sums. From
/// single-thread step times on the Intel Xeon (spinning): ER N = 1000, d = 100 31 us, N = 2000,
/// d = 10 16 us, N = 1500, d = 30 18 us: ~0.27 ns a gather and ~5.4 ns a row, ~20 gathers. (The
/// AMD EPYC, before the vectorised sin/cos and the ordered sums side by side, gave 19 ns a row
/// and 0.46 ns a gather: ~40.)
inline constexpr std::int64_t k_row_work = 20;

/// A row and replica of the complete graph's rank-one force in the same units: its sin/cos, its
/// share of the two passes (Z; g with the order and coupling sums), kick and drift. 4.1 ns a row
/// with one replica (K_N N = 2 10^4) and 3.6 ns a row and replica with 16 (N = 2000) on the
/// Intel Xeon, ~15 gathers of 0.27 ns; with the thresholds above K_N takes a second thread from
/// N = 6667 with one replica and N = 417 with 16 (spinning; 0.82-0.85x measured at N = 400 and
/// 0.99x at N = 625 with 16), and from N = 77,334 with one under PASSIVE (0.84x at 8 10^4).
/// RankOneForce::row_work gives it.
inline constexpr std::int64_t k_rank_one_row_work = 15;

/// What one lane's gather costs against one replica's where the sparse force's wide row loops run
/// (wide_rows.hpp): an entry's index is read once for all lanes and its record added in one or
/// two registers. The inverse of the aggregate rate over float64 B = 1 (ER N = 10^4, d = 100,
/// 1 thread, Intel Xeon; docs/performance.md "Replica rows in wide registers"): float64 B = 2
/// 0.64, B = 4 0.44, B = 8 0.44; float32 B = 4 0.40, B = 8 0.32: whole steps' ratios given to
/// the gathers alone, measured in AVX-512 (AVX2 gains less), an approximation that moves the
/// crossover at d = 100 by ~20%, where either count runs within 1.2x. Counted at 1 per lane, B = 8
/// rows took a second thread under PASSIVE at ER N = 1500, d = 100, where it ran 0.72x one.
/// 1 where those loops do not serve (the baseline loops: a lane's gather was counted whole when
/// the rule was measured).
double wide_lane_gather_cost(bool float32, int lanes);

/// The same for a count the wide loops run in groups (wide_rows.hpp: wide_groups_serve): groups
/// of 8, 4 and 2 (float64) replicas at their costs above, the replicas left at 1, averaged over
/// the lanes (24: 0.44; float64 3: (2 x 0.64 + 1) / 3).
double grouped_lane_gather_cost(bool float32, int lanes);

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
