#pragma once
// Replicas of the HMF on one network, stepped on a CUDA device: the state (theta, p) of every
// rotor and replica lives on the device, and each step is the CPU's (integrator.cpp: kick_drift,
// kick; network_force.cpp: the rows' sum) cell by cell, with the host-and-device arithmetic of
// dynamics/kernel_arithmetic.hpp. In float64 and float32 the device therefore computes the CPU's
// bits (tests/gpu/test_sparse_ensemble.cpp checks it against a host run of the same functions).
//
// A plain C++ interface: no CUDA header reaches the caller (cmake/HmfnetCuda.cmake).
#include <cstdint>
#include <vector>

#include "dynamics/cuda/device_ensemble.hpp"
#include "dynamics/cuda/rank_exchange.hpp"

namespace hmfnet::cuda {

class SparseEnsemble : public DeviceEnsemble {
 public:
  /// Copies `network` to device 0 for `replicas` lanes (cells = rows x replicas, node-major as
  /// RotorState). Throws DeviceError before any allocation when the device memory does not
  /// suffice (naming the bytes needed and free), and where no device can run this build.
  /// threads_per_block: of every cell kernel (the results do not depend on it).
  SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                 int threads_per_block = 256);
  /// One MPI rank's rows of a network spread over ranks: `network` holds this rank's rows over
  /// its column space (HostCsr::column_count), whose values `ranks.import_columns` fills at
  /// each evaluation from the owned rows' [cos, sin] (copied to the host and the column space
  /// back: 16 B x replicas x (rows + column_count) an evaluation in float64; docs/scaling.md).
  /// Each row is summed in the column space's order, as network_force.cpp sums it.
  SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                 RankExchange ranks, int threads_per_block = 256);
  /// A network generated on the device: the directed Erdos-Renyi graph G(N, p = degree / N)
  /// (each ordered pair, self-pairs included, an edge with probability p, independently;
  /// columns sorted), drawn from `seed` by a counter-based generator per row. For benchmarks of
  /// sizes whose CSR would not fit the host's memory or time (N = 10^7: 10^9 entries).
  static SparseEnsemble directed_er(std::int64_t rows, double degree, std::uint64_t seed,
                                    int replicas, DevicePrecision precision,
                                    int threads_per_block = 256);

  /// The memory a network of `rows` rows, `entries` stored entries and `replicas` lanes needs.
  /// `column_count` above 0: one rank's rows over ranks, with a column space of that size.
  static DeviceMemory memory(std::int64_t rows, std::int64_t entries, int replicas,
                             DevicePrecision precision, bool weighted = false,
                             std::int64_t column_count = 0);

  std::int64_t entries() const;
  /// Threads summing one cell's row: 1, or 4 (each a quarter of the row's entries, combined in
  /// the CPU's order). The results do not depend on it; 4 by default for one replica, where a
  /// warp's lanes are otherwise 32 rows reading their column indices apart.
  void set_threads_per_row(int threads);
  int threads_per_row() const;

  struct Impl;  ///< the device side (sparse_ensemble.cu)

 private:
  explicit SparseEnsemble(std::unique_ptr<Impl> impl);
};

}  // namespace hmfnet::cuda
