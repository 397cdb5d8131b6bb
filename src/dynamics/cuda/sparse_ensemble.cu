// The sparse ensemble's kernels and memory (sparse_ensemble.hpp). One thread per cell (row n,
// replica b; k = n B + b) in every kernel, each doing what the CPU does for that cell, in the
// CPU's order: the results do not depend on the launch configuration. Compiled with
// --fmad=false (kernel_arithmetic.hpp says why).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cub/device/device_scan.cuh>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/cuda/sparse_ensemble.hpp"
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

template <typename T>
struct ForceArgs {
  const std::int64_t* offsets;
  const std::int32_t* columns;
  const T* table;  // cells x [cos, sin] in T
  const double* cs;
  int replicas;
  std::int64_t cells;
  double inverse_n;
  double* g;
  double* terms;  // nullptr, or cells x [|y_n|, Re(e^{-i theta_n} y_n)]
};

// g of one cell from its row's sum (network_force.cpp's rows kernels, kernel_arithmetic.hpp).
template <typename T>
__global__ void __launch_bounds__(1024) force_kernel(ForceArgs<T> a) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= a.cells) return;
  const std::int64_t row = k / a.replicas;
  const int lane = static_cast<int>(k % a.replicas);
  const LocalField y = row_field<T, std::int64_t, std::int32_t>(
      a.offsets[row], a.offsets[row + 1], a.columns, static_cast<const T*>(nullptr), a.table,
      a.replicas, lane);
  const double c = a.cs[2 * k], s = a.cs[2 * k + 1];
  a.g[k] = coupling_force(a.inverse_n, c, s, y);
  if (a.terms != nullptr) {
    a.terms[2 * k] = order_term(y);
    a.terms[2 * k + 1] = coupling_term(c, s, y);
  }
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

// The directed G(N, p) row by row: geometric gaps between successive columns, from a
// SplitMix64 stream keyed by (seed, row). The same function counts (out == nullptr) and fills.
__device__ std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

__device__ std::int64_t er_row(std::uint64_t seed, std::int64_t row, std::int64_t n, double log_q,
                               std::int32_t* out, std::int64_t room) {
  std::uint64_t state = mix(seed ^ mix(static_cast<std::uint64_t>(row) + 0x9e3779b97f4a7c15ULL));
  std::int64_t column = -1, count = 0;
  for (;;) {
    state += 0x9e3779b97f4a7c15ULL;
    // u in (0, 1]: a gap of floor(ln u / ln(1 - p)) non-edges before the next edge.
    const double u = static_cast<double>((mix(state) >> 11) + 1) * 0x1.0p-53;
    const double gap = std::floor(std::log(u) / log_q);
    if (!(gap < static_cast<double>(n))) break;
    column += 1 + static_cast<std::int64_t>(gap);
    if (column >= n) break;
    if (out != nullptr && count < room) out[count] = static_cast<std::int32_t>(column);
    ++count;
  }
  return count;
}

__global__ void er_count_kernel(std::uint64_t seed, std::int64_t n, double log_q,
                                std::int64_t* counts) {
  const std::int64_t row = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (row > n) return;
  counts[row] = row < n ? er_row(seed, row, n, log_q, nullptr, 0) : 0;
}

__global__ void er_fill_kernel(std::uint64_t seed, std::int64_t n, double log_q,
                               const std::int64_t* offsets, std::int32_t* columns) {
  const std::int64_t row = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (row >= n) return;
  // The same draw as the count; `room` only guards the row's slice.
  er_row(seed, row, n, log_q, columns + offsets[row], offsets[row + 1] - offsets[row]);
}

std::size_t state_bytes(std::int64_t rows, int replicas, DevicePrecision precision) {
  const auto cells = static_cast<std::size_t>(rows) * static_cast<std::size_t>(replicas);
  // theta, p, g, cs (2), terms (2), the kinetic and |p| scratch, and the float32 table.
  const std::size_t per_cell =
      9 * sizeof(double) + (precision == DevicePrecision::float32 ? 2 * sizeof(float) : 0);
  return cells * per_cell;
}

}  // namespace

struct SparseEnsemble::Impl {
  std::int64_t rows = 0;
  std::int64_t entries = 0;
  int replicas = 1;
  DevicePrecision precision = DevicePrecision::float64;
  int threads = 256;
  DeviceBuffer<std::int64_t> offsets;
  DeviceBuffer<std::int32_t> columns;
  DeviceBuffer<double> theta, p, g, cs, terms, scratch, magnitude, K, partial, order_steps;
  DeviceBuffer<float> cs32;

  std::int64_t cells() const { return rows * replicas; }
  unsigned tpb() const { return static_cast<unsigned>(threads); }
  unsigned cell_blocks() const { return blocks_for(static_cast<std::size_t>(cells()), threads); }

  void allocate_state() {
    const auto c = static_cast<std::size_t>(cells());
    theta.allocate(c);
    p.allocate(c);
    g.allocate(c);
    cs.allocate(2 * c);
    terms.allocate(2 * c);
    scratch.allocate(c);
    magnitude.allocate(c);
    if (precision == DevicePrecision::float32) cs32.allocate(2 * c);
    const std::vector<double> ones(static_cast<std::size_t>(replicas), 1.0);
    K.upload(ones.data(), ones.size());
  }

  // The force at the current [cos, sin] (g, and the terms when asked).
  void evaluate(bool with_terms) {
    if (precision == DevicePrecision::float64) {
      launch_force<double>(cs.data(), with_terms);
    } else {
      launch_force<float>(cs32.data(), with_terms);
    }
  }

  template <typename T>
  void launch_force(const T* table, bool with_terms) {
    const ForceArgs<T> a{offsets.data(),
                         columns.data(),
                         table,
                         cs.data(),
                         replicas,
                         cells(),
                         1.0 / static_cast<double>(rows),
                         g.data(),
                         with_terms ? terms.data() : nullptr};
    force_kernel<T><<<cell_blocks(), tpb()>>>(a);
    check_launch("force kernel");
  }

  void refresh() {
    sincos_kernel<<<cell_blocks(), tpb()>>>(
        theta.data(), cells(), cs.data(),
        precision == DevicePrecision::float32 ? cs32.data() : nullptr);
    check_launch("sincos kernel");
    evaluate(false);
  }

  std::int64_t sum_blocks() const { return (rows + k_sum_block_rows - 1) / k_sum_block_rows; }

  // Each block's column sums of rows x width values, into `partial`.
  void block_sums(const double* values, int width) {
    const auto n = static_cast<std::size_t>(sum_blocks() * width);
    if (partial.size() < n) partial.allocate(n);
    block_sums_kernel<<<blocks_for(n, 128), 128>>>(values, rows, width, partial.data());
    check_launch("block sums kernel");
  }

  // The order sums (sum_n |y_n| per replica) of the terms just evaluated, in OrderedColumnSums'
  // order, left on the device at `out` (replicas values).
  void order_sums_to(double* out) {
    block_sums(terms.data(), 2 * replicas);
    add_blocks_kernel<<<blocks_for(static_cast<std::size_t>(replicas), 128), 128>>>(
        partial.data(), sum_blocks(), 2 * replicas, 0, 2, replicas, out);
    check_launch("add blocks kernel");
  }

  // Column sums of rows x width values in OrderedColumnSums' order.
  std::vector<double> ordered_sums(const double* values, int width) {
    const std::int64_t blocks = sum_blocks();
    const auto n = static_cast<std::size_t>(blocks * width);
    block_sums(values, width);
    std::vector<double> host(n);
    partial.download(host.data(), n);
    std::vector<double> out(static_cast<std::size_t>(width), 0.0);
    for (std::int64_t b = 0; b < blocks; ++b) {
      for (int j = 0; j < width; ++j)
        out[static_cast<std::size_t>(j)] += host[static_cast<std::size_t>(b * width + j)];
    }
    return out;
  }
};

DeviceMemory SparseEnsemble::memory(std::int64_t rows, std::int64_t entries, int replicas,
                                    DevicePrecision precision) {
  DeviceMemory m;
  m.needed = static_cast<std::size_t>(rows + 1) * sizeof(std::int64_t) +
             static_cast<std::size_t>(entries) * sizeof(std::int32_t) +
             state_bytes(rows, replicas, precision);
  std::size_t total = 0;
  check(cudaMemGetInfo(&m.free, &total), "cudaMemGetInfo");
  return m;
}

namespace {

void check_shape(std::int64_t rows, int replicas, int threads) {
  if (rows < 1 || rows > INT32_MAX) {
    throw DeviceError("device ensemble: rows " + std::to_string(rows) + " outside [1, 2^31 - 1]");
  }
  if (replicas < 1) throw DeviceError("device ensemble: replicas must be at least 1");
  if (threads < 32 || threads > 1024 || threads % 32 != 0) {
    throw DeviceError("device ensemble: threads per block " + std::to_string(threads) +
                      " is not a multiple of 32 in [32, 1024]");
  }
}

}  // namespace

SparseEnsemble::SparseEnsemble(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}

SparseEnsemble::SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                               int threads_per_block) {
  check_shape(network.rows, replicas, threads_per_block);
  if (network.offsets.size() != static_cast<std::size_t>(network.rows + 1) ||
      network.offsets.front() != 0 ||
      network.offsets.back() != static_cast<std::int64_t>(network.columns.size())) {
    throw DeviceError("device ensemble: the CSR offsets do not match the rows and entries");
  }
  if (!std::is_sorted(network.offsets.begin(), network.offsets.end())) {
    throw DeviceError("device ensemble: the CSR offsets decrease");
  }
  for (const std::int32_t c : network.columns) {
    if (c < 0 || c >= network.rows) {
      throw DeviceError("device ensemble: column " + std::to_string(c) + " outside [0, " +
                        std::to_string(network.rows) + ")");
    }
  }
  require_device();
  const auto entries = static_cast<std::int64_t>(network.columns.size());
  require_memory(memory(network.rows, entries, replicas, precision).needed,
                 "the network's ensemble");
  m_impl = std::make_unique<Impl>();
  Impl& e = *m_impl;
  e.rows = network.rows;
  e.entries = entries;
  e.replicas = replicas;
  e.precision = precision;
  e.threads = threads_per_block;
  e.offsets.upload(network.offsets.data(), network.offsets.size());
  e.columns.upload(network.columns.data(), network.columns.size());
  e.allocate_state();
}

SparseEnsemble SparseEnsemble::directed_er(std::int64_t rows, double degree, std::uint64_t seed,
                                           int replicas, DevicePrecision precision,
                                           int threads_per_block) {
  check_shape(rows, replicas, threads_per_block);
  const double p = degree / static_cast<double>(rows);
  if (!(p > 0.0) || !(p < 1.0)) {
    throw DeviceError("directed ER: degree / rows must lie in (0, 1)");
  }
  require_device();
  // Entries are known after counting; the memory is checked first against 6 standard
  // deviations above the mean (binomial), then exactly.
  const double mean = degree * static_cast<double>(rows);
  const auto bound = static_cast<std::int64_t>(mean + 6.0 * std::sqrt(mean) + 1.0);
  if (bound > INT64_C(1) << 40) throw DeviceError("directed ER: too many entries");
  require_memory(memory(rows, bound, replicas, precision).needed +
                     static_cast<std::size_t>(rows + 1) * sizeof(std::int64_t),
                 "the directed ER ensemble");
  auto impl = std::make_unique<Impl>();
  Impl& e = *impl;
  e.rows = rows;
  e.replicas = replicas;
  e.precision = precision;
  e.threads = threads_per_block;
  const double log_q = std::log1p(-p);
  const auto n1 = static_cast<std::size_t>(rows + 1);
  DeviceBuffer<std::int64_t> counts(n1);
  er_count_kernel<<<blocks_for(n1, 256), 256>>>(seed, rows, log_q, counts.data());
  check_launch("directed ER count kernel");
  e.offsets.allocate(n1);
  std::size_t temp_bytes = 0;
  check(cub::DeviceScan::ExclusiveSum(nullptr, temp_bytes, counts.data(), e.offsets.data(),
                                      static_cast<std::int64_t>(n1)),
        "cub scan size");
  DeviceBuffer<unsigned char> temp(temp_bytes);
  check(cub::DeviceScan::ExclusiveSum(temp.data(), temp_bytes, counts.data(), e.offsets.data(),
                                      static_cast<std::int64_t>(n1)),
        "cub scan");
  check(
      cudaMemcpy(&e.entries, e.offsets.data() + rows, sizeof(std::int64_t), cudaMemcpyDeviceToHost),
      "directed ER: reading the entry count");
  e.columns.allocate(static_cast<std::size_t>(e.entries));
  er_fill_kernel<<<blocks_for(static_cast<std::size_t>(rows), 256), 256>>>(
      seed, rows, log_q, e.offsets.data(), e.columns.data());
  check_launch("directed ER fill kernel");
  check(cudaDeviceSynchronize(), "directed ER generation");
  e.allocate_state();
  return SparseEnsemble(std::move(impl));
}

SparseEnsemble::~SparseEnsemble() = default;
SparseEnsemble::SparseEnsemble(SparseEnsemble&&) noexcept = default;
SparseEnsemble& SparseEnsemble::operator=(SparseEnsemble&&) noexcept = default;

std::int64_t SparseEnsemble::rows() const { return m_impl->rows; }
std::int64_t SparseEnsemble::entries() const { return m_impl->entries; }
int SparseEnsemble::replicas() const { return m_impl->replicas; }

void SparseEnsemble::set_state(const std::vector<double>& theta, const std::vector<double>& p) {
  const auto c = static_cast<std::size_t>(m_impl->cells());
  if (theta.size() != c || p.size() != c) {
    throw DeviceError(
        "device ensemble: the state must hold rows x replicas = " + std::to_string(c) + " values");
  }
  m_impl->theta.upload(theta.data(), c);
  m_impl->p.upload(p.data(), c);
  m_impl->refresh();
}

void SparseEnsemble::get_state(std::vector<double>& theta, std::vector<double>& p) const {
  const auto c = static_cast<std::size_t>(m_impl->cells());
  theta.resize(c);
  p.resize(c);
  m_impl->theta.download(theta.data(), c);
  m_impl->p.download(p.data(), c);
}

void SparseEnsemble::set_coupling(const std::vector<double>& K) {
  if (K.size() != static_cast<std::size_t>(m_impl->replicas)) {
    throw DeviceError("device ensemble: one K per replica");
  }
  m_impl->K.upload(K.data(), K.size());
}

void SparseEnsemble::advance(const SplittingCoefficients& splitting, double h, std::int64_t steps,
                             std::vector<double>* order) {
  const auto& b = splitting.kicks;
  const auto& a = splitting.drifts;
  if (a.empty() || b.size() != a.size() + 1) {
    throw DeviceError("device ensemble: a splitting has one more kick than drifts");
  }
  Impl& e = *m_impl;
  if (steps <= 0) return;
  const auto w = static_cast<std::size_t>(e.replicas);
  if (order != nullptr && e.order_steps.size() < static_cast<std::size_t>(steps) * w) {
    e.order_steps.allocate(static_cast<std::size_t>(steps) * w);
  }
  for (std::int64_t step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const StageArgs s{
          e.theta.data(),     e.p.data(),
          e.g.data(),         e.K.data(),
          e.replicas,         e.cells(),
          step > 0 && i == 0, b.back() * h,
          b[i] * h,           a[i] * h,
          e.cs.data(),        e.precision == DevicePrecision::float32 ? e.cs32.data() : nullptr};
      stage_kernel<<<e.cell_blocks(), e.tpb()>>>(s);
      check_launch("stage kernel");
      // The step's last evaluation gives the step's order sums (the state's, up to the final
      // kick, which changes no angle): the terms are formed there when the caller asks.
      const bool last = i + 1 == a.size();
      e.evaluate(last && order != nullptr);
      if (last && order != nullptr) {
        e.order_sums_to(e.order_steps.data() + static_cast<std::size_t>(step) * w);
      }
    }
  }
  kick_kernel<<<e.cell_blocks(), e.tpb()>>>(e.p.data(), e.g.data(), e.K.data(), e.replicas,
                                            e.cells(), b.back() * h);
  check_launch("kick kernel");
  if (order != nullptr) {
    const std::size_t first = order->size();
    order->resize(first + static_cast<std::size_t>(steps) * w);
    e.order_steps.download(order->data() + first, static_cast<std::size_t>(steps) * w);
  }
}

EnsembleSums SparseEnsemble::sums() {
  Impl& e = *m_impl;
  e.evaluate(true);
  kinetic_kernel<<<e.cell_blocks(), e.tpb()>>>(e.p.data(), e.cells(), e.scratch.data(),
                                               e.magnitude.data());
  check_launch("kinetic kernel");
  const std::vector<double> terms = e.ordered_sums(e.terms.data(), 2 * e.replicas);
  EnsembleSums s;
  s.kinetic = e.ordered_sums(e.scratch.data(), e.replicas);
  s.momentum = e.ordered_sums(e.p.data(), e.replicas);
  s.momentum_scale = e.ordered_sums(e.magnitude.data(), e.replicas);
  for (int b = 0; b < e.replicas; ++b) {
    s.order.push_back(terms[static_cast<std::size_t>(2 * b)]);
    s.coupling.push_back(terms[static_cast<std::size_t>(2 * b + 1)]);
  }
  return s;
}

void SparseEnsemble::synchronize() const { check(cudaDeviceSynchronize(), "device ensemble"); }

}  // namespace hmfnet::cuda
