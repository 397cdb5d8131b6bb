#pragma once
// What the device's network steppers share (sparse_ensemble.cu, rank_one_ensemble.cu): every
// replica's state as cells (row n, replica b; k = n B + b, RotorState's layout), the splitting's
// stages, the closing kick and the observables' sums, one thread per cell doing the CPU's
// per-cell work in its order (kernel_arithmetic.hpp), the sums in OrderedColumnSums' order. A
// stepper adds only its force: `evaluate` forms g (and, when asked, the terms |y_n| and
// Re(e^{-i theta_n} y_n)) from the [cos, sin] of the current angles.
#include <cstdint>
#include <vector>

#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/cuda/device_ensemble.hpp"
#include "dynamics/splitting_coefficients.hpp"

namespace hmfnet::cuda {

class EnsembleCells {
 public:
  /// Throws DeviceError for rows outside [1, 2^31 - 1], no replica, or threads per block not a
  /// multiple of 32 in [32, 1024].
  EnsembleCells(std::int64_t rows, int replicas, bool float32_table, int threads_per_block);
  virtual ~EnsembleCells() = default;
  EnsembleCells(const EnsembleCells&) = delete;
  EnsembleCells& operator=(const EnsembleCells&) = delete;

  /// Device bytes of the cells' buffers.
  static std::size_t bytes(std::int64_t rows, int replicas, bool float32_table);
  /// Allocates the cells' buffers (a stepper calls it once its own are in place); K = 1.
  void allocate();

  std::int64_t rows() const { return m_rows; }
  int replicas() const { return m_replicas; }
  void set_state(const std::vector<double>& theta, const std::vector<double>& p);
  void get_state(std::vector<double>& theta, std::vector<double>& p) const;
  void set_coupling(const std::vector<double>& K);
  /// DeviceEnsemble::advance's contract.
  void advance(const SplittingCoefficients& splitting, double h, std::int64_t steps,
               std::vector<double>* order);
  EnsembleSums sums();
  /// DeviceEnsemble::keep_fields and fields.
  void keep_fields();
  void fields(std::vector<double>& y) const;

 protected:
  /// g at the current [cos, sin] (cs, and cs32 for a float32 table); with_terms: the terms too.
  virtual void evaluate(bool with_terms) = 0;
  /// Each block's column sums of rows x width values into `partial` (blocks x width).
  void block_sums(const double* values, int width);
  std::int64_t sum_blocks() const;
  std::int64_t cells() const { return m_rows * m_replicas; }
  /// Where `evaluate` writes each cell's y_n: the kept fields, or nullptr.
  double* fields_out() const { return m_fields.data(); }
  unsigned tpb() const { return static_cast<unsigned>(m_threads); }
  unsigned cell_blocks() const { return blocks_for(static_cast<std::size_t>(cells()), m_threads); }

  std::int64_t m_rows;
  int m_replicas;
  bool m_float32_table;
  int m_threads;
  DeviceBuffer<double> m_theta, m_p, m_g, m_cs, m_terms, m_scratch, m_magnitude, m_K, m_partial,
      m_order_steps;
  DeviceBuffer<float> m_cs32;

 private:
  DeviceBuffer<double> m_fields;  // cells x [Re, Im] once kept, else empty
  bool m_has_state = false;

  void refresh();
  void order_sums_to(double* out);
  std::vector<double> ordered_sums(const double* values, int width);
};

}  // namespace hmfnet::cuda
