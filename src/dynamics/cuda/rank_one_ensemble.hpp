#pragma once
// Replicas of the HMF with a rank-one coupling A = a a^T, with or without its diagonal
// (rank_one_force.hpp; the complete graph K_N is a = 1), stepped on a CUDA device with the CPU's
// bits: Z = sum_m a_m e^{i theta_m} of each replica summed as the CPU sums it (2048-row blocks,
// each from 0 in row order, the terms staged in shared memory and added by one thread per block
// and replica, then the blocks in order), then
// each cell's y_n = a_n Z - [no diagonal] a_n^2 e^{i theta_n}, g and the observables' terms with
// rank_one_force.cpp's functions (kernel_arithmetic.hpp). The stages, the closing kick and the
// sums are every device ensemble's (device_ensemble.hpp), so `hmfnet simulate --device cuda` on K_N
// is the CPU's run bit for bit. For a finite-size campaign of many small systems at once,
// CompleteGraphEnsembles (one block per replica for many steps) is the faster tool.
//
// A plain C++ interface: no CUDA header reaches the caller.
#include <cstdint>
#include <vector>

#include "dynamics/cuda/device_ensemble.hpp"
#include "dynamics/cuda/rank_exchange.hpp"

namespace hmfnet::cuda {

class RankOneEnsemble : public DeviceEnsemble {
 public:
  /// `a`: the whole vector (rows = a.size()); `diagonal`: A_nn = a_n^2 stored (false: K_N
  /// without self-loops). Throws DeviceError before any allocation when the device memory does
  /// not suffice, and where no device can run this build.
  RankOneEnsemble(const std::vector<double>& a, bool diagonal, int replicas,
                  int threads_per_block = 256);
  /// One MPI rank's rows of A = a a^T spread over ranks: `a` holds this rank's rows' a_n, and
  /// each evaluation sums this rank's Z (its rows' blocks, as rank_one_force.cpp) over the ranks
  /// with `ranks.sum_over_ranks` (2 x replicas doubles through the host), N from
  /// `ranks.global_rows`.
  RankOneEnsemble(const std::vector<double>& a, bool diagonal, int replicas, RankExchange ranks,
                  int threads_per_block = 256);

  /// The device memory `rows` rotors and `replicas` lanes need, and what is free.
  static DeviceMemory memory(std::int64_t rows, int replicas);

  struct Impl;  ///< the device side (rank_one_ensemble.cu)
};

}  // namespace hmfnet::cuda
