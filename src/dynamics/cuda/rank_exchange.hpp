#pragma once
// What a device ensemble needs of the other MPI ranks when the network's rows are spread over
// them: N, for g's 1/N (eq:dMomentum_dT_orderParam), and the exchange that each force evaluation
// makes through the host, as the CPU's force makes it (network_force.cpp: the ghosts' [cos, sin]
// through one Tpetra Import; rank_one_force.cpp: Z summed over the ranks). Plain std::function:
// no MPI or Trilinos header reaches nvcc; device_stepper.cpp binds them to DistributedNetwork and
// ParallelSession, the gpu tests to threads standing for ranks (the device check's build has no
// MPI). Each is collective: every rank's ensemble calls it at the same evaluation.
#include <cstdint>
#include <functional>

namespace hmfnet::cuda {

struct RankExchange {
  /// N over all ranks; 0: the ensemble's rows are the whole network (one rank).
  std::int64_t global_rows = 0;
  /// Sparse force: fills the column space (HostCsr::column_count x width values, row-major)
  /// from the owned rows' values (rows x width), as DistributedNetwork::import_columns. Empty:
  /// the column space is the owned rows.
  std::function<void(const double* owned, int width, double* columns)> import_columns;
  /// Rank-one force: `count` values (each replica's [Re Z, Im Z]) summed over the ranks in place,
  /// the same bits on every rank, as ParallelSession::sum_in_place. Empty: one rank.
  std::function<void(double* values, int count)> sum_over_ranks;
};

}  // namespace hmfnet::cuda
