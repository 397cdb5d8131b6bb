#pragma once
// MPI + Kokkos lifetime for the whole program (Tpetra::ScopeGuard behind a plain interface).
// Create one in main() before any distributed object and let it outlive them all: without it,
// `mpirun -np 2` silently runs two independent serial copies (TOOLCHAIN.md).
#include <memory>
#include <vector>

namespace hmfnet {

class ParallelSession {
 public:
  ParallelSession(int* argc, char*** argv);
  ~ParallelSession();
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;

  /// This process's rank and the number of ranks in the default communicator.
  static int rank();
  static int ranks();
  /// Sum / max over all ranks (identity on one rank).
  static double sum(double local);
  static double max(double local);
  /// Element-wise sum over ranks, in place (one reduction for the whole vector).
  static void sum_in_place(std::vector<double>& values);

 private:
  struct Guard;
  std::unique_ptr<Guard> m_guard;
};

}  // namespace hmfnet
