#pragma once
// Replicas of the HMF on one network, stepped on a CUDA device: the state (theta, p) of every
// rotor and replica lives on the device, and each step is the CPU's (integrator.cpp: kick_drift,
// kick; network_force.cpp: the rows' sum) cell by cell, with the host-and-device arithmetic of
// dynamics/kernel_arithmetic.hpp. In float64 and float32 the device therefore computes the CPU's
// bits (tests/gpu/test_sparse_ensemble.cpp checks it against a host run of the same functions).
//
// A plain C++ interface: no CUDA header reaches the caller (cmake/HmfnetCuda.cmake).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/cuda/device.hpp"
#include "dynamics/splitting_coefficients.hpp"

namespace hmfnet::cuda {

/// The gathered [cos, sin] table and the row sums in double or in float (ForcePrecision).
enum class DevicePrecision { float64, float32 };

/// A network's rows in CSR on the host: offsets has rows + 1 entries, columns index [0, rows).
/// 0/1 entries (no weights).
struct HostCsr {
  std::int64_t rows = 0;
  std::vector<std::int64_t> offsets;
  std::vector<std::int32_t> columns;
};

/// Per replica, the sums the observables need (coupling_force.hpp): sum_n |y_n| (R = that /
/// sum_n d_n), sum_n Re(e^{-i theta_n} y_n) (potential -K / (2N) that), sum_n p_n,
/// sum_n p_n^2 / 2 (kinetic) and sum_n |p_n| (the momentum drift's scale). Each column summed in
/// OrderedColumnSums' order (blocks of 2048 rows in order, then the blocks in order).
struct EnsembleSums {
  std::vector<double> order, coupling, momentum, kinetic, momentum_scale;
};

/// Device memory in bytes: what a SparseEnsemble of this size allocates, and what the device
/// has free now.
struct DeviceMemory {
  std::size_t needed = 0;
  std::size_t free = 0;
};

class SparseEnsemble {
 public:
  /// Copies `network` to device 0 for `replicas` lanes (cells = rows x replicas, node-major as
  /// RotorState). Throws DeviceError before any allocation when the device memory does not
  /// suffice (naming the bytes needed and free), and where no device can run this build.
  /// threads_per_block: of every cell kernel (the results do not depend on it).
  SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                 int threads_per_block = 256);
  /// A network generated on the device: the directed Erdos-Renyi graph G(N, p = degree / N)
  /// (each ordered pair, self-pairs included, an edge with probability p, independently;
  /// columns sorted), drawn from `seed` by a counter-based generator per row. For benchmarks of
  /// sizes whose CSR would not fit the host's memory or time (N = 10^7: 10^9 entries).
  static SparseEnsemble directed_er(std::int64_t rows, double degree, std::uint64_t seed,
                                    int replicas, DevicePrecision precision,
                                    int threads_per_block = 256);
  ~SparseEnsemble();
  SparseEnsemble(SparseEnsemble&&) noexcept;
  SparseEnsemble& operator=(SparseEnsemble&&) noexcept;
  SparseEnsemble(const SparseEnsemble&) = delete;
  SparseEnsemble& operator=(const SparseEnsemble&) = delete;

  /// The memory a network of `rows` rows, `entries` stored entries and `replicas` lanes needs.
  static DeviceMemory memory(std::int64_t rows, std::int64_t entries, int replicas,
                             DevicePrecision precision);

  std::int64_t rows() const;
  std::int64_t entries() const;
  int replicas() const;

  /// The state, rows x replicas (k = n * replicas + b), then the force at it.
  void set_state(const std::vector<double>& theta, const std::vector<double>& p);
  void get_state(std::vector<double>& theta, std::vector<double>& p) const;
  /// K of each replica (--K-across-replicas); 1 for every replica until set.
  void set_coupling(const std::vector<double>& K);
  /// `steps` steps of h with the splitting's table (kicks.size() == drifts.size() + 1), each
  /// evaluation once per drift, the last kick's force kept for the next step as on the CPU.
  /// With `order` not null, each step's sum_n |y_n| per replica (the CPU force's order sums
  /// after that step: ensemble_stepper.hpp) is appended to it, steps x replicas values, summed
  /// on the device and copied once at the end.
  void advance(const SplittingCoefficients& splitting, double h, std::int64_t steps,
               std::vector<double>* order = nullptr);
  /// The sums at the current state.
  EnsembleSums sums();
  /// Waits for the device and reports the first error of its queue.
  void synchronize() const;

 private:
  struct Impl;
  explicit SparseEnsemble(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> m_impl;
};

}  // namespace hmfnet::cuda
