// The cells' kernels and the splitting's loop (ensemble_cells.cuh). Compiled with --fmad=false
// (kernel_arithmetic.hpp says why).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dynamics/cuda/ensemble_cells.cuh"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

// OrderedColumnSums::k_block_rows (ordered_sum.hpp): the observables' sums are blocked as on
// the CPU, so that they too carry the CPU's bits.
constexpr std::int64_t k_sum_block_rows = 2048;

// The [cos, sin] of every cell's angle, in double (the rows' own) and, for float32, narrowed
// (network_force.cpp: narrow).
__global__ void __launch_bounds__(1024)
    sincos_kernel(const double* theta, std::int64_t cells, double* cs, float* cs32) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= cells) return;
  double c = 0.0, s = 0.0;
  sincos_one(theta[k], c, s);
  cs[2 * k] = c;
  cs[2 * k + 1] = s;
  if (cs32 != nullptr) {
    cs32[2 * k] = static_cast<float>(c);
    cs32[2 * k + 1] = static_cast<float>(s);
  }
}

struct StageArgs {
  double* theta;
  double* p;
  const double* g;
  const double* K;
  int replicas;
  std::int64_t cells;
  bool pending;      // the previous step's last kick, not yet applied
  double c_pending;  // its b_s h
  double c_kick;     // this stage's b_i h
  double c_drift;    // this stage's a_i h
  double* cs;
  float* cs32;
};

// integrator.cpp's kick (the pending one) then kick_drift, for one cell, then the [cos, sin] of
// the new angle for the evaluation that follows.
__global__ void __launch_bounds__(1024) stage_kernel(StageArgs a) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= a.cells) return;
  const double K = a.K[k % a.replicas];
  const double g = a.g[k];
  double p = a.p[k];
  if (a.pending) p = kicked_momentum(p, a.c_pending, K, g);
  p = kicked_momentum(p, a.c_kick, K, g);
  const double theta = drifted_angle(a.theta[k], a.c_drift, p);
  a.p[k] = p;
  a.theta[k] = theta;
  double c = 0.0, s = 0.0;
  sincos_one(theta, c, s);
  a.cs[2 * k] = c;
  a.cs[2 * k + 1] = s;
  if (a.cs32 != nullptr) {
    a.cs32[2 * k] = static_cast<float>(c);
    a.cs32[2 * k + 1] = static_cast<float>(s);
  }
}

// integrator.cpp's kick alone: the last kick of an advance.
__global__ void __launch_bounds__(1024) kick_kernel(double* p, const double* g, const double* K,
                                                    int replicas, std::int64_t cells, double c) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= cells) return;
  p[k] = kicked_momentum(p[k], c, K[k % replicas], g[k]);
}

// Per cell: p^2 / 2 and |p| as the CPU's stepper forms them (host_stepper.cpp).
__global__ void __launch_bounds__(1024)
    kinetic_kernel(const double* p, std::int64_t cells, double* kinetic, double* magnitude) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= cells) return;
  kinetic[k] = 0.5 * p[k] * p[k];
  magnitude[k] = fabs(p[k]);
}

// OrderedColumnSums::sum's block partials: one thread per (block, column), rows in order from 0.
__global__ void block_sums_kernel(const double* values, std::int64_t rows, int width,
                                  double* partial) {
  const std::int64_t i = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const std::int64_t blocks = (rows + k_sum_block_rows - 1) / k_sum_block_rows;
  if (i >= blocks * width) return;
  const std::int64_t block = i / width;
  const std::int64_t column = i % width;
  const std::int64_t end =
      (block + 1) * k_sum_block_rows < rows ? (block + 1) * k_sum_block_rows : rows;
  double sum = 0.0;
  // Unrolled so that the loads run ahead of the chain of additions (in row order, as the CPU's):
  // a block's 2048 serial adds, not 2048 load latencies, set its time.
#pragma unroll 16
  for (std::int64_t r = block * k_sum_block_rows; r < end; ++r) sum += values[r * width + column];
  partial[i] = sum;
}

// OrderedColumnSums::add_blocks for `columns` of the partials' columns (every `stride`-th from
// `first`): from 0, the blocks in order. One thread per column.
__global__ void add_blocks_kernel(const double* partial, std::int64_t blocks, int width, int first,
                                  int stride, int columns, double* out) {
  const int j = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (j >= columns) return;
  double sum = 0.0;
  for (std::int64_t b = 0; b < blocks; ++b) sum += partial[b * width + first + j * stride];
  out[j] = sum;
}

}  // namespace

EnsembleCells::EnsembleCells(std::int64_t rows, int replicas, bool float32_table,
                             int threads_per_block)
    : m_rows(rows),
      m_replicas(replicas),
      m_float32_table(float32_table),
      m_threads(threads_per_block) {
  if (rows < 1 || rows > INT32_MAX) {
    throw DeviceError("device ensemble: rows " + std::to_string(rows) + " outside [1, 2^31 - 1]");
  }
  if (replicas < 1) throw DeviceError("device ensemble: replicas must be at least 1");
  if (threads_per_block < 32 || threads_per_block > 1024 || threads_per_block % 32 != 0) {
    throw DeviceError("device ensemble: threads per block " + std::to_string(threads_per_block) +
                      " is not a multiple of 32 in [32, 1024]");
  }
}

std::size_t EnsembleCells::bytes(std::int64_t rows, int replicas, bool float32_table) {
  const auto cells = static_cast<std::size_t>(rows) * static_cast<std::size_t>(replicas);
  // theta, p, g, cs (2), terms (2), the kinetic and |p| scratch, and the float32 table.
  const std::size_t per_cell = 9 * sizeof(double) + (float32_table ? 2 * sizeof(float) : 0);
  return cells * per_cell;
}

void EnsembleCells::allocate() {
  const auto c = static_cast<std::size_t>(cells());
  m_theta.allocate(c);
  m_p.allocate(c);
  m_g.allocate(c);
  m_cs.allocate(2 * c);
  m_terms.allocate(2 * c);
  m_scratch.allocate(c);
  m_magnitude.allocate(c);
  if (m_float32_table) m_cs32.allocate(2 * c);
  const std::vector<double> ones(static_cast<std::size_t>(m_replicas), 1.0);
  m_K.upload(ones.data(), ones.size());
}

void EnsembleCells::refresh() {
  sincos_kernel<<<cell_blocks(), tpb()>>>(m_theta.data(), cells(), m_cs.data(),
                                          m_float32_table ? m_cs32.data() : nullptr);
  check_launch("sincos kernel");
  evaluate(false);
}

std::int64_t EnsembleCells::sum_blocks() const {
  return (m_rows + k_sum_block_rows - 1) / k_sum_block_rows;
}

void EnsembleCells::block_sums(const double* values, int width) {
  const auto n = static_cast<std::size_t>(sum_blocks() * width);
  if (m_partial.size() < n) m_partial.allocate(n);
  block_sums_kernel<<<blocks_for(n, 128), 128>>>(values, m_rows, width, m_partial.data());
  check_launch("block sums kernel");
}

// The order sums (sum_n |y_n| per replica) of the terms just evaluated, in OrderedColumnSums'
// order, left on the device at `out` (replicas values).
void EnsembleCells::order_sums_to(double* out) {
  block_sums(m_terms.data(), 2 * m_replicas);
  add_blocks_kernel<<<blocks_for(static_cast<std::size_t>(m_replicas), 128), 128>>>(
      m_partial.data(), sum_blocks(), 2 * m_replicas, 0, 2, m_replicas, out);
  check_launch("add blocks kernel");
}

// Column sums of rows x width values in OrderedColumnSums' order.
std::vector<double> EnsembleCells::ordered_sums(const double* values, int width) {
  const std::int64_t blocks = sum_blocks();
  const auto n = static_cast<std::size_t>(blocks * width);
  block_sums(values, width);
  std::vector<double> host(n);
  m_partial.download(host.data(), n);
  std::vector<double> out(static_cast<std::size_t>(width), 0.0);
  for (std::int64_t b = 0; b < blocks; ++b) {
    for (int j = 0; j < width; ++j)
      out[static_cast<std::size_t>(j)] += host[static_cast<std::size_t>(b * width + j)];
  }
  return out;
}

void EnsembleCells::set_state(const std::vector<double>& theta, const std::vector<double>& p) {
  const auto c = static_cast<std::size_t>(cells());
  if (theta.size() != c || p.size() != c) {
    throw DeviceError(
        "device ensemble: the state must hold rows x replicas = " + std::to_string(c) + " values");
  }
  m_theta.upload(theta.data(), c);
  m_p.upload(p.data(), c);
  m_has_state = true;
  refresh();
}

void EnsembleCells::get_state(std::vector<double>& theta, std::vector<double>& p) const {
  const auto c = static_cast<std::size_t>(cells());
  theta.resize(c);
  p.resize(c);
  m_theta.download(theta.data(), c);
  m_p.download(p.data(), c);
}

void EnsembleCells::set_coupling(const std::vector<double>& K) {
  if (K.size() != static_cast<std::size_t>(m_replicas)) {
    throw DeviceError("device ensemble: one K per replica");
  }
  m_K.upload(K.data(), K.size());
}

void EnsembleCells::advance(const SplittingCoefficients& splitting, double h, std::int64_t steps,
                            std::vector<double>* order) {
  const auto& b = splitting.kicks;
  const auto& a = splitting.drifts;
  if (a.empty() || b.size() != a.size() + 1) {
    throw DeviceError("device ensemble: a splitting has one more kick than drifts");
  }
  if (steps <= 0) return;
  const auto w = static_cast<std::size_t>(m_replicas);
  if (order != nullptr && m_order_steps.size() < static_cast<std::size_t>(steps) * w) {
    m_order_steps.allocate(static_cast<std::size_t>(steps) * w);
  }
  for (std::int64_t step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const StageArgs s{
          m_theta.data(),     m_p.data(),   m_g.data(),
          m_K.data(),         m_replicas,   cells(),
          step > 0 && i == 0, b.back() * h, b[i] * h,
          a[i] * h,           m_cs.data(),  m_float32_table ? m_cs32.data() : nullptr};
      stage_kernel<<<cell_blocks(), tpb()>>>(s);
      check_launch("stage kernel");
      // The step's last evaluation gives the step's order sums (the state's, up to the final
      // kick, which changes no angle): the terms are formed there when the caller asks.
      const bool last = i + 1 == a.size();
      evaluate(last && order != nullptr);
      if (last && order != nullptr) {
        order_sums_to(m_order_steps.data() + static_cast<std::size_t>(step) * w);
      }
    }
  }
  kick_kernel<<<cell_blocks(), tpb()>>>(m_p.data(), m_g.data(), m_K.data(), m_replicas, cells(),
                                        b.back() * h);
  check_launch("kick kernel");
  if (order != nullptr) {
    const std::size_t first = order->size();
    order->resize(first + static_cast<std::size_t>(steps) * w);
    m_order_steps.download(order->data() + first, static_cast<std::size_t>(steps) * w);
  }
}

EnsembleSums EnsembleCells::sums() {
  evaluate(true);
  kinetic_kernel<<<cell_blocks(), tpb()>>>(m_p.data(), cells(), m_scratch.data(),
                                           m_magnitude.data());
  check_launch("kinetic kernel");
  const std::vector<double> terms = ordered_sums(m_terms.data(), 2 * m_replicas);
  EnsembleSums s;
  s.kinetic = ordered_sums(m_scratch.data(), m_replicas);
  s.momentum = ordered_sums(m_p.data(), m_replicas);
  s.momentum_scale = ordered_sums(m_magnitude.data(), m_replicas);
  for (int b = 0; b < m_replicas; ++b) {
    s.order.push_back(terms[static_cast<std::size_t>(2 * b)]);
    s.coupling.push_back(terms[static_cast<std::size_t>(2 * b + 1)]);
  }
  return s;
}

void EnsembleCells::keep_fields() {
  if (m_fields.size() > 0) return;
  const std::size_t n = 2 * static_cast<std::size_t>(cells());
  require_memory(n * sizeof(double), "the node data's fields");
  m_fields.allocate(n);
  // Every evaluation writes them from now on; with a state already set, one now makes them
  // current at once.
  if (m_has_state) evaluate(false);
}

void EnsembleCells::fields(std::vector<double>& y) const {
  if (m_fields.size() == 0) throw DeviceError("device ensemble: the fields were not kept");
  if (!m_has_state) throw DeviceError("device ensemble: no state set, so no fields yet");
  y.resize(m_fields.size());
  m_fields.download(y.data(), y.size());
}

DeviceEnsemble::DeviceEnsemble(std::unique_ptr<EnsembleCells> cells) : m_cells(std::move(cells)) {}
DeviceEnsemble::~DeviceEnsemble() = default;
DeviceEnsemble::DeviceEnsemble(DeviceEnsemble&&) noexcept = default;
DeviceEnsemble& DeviceEnsemble::operator=(DeviceEnsemble&&) noexcept = default;

std::int64_t DeviceEnsemble::rows() const { return m_cells->rows(); }
int DeviceEnsemble::replicas() const { return m_cells->replicas(); }

void DeviceEnsemble::set_state(const std::vector<double>& theta, const std::vector<double>& p) {
  m_cells->set_state(theta, p);
}

void DeviceEnsemble::get_state(std::vector<double>& theta, std::vector<double>& p) const {
  m_cells->get_state(theta, p);
}

void DeviceEnsemble::set_coupling(const std::vector<double>& K) { m_cells->set_coupling(K); }

void DeviceEnsemble::advance(const SplittingCoefficients& splitting, double h, std::int64_t steps,
                             std::vector<double>* order) {
  m_cells->advance(splitting, h, steps, order);
}

EnsembleSums DeviceEnsemble::sums() { return m_cells->sums(); }

void DeviceEnsemble::keep_fields() { m_cells->keep_fields(); }

void DeviceEnsemble::fields(std::vector<double>& y) const { m_cells->fields(y); }

void DeviceEnsemble::synchronize() const { check(cudaDeviceSynchronize(), "device ensemble"); }

}  // namespace hmfnet::cuda
