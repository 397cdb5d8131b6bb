// The sparse ensemble's force and its network (sparse_ensemble.hpp): one thread per cell (row
// n, replica b; k = n B + b) summing its row as network_force.cpp does, in the CPU's order, so the
// results do not depend on the launch configuration; the cells' stages and sums are
// ensemble_cells.cu's. Compiled with --fmad=false (kernel_arithmetic.hpp says why).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cub/device/device_scan.cuh>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/cuda/ensemble_cells.cuh"
#include "dynamics/cuda/sparse_ensemble.hpp"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

template <typename T>
struct ForceArgs {
  const std::int64_t* offsets;
  const std::int32_t* columns;
  const T* weights;  // per entry in T, or nullptr: 0/1
  const T* table;    // cells x [cos, sin] in T
  const double* cs;
  int replicas;
  std::int64_t cells;
  double inverse_n;
  double* g;
  double* terms;   // nullptr, or cells x [|y_n|, Re(e^{-i theta_n} y_n)]
  double* fields;  // nullptr, or cells x [Re y_n, Im y_n] (node data)
};

// What both force kernels do with a cell's row sum y: g, and the terms and y where asked
// (row_kernel_args.hpp's finish_row, kernel_arithmetic.hpp).
template <typename T>
__device__ void finish_cell(const ForceArgs<T>& a, std::int64_t k, const LocalField& y) {
  const double c = a.cs[2 * k], s = a.cs[2 * k + 1];
  a.g[k] = coupling_force(a.inverse_n, c, s, y);
  if (a.terms != nullptr) {
    a.terms[2 * k] = order_term(y);
    a.terms[2 * k + 1] = coupling_term(c, s, y);
  }
  if (a.fields != nullptr) {
    a.fields[2 * k] = y.re;
    a.fields[2 * k + 1] = y.im;
  }
}

// g of one cell from its row's sum (network_force.cpp's rows kernels, kernel_arithmetic.hpp).
template <typename T>
__global__ void __launch_bounds__(1024) force_kernel(ForceArgs<T> a) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= a.cells) return;
  const std::int64_t row = k / a.replicas;
  const int lane = static_cast<int>(k % a.replicas);
  finish_cell(
      a, k,
      row_field<T, std::int64_t, std::int32_t>(a.offsets[row], a.offsets[row + 1], a.columns,
                                               a.weights, a.table, a.replicas, lane));
}

// The same g with k_row_threads threads a cell (adjacent lanes of one warp): thread j sums the
// entries begin + j, begin + j + 4, ... of the row's whole groups of four (row_field's partial
// j, in its order), thread 0 then the tail; the partials are combined as row_field combines
// them, (s0 + s1) + (s2 + s3), by two shuffles: the same bits. Where a cell is a warp lane alone
// (one replica), its row's column indices are read 16 bytes at a time per lane by 32 rows at
// once; here 8 rows read theirs as 8 contiguous runs, and four times the threads gather.
constexpr int k_row_threads = 4;

template <typename T>
__global__ void __launch_bounds__(1024) force_kernel_split(ForceArgs<T> a) {
  const std::int64_t t = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const std::int64_t k = t / k_row_threads;
  const int j = static_cast<int>(t % k_row_threads);
  const bool live = k < a.cells;
  T c_part = T(0), s_part = T(0);
  std::int64_t row = 0;
  int lane = 0;
  if (live) {
    row = k / a.replicas;
    lane = static_cast<int>(k % a.replicas);
    const std::int64_t begin = a.offsets[row], end = a.offsets[row + 1];
    const std::int64_t full = begin + (end - begin) / 4 * 4;
    const auto add = [&](std::int64_t q) {
      const T* r = a.table + 2 * static_cast<std::ptrdiff_t>(a.columns[q]) * a.replicas + 2 * lane;
      const T w = a.weights != nullptr ? a.weights[q] : T(1);
      c_part += w * r[0];
      s_part += w * r[1];
    };
    for (std::int64_t q = begin + j; q < full; q += 4) add(q);
    if (j == 0) {
      for (std::int64_t q = full; q < end; ++q) add(q);
    }
  }
  // Every lane of the warp takes part in the shuffles (blockDim is a multiple of 32).
  constexpr unsigned all = 0xffffffffu;
  const T c_pair = c_part + __shfl_down_sync(all, c_part, 1);  // lanes j = 0, 2: s0 + s1, s2 + s3
  const T s_pair = s_part + __shfl_down_sync(all, s_part, 1);
  const T c_sum = c_pair + __shfl_down_sync(all, c_pair, 2);
  const T s_sum = s_pair + __shfl_down_sync(all, s_pair, 2);
  if (!live || j != 0) return;
  finish_cell(a, k, LocalField{static_cast<double>(c_sum), static_cast<double>(s_sum)});
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

}  // namespace

struct SparseEnsemble::Impl : EnsembleCells {
  // Over ranks the float32 force reads the column space's table, narrowed on the host: the
  // cells keep no float32 table of their own (one 8-byte write a cell and stage less).
  Impl(std::int64_t rows, int replicas, DevicePrecision p, bool over_ranks, int threads)
      : EnsembleCells(rows, replicas, p == DevicePrecision::float32 && !over_ranks, threads),
        precision(p),
        threads_per_row(replicas == 1 ? k_row_threads : 1),
        inverse_n(1.0 / static_cast<double>(rows)) {}
  std::int64_t entries = 0;
  DevicePrecision precision;
  int threads_per_row;  // 1: force_kernel, k_row_threads: force_kernel_split
  double inverse_n;     // 1 / N, N over all ranks
  DeviceBuffer<std::int64_t> offsets;
  DeviceBuffer<std::int32_t> columns;
  DeviceBuffer<double> weights64;  // float64 weighted networks
  DeviceBuffer<float> weights32;   // float32 weighted networks (narrowed as on the CPU)
  // Over ranks: the column space's [cos, sin] (columns x replicas x 2) on the device, in the
  // table's type, and the host's copies the exchange reads and fills.
  RankExchange ranks;
  std::int64_t column_count = 0;
  DeviceBuffer<double> column64;
  DeviceBuffer<float> column32;
  std::vector<double> host_owned, host_columns;
  std::vector<float> host_columns32;

  // The force at the current [cos, sin] (g, and the terms when asked).
  void evaluate(bool with_terms) override {
    const bool over_ranks = static_cast<bool>(ranks.import_columns);
    if (over_ranks) import_columns();
    if (precision == DevicePrecision::float64) {
      launch_force<double>(over_ranks ? column64.data() : m_cs.data(),
                           weights64.size() > 0 ? weights64.data() : nullptr, with_terms);
    } else {
      launch_force<float>(over_ranks ? column32.data() : m_cs32.data(),
                          weights32.size() > 0 ? weights32.data() : nullptr, with_terms);
    }
  }

  // network_force.cpp's import: the owned rows' [cos, sin] to the host (the copy waits for the
  // stage that formed them), the exchange, and the column space back in the table's type (the
  // float32 table narrowed from the imported doubles, as network_force.cpp narrows it).
  void import_columns() {
    m_cs.download(host_owned.data(), host_owned.size());
    ranks.import_columns(host_owned.data(), 2 * m_replicas, host_columns.data());
    if (precision == DevicePrecision::float64) {
      column64.upload(host_columns.data(), host_columns.size());
      return;
    }
    for (std::size_t k = 0; k < host_columns.size(); ++k) {
      host_columns32[k] = static_cast<float>(host_columns[k]);
    }
    column32.upload(host_columns32.data(), host_columns32.size());
  }

  // The column space's buffers, where the rows are one rank's of several.
  void allocate_columns() {
    const auto values =
        2 * static_cast<std::size_t>(column_count) * static_cast<std::size_t>(m_replicas);
    host_owned.assign(2 * static_cast<std::size_t>(cells()), 0.0);
    host_columns.assign(values, 0.0);
    if (precision == DevicePrecision::float64) {
      column64.allocate(values);
    } else {
      host_columns32.assign(values, 0.0F);
      column32.allocate(values);
    }
  }

  template <typename T>
  void launch_force(const T* table, const T* weights, bool with_terms) {
    const ForceArgs<T> a{offsets.data(), columns.data(),
                         weights,        table,
                         m_cs.data(),    m_replicas,
                         cells(),        inverse_n,
                         m_g.data(),     with_terms ? m_terms.data() : nullptr,
                         fields_out()};
    if (threads_per_row == 1) {
      force_kernel<T><<<cell_blocks(), tpb()>>>(a);
    } else {
      const auto threads = static_cast<std::size_t>(cells()) * k_row_threads;
      force_kernel_split<T><<<blocks_for(threads, static_cast<int>(tpb())), tpb()>>>(a);
    }
    check_launch("force kernel");
  }
};

DeviceMemory SparseEnsemble::memory(std::int64_t rows, std::int64_t entries, int replicas,
                                    DevicePrecision precision, bool weighted,
                                    std::int64_t column_count) {
  DeviceMemory m;
  const std::size_t value_bytes =
      precision == DevicePrecision::float64 ? sizeof(double) : sizeof(float);
  const std::size_t weight_bytes = weighted ? value_bytes : 0;
  // Over ranks, the column space's table in the table's type instead of the cells' float32 one.
  const bool over_ranks = column_count > 0;
  const std::size_t column_bytes = over_ranks ? 2 * static_cast<std::size_t>(column_count) *
                                                    static_cast<std::size_t>(replicas) * value_bytes
                                              : 0;
  m.needed =
      static_cast<std::size_t>(rows + 1) * sizeof(std::int64_t) +
      static_cast<std::size_t>(entries) * (sizeof(std::int32_t) + weight_bytes) + column_bytes +
      EnsembleCells::bytes(rows, replicas, precision == DevicePrecision::float32 && !over_ranks);
  std::size_t total = 0;
  check(cudaMemGetInfo(&m.free, &total), "cudaMemGetInfo");
  return m;
}

SparseEnsemble::SparseEnsemble(std::unique_ptr<Impl> impl) : DeviceEnsemble(std::move(impl)) {}

namespace {

// The network's checks, then the device's, then the ensemble on the device.
std::unique_ptr<SparseEnsemble::Impl> copied_network(const HostCsr& network, int replicas,
                                                     DevicePrecision precision, RankExchange ranks,
                                                     int threads_per_block) {
  if (network.offsets.size() != static_cast<std::size_t>(network.rows + 1) ||
      network.offsets.front() != 0 ||
      network.offsets.back() != static_cast<std::int64_t>(network.columns.size())) {
    throw DeviceError("device ensemble: the CSR offsets do not match the rows and entries");
  }
  if (!std::is_sorted(network.offsets.begin(), network.offsets.end())) {
    throw DeviceError("device ensemble: the CSR offsets decrease");
  }
  const bool over_ranks = static_cast<bool>(ranks.import_columns);
  const std::int64_t column_count = network.column_count > 0 ? network.column_count : network.rows;
  if (!over_ranks && column_count != network.rows) {
    throw DeviceError("device ensemble: a column space of " + std::to_string(column_count) +
                      " for " + std::to_string(network.rows) +
                      " rows needs the ranks' column import");
  }
  if (column_count > INT32_MAX) {
    throw DeviceError("device ensemble: a column space of more than 2^31 - 1 columns");
  }
  if (ranks.global_rows != 0 && ranks.global_rows < network.rows) {
    throw DeviceError("device ensemble: N = " + std::to_string(ranks.global_rows) +
                      " over all ranks is below this rank's " + std::to_string(network.rows) +
                      " rows");
  }
  for (const std::int32_t c : network.columns) {
    if (c < 0 || c >= column_count) {
      throw DeviceError("device ensemble: column " + std::to_string(c) + " outside [0, " +
                        std::to_string(column_count) + ")");
    }
  }
  require_device();
  const auto entries = static_cast<std::int64_t>(network.columns.size());
  const bool weighted = !network.weights.empty();
  if (weighted && network.weights.size() != network.columns.size()) {
    throw DeviceError("device ensemble: one weight per column entry");
  }
  require_memory(SparseEnsemble::memory(network.rows, entries, replicas, precision, weighted,
                                        over_ranks ? column_count : 0)
                     .needed,
                 "the network's ensemble");
  auto e = std::make_unique<SparseEnsemble::Impl>(network.rows, replicas, precision, over_ranks,
                                                  threads_per_block);
  e->entries = entries;
  if (ranks.global_rows > 0) e->inverse_n = 1.0 / static_cast<double>(ranks.global_rows);
  e->offsets.upload(network.offsets.data(), network.offsets.size());
  e->columns.upload(network.columns.data(), network.columns.size());
  if (weighted && precision == DevicePrecision::float64) {
    e->weights64.upload(network.weights.data(), network.weights.size());
  } else if (weighted) {
    std::vector<float> narrow(network.weights.size());
    for (std::size_t k = 0; k < narrow.size(); ++k)
      narrow[k] = static_cast<float>(network.weights[k]);
    e->weights32.upload(narrow.data(), narrow.size());
  }
  if (over_ranks) {
    e->column_count = column_count;
    e->ranks = std::move(ranks);
    e->allocate_columns();
  }
  e->allocate();
  return e;
}

}  // namespace

SparseEnsemble::SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                               int threads_per_block)
    : SparseEnsemble(copied_network(network, replicas, precision, {}, threads_per_block)) {}

SparseEnsemble::SparseEnsemble(const HostCsr& network, int replicas, DevicePrecision precision,
                               RankExchange ranks, int threads_per_block)
    : SparseEnsemble(
          copied_network(network, replicas, precision, std::move(ranks), threads_per_block)) {}

SparseEnsemble SparseEnsemble::directed_er(std::int64_t rows, double degree, std::uint64_t seed,
                                           int replicas, DevicePrecision precision,
                                           int threads_per_block) {
  auto impl = std::make_unique<Impl>(rows, replicas, precision, false, threads_per_block);
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
  Impl& e = *impl;
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
  e.allocate();
  return SparseEnsemble(std::move(impl));
}

std::int64_t SparseEnsemble::entries() const { return static_cast<Impl&>(cells()).entries; }

void SparseEnsemble::set_threads_per_row(int threads) {
  if (threads != 1 && threads != k_row_threads) {
    throw DeviceError("sparse ensemble: threads per cell " + std::to_string(threads) +
                      " is neither 1 nor " + std::to_string(k_row_threads));
  }
  static_cast<Impl&>(cells()).threads_per_row = threads;
}

int SparseEnsemble::threads_per_row() const { return static_cast<Impl&>(cells()).threads_per_row; }

}  // namespace hmfnet::cuda
