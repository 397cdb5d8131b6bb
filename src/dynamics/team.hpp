#pragma once
// One OpenMP parallel region per time step (docs/performance.md). The integrator opens the region
// once (`in_team`), and every loop of a step (kick, drift, sin and cos, the row kernel, the ordered
// sums) is an orphaned `#pragma omp for`, or a split by thread number closed by an orphaned
// `#pragma omp barrier`, that binds to it: a step forks and joins once instead of once per loop,
// and its loops meet only at the barriers they need. The same functions called
// outside a region run serially on the calling thread (an orphaned worksharing loop then has a
// team of one, an orphaned barrier does nothing), so start-up evaluations and tests need no
// region.
//
// The rules of code that runs in a team:
//  - every thread calls the same functions in the same order (worksharing loops and barriers
//    must be met by the whole team);
//  - shared buffers are sized before the region (CouplingForce::prepare), never inside it;
//  - an exception must not leave a thread (it would end the process, and the other threads would
//    wait at the next barrier for ever): the only code that may throw (MPI and Tpetra calls) runs
//    on the master thread through `on_master`, which keeps the first exception; the team goes on
//    through the same barriers, and `in_team` rethrows it after the region.
#include <omp.h>

#include <exception>
#include <utility>

namespace hmfnet {

namespace team_detail {
// The error slot of the team the calling thread opened (the master of a team is the thread that
// opened it, so this is visible in `on_master`).
inline thread_local std::exception_ptr* t_error = nullptr;
}  // namespace team_detail

/// True outside any parallel region, active or not (a region the runtime gave one thread is
/// still a region: code in it must not throw or allocate shared buffers).
inline bool outside_team() { return omp_get_level() == 0; }

/// Runs `body` on every thread of one parallel region (or directly when one thread is allowed or
/// a region is already active) and rethrows the first exception `on_master` caught in it.
template <typename Body>
void in_team(Body&& body) {
  if (!outside_team() || omp_get_max_threads() == 1) {
    std::forward<Body>(body)();
    return;
  }
  std::exception_ptr error;
  std::exception_ptr* const outer = team_detail::t_error;
  team_detail::t_error = &error;
#pragma omp parallel
  { body(); }
  team_detail::t_error = outer;
  if (error) std::rethrow_exception(error);
}

/// `f()` on the master thread alone, with no barrier: for work whose results only the master
/// reads. Outside a region it is a plain call and its exceptions propagate; inside, the first
/// exception is kept for `in_team` to rethrow, and after a failure in this team later calls skip
/// `f()` (no further MPI exchange after a failed one).
template <typename F>
void master_only(F&& f) {
  if (outside_team()) {
    std::forward<F>(f)();
    return;
  }
#pragma omp master
  {
    try {
      if (team_detail::t_error == nullptr || !*team_detail::t_error) f();
    } catch (...) {
      // A region not opened by in_team has nowhere to carry the error to: ending the process
      // is better than results computed past a failed exchange.
      if (team_detail::t_error == nullptr) std::terminate();
      if (!*team_detail::t_error) *team_detail::t_error = std::current_exception();
    }
  }
}

/// master_only, then a barrier (so the whole team sees what `f()` wrote).
template <typename F>
void on_master(F&& f) {
  master_only(std::forward<F>(f));
#pragma omp barrier
}

}  // namespace hmfnet
