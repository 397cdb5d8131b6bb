#pragma once
// MPI + Kokkos lifetime for the whole program (Tpetra::ScopeGuard behind a plain interface).
// Create one in main() before any distributed object and let it outlive them all: without it,
// `mpirun -np 2` silently runs two independent serial copies (TOOLCHAIN.md).
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hmfnet {

/// An error every rank knows of: thrown on every rank by ParallelSession::agree with the message
/// of the lowest rank that failed, so the program reports it once (on rank 0) and every rank
/// exits with it instead of waiting for the failed one in the next collective.
class CollectiveError : public std::runtime_error {
 public:
  CollectiveError(const std::string& message, int failed_rank)
      : std::runtime_error(message), m_failed_rank(failed_rank) {}
  int failed_rank() const { return m_failed_rank; }

 private:
  int m_failed_rank;
};

class ParallelSession {
 public:
  ParallelSession(int* argc, char*** argv);
  ~ParallelSession();
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;

  /// This process's rank and the number of ranks in the default communicator.
  static int rank();
  static int ranks();
  /// Whether a launcher (mpirun, mpiexec, srun) started this process; if not, it runs as an
  /// isolated singleton (parallel_session.cpp).
  static bool started_by_launcher();
  /// Sum / max over all ranks (identity on one rank).
  static double sum(double local);
  static double max(double local);
  /// Element-wise sum over ranks, in place (one reduction for the whole vector).
  static void sum_in_place(std::vector<double>& values);
  /// Element-wise max over ranks, in place (one reduction; a min is the max of the negated).
  static void max_in_place(std::vector<double>& values);
  /// Element-wise sum modulo 2^64 (hash signatures), in place.
  static void sum_in_place(std::vector<std::uint64_t>& values);

  /// Each rank's value, indexed by rank, on every rank. Collective.
  static std::vector<std::int64_t> all_gather(std::int64_t mine);

  /// The ranks on this rank's machine (same host name): how many, and this rank's place among
  /// them in rank order (0 first). Collective.
  struct MachineRanks {
    int index = 0;
    int count = 1;
  };
  static MachineRanks machine_ranks();

  /// Point to point and from one rank to all (length travels first). Blocking.
  static void send(const std::vector<std::int64_t>& values, int destination);
  static std::vector<std::int64_t> receive(int source);
  static void broadcast(std::vector<std::int64_t>& values, int root);
  static void broadcast(std::string& text, int root);
  static void barrier();

  /// Each rank's peak resident memory so far (getrusage maxrss), in MB, indexed by rank, on
  /// every rank. Collective.
  static std::vector<double> peak_memory_mb();
  /// This rank's own peak resident memory so far, MB (not collective).
  static double own_peak_memory_mb();

  /// Runs a step that may fail on some ranks only (a read of this rank's part of a file, an
  /// allocation). Collective: when it throws on any rank, every rank throws CollectiveError with
  /// the message of the lowest rank that failed; otherwise every rank returns normally.
  static void agree(const std::function<void()>& step);

 private:
  struct Guard;
  std::unique_ptr<Guard> m_guard;
};

}  // namespace hmfnet
