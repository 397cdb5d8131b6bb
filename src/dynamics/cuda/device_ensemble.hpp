#pragma once
// What the device's network steppers share (sparse_ensemble.hpp, rank_one_ensemble.hpp): every
// replica's state on the device as cells (row n, replica b; k = n B + b, RotorState's layout),
// stepped by a kick-drift splitting's table with the CPU's per-cell arithmetic
// (kernel_arithmetic.hpp), each step's order sums and a record's sums in OrderedColumnSums'
// order. A stepper adds its force (ensemble_cells.cuh).
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

/// A network's rows in CSR on the host: offsets has rows + 1 entries, columns index the column
/// space [0, column_count) (one rank: the rows themselves; over ranks: DistributedNetwork::
/// LocalAdjacency's, the owned rows and the ghosts in ascending global order), weights A_nm
/// (the float32 table sums them as floats, as network_force.cpp does) or none.
struct HostCsr {
  std::int64_t rows = 0;
  std::vector<std::int64_t> offsets;
  std::vector<std::int32_t> columns;
  std::vector<double> weights;    ///< one per column entry, or empty: 0/1 entries
  std::int64_t column_count = 0;  ///< the column space's size; 0: rows (the columns are the rows)
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

class EnsembleCells;  // ensemble_cells.cuh

class DeviceEnsemble {
 public:
  virtual ~DeviceEnsemble();
  DeviceEnsemble(DeviceEnsemble&&) noexcept;
  DeviceEnsemble& operator=(DeviceEnsemble&&) noexcept;
  DeviceEnsemble(const DeviceEnsemble&) = delete;
  DeviceEnsemble& operator=(const DeviceEnsemble&) = delete;

  std::int64_t rows() const;
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
  /// From now on every evaluation also keeps each cell's y_n on the device (2 doubles a cell,
  /// checked against the free memory), for `fields`: node data read them every step.
  void keep_fields();
  /// y_n at the current state, rows x replicas x [Re, Im] (CouplingForce::local_fields's
  /// layout and bits). Throws DeviceError unless keep_fields was called.
  void fields(std::vector<double>& y) const;
  /// Waits for the device and reports the first error of its queue.
  void synchronize() const;

 protected:
  explicit DeviceEnsemble(std::unique_ptr<EnsembleCells> cells);
  EnsembleCells& cells() const { return *m_cells; }

 private:
  std::unique_ptr<EnsembleCells> m_cells;
};

}  // namespace hmfnet::cuda
