// The rank-one force on the device (rank_one_ensemble.hpp): Z by blocks in the CPU's order, then
// one thread per cell for y_n, g and the terms. Compiled with --fmad=false (kernel_arithmetic.hpp
// says why).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/cuda/ensemble_cells.cuh"
#include "dynamics/cuda/rank_one_ensemble.hpp"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

// OrderedColumnSums::k_block_rows: rank_one_force.cpp sums Z by these blocks.
constexpr std::int64_t k_z_block_rows = 2048;

// Rows a tile stages and replicas a CUDA block sums (z_blocks_kernel).
constexpr int k_z_tile_rows = 128;
constexpr int k_z_group = 16;
constexpr int k_z_threads = 256;

// One (block, group of up to 16 replicas): each replica's share of Z summed from 0 over the
// block's rows in order, as rank_one_force.cpp's z_block (a_m cos, a_m sin). The sum is a chain
// of dependent additions that must keep the CPU's order; a thread that also loaded each term
// waited on memory at every row (8% of the stream bound, measured on an H200). So the CUDA
// block's threads stage a tile of rows x replicas products into shared memory, coalesced and
// with many loads in flight, and then one thread per replica adds the tile's rows in order.
// Each product is rounded once before its addition (--fmad=false), as in the CPU's loop: the
// same bits.
__global__ void __launch_bounds__(k_z_threads)
    z_blocks_kernel(const double* a, const double* cs, std::int64_t rows, int replicas,
                    double* partial) {
  __shared__ double2 tile[k_z_tile_rows * k_z_group];
  const std::int64_t block = blockIdx.x;
  const int b0 = static_cast<int>(blockIdx.y) * k_z_group;
  const int group = replicas - b0 < k_z_group ? replicas - b0 : k_z_group;
  const std::int64_t begin = block * k_z_block_rows;
  const std::int64_t end = begin + k_z_block_rows < rows ? begin + k_z_block_rows : rows;
  const int j = static_cast<int>(threadIdx.x);
  double re = 0.0, im = 0.0;
  for (std::int64_t r0 = begin; r0 < end; r0 += k_z_tile_rows) {
    const int tile_rows = end - r0 < k_z_tile_rows ? static_cast<int>(end - r0) : k_z_tile_rows;
    for (int t = j; t < tile_rows * group; t += k_z_threads) {
      const int r = t / group;
      const std::int64_t k = (r0 + r) * replicas + b0 + t % group;
      const double ar = a[r0 + r];
      tile[r * k_z_group + t % group] = make_double2(ar * cs[2 * k], ar * cs[2 * k + 1]);
    }
    __syncthreads();
    if (j < group) {
      for (int r = 0; r < tile_rows; ++r) {
        const double2 v = tile[r * k_z_group + j];
        re += v.x;
        im += v.y;
      }
    }
    __syncthreads();
  }
  if (j < group) {
    const std::int64_t i = block * replicas + b0 + j;
    partial[2 * i] = re;
    partial[2 * i + 1] = im;
  }
}

// Z of each replica: the blocks' shares added from 0 in block order (OrderedColumnSums::
// add_blocks). One thread per replica.
__global__ void z_total_kernel(const double* partial, std::int64_t blocks, int replicas,
                               double* z) {
  const int b = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (b >= replicas) return;
  double re = 0.0, im = 0.0;
  for (std::int64_t block = 0; block < blocks; ++block) {
    re += partial[2 * (block * replicas + b)];
    im += partial[2 * (block * replicas + b) + 1];
  }
  z[2 * b] = re;
  z[2 * b + 1] = im;
}

struct FieldArgs {
  const double* a;
  const double* cs;
  const double* z;
  int replicas;
  std::int64_t cells;
  double inverse_n;
  bool diagonal;
  double* g;
  double* terms;   // nullptr, or cells x [|y_n|, Re(e^{-i theta_n} y_n)]
  double* fields;  // nullptr, or cells x [Re y_n, Im y_n] (node data)
};

// rank_one_force.cpp's field_one for one cell.
__global__ void __launch_bounds__(1024) field_kernel(FieldArgs f) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= f.cells) return;
  const std::int64_t row = k / f.replicas;
  const int b = static_cast<int>(k % f.replicas);
  const double c = f.cs[2 * k], s = f.cs[2 * k + 1];
  const LocalField y = rank_one_field(f.a[row], f.z[2 * b], f.z[2 * b + 1], c, s, f.diagonal);
  f.g[k] = coupling_force(f.inverse_n, c, s, y);
  if (f.terms != nullptr) {
    f.terms[2 * k] = order_term(y);
    f.terms[2 * k + 1] = coupling_term(c, s, y);
  }
  if (f.fields != nullptr) {
    f.fields[2 * k] = y.re;
    f.fields[2 * k + 1] = y.im;
  }
}

std::int64_t z_blocks(std::int64_t rows) { return (rows + k_z_block_rows - 1) / k_z_block_rows; }

}  // namespace

struct RankOneEnsemble::Impl : EnsembleCells {
  Impl(std::int64_t rows, int replicas, bool diag, int threads)
      : EnsembleCells(rows, replicas, false, threads),
        diagonal(diag),
        inverse_n(1.0 / static_cast<double>(rows)) {}
  bool diagonal;
  double inverse_n;  // 1 / N, N over all ranks
  DeviceBuffer<double> a, z_partial, z;
  RankExchange ranks;          // over ranks: Z's sum over them
  std::vector<double> host_z;  // its host copy

  void evaluate(bool with_terms) override {
    const dim3 grid(static_cast<unsigned>(z_blocks(m_rows)),
                    static_cast<unsigned>((m_replicas + k_z_group - 1) / k_z_group));
    z_blocks_kernel<<<grid, k_z_threads>>>(a.data(), m_cs.data(), m_rows, m_replicas,
                                           z_partial.data());
    check_launch("Z blocks kernel");
    z_total_kernel<<<blocks_for(static_cast<std::size_t>(m_replicas), 64), 64>>>(
        z_partial.data(), z_blocks(m_rows), m_replicas, z.data());
    check_launch("Z total kernel");
    if (ranks.sum_over_ranks) {
      // rank_one_force.cpp's reduce_z: this rank's Z, then the sum over ranks.
      z.download(host_z.data(), host_z.size());
      ranks.sum_over_ranks(host_z.data(), static_cast<int>(host_z.size()));
      z.upload(host_z.data(), host_z.size());
    }
    const FieldArgs f{a.data(),   m_cs.data(), z.data(),   m_replicas,
                      cells(),    inverse_n,   diagonal,   m_g.data(),
                      with_terms ? m_terms.data() : nullptr, fields_out()};
    field_kernel<<<cell_blocks(), tpb()>>>(f);
    check_launch("rank-one field kernel");
  }
};

DeviceMemory RankOneEnsemble::memory(std::int64_t rows, int replicas) {
  DeviceMemory m;
  m.needed = static_cast<std::size_t>(rows) * sizeof(double) +
             static_cast<std::size_t>(z_blocks(rows) + 1) * 2 * static_cast<std::size_t>(replicas) *
                 sizeof(double) +
             EnsembleCells::bytes(rows, replicas, false);
  std::size_t total = 0;
  check(cudaMemGetInfo(&m.free, &total), "cudaMemGetInfo");
  return m;
}

namespace {

std::unique_ptr<RankOneEnsemble::Impl> rank_one_cells(const std::vector<double>& a, bool diagonal,
                                                      int replicas, RankExchange ranks,
                                                      int threads_per_block) {
  const auto rows = static_cast<std::int64_t>(a.size());
  if (ranks.global_rows != 0 && ranks.global_rows < rows) {
    throw DeviceError("rank-one ensemble: N = " + std::to_string(ranks.global_rows) +
                      " over all ranks is below this rank's " + std::to_string(rows) + " rows");
  }
  // z_blocks_kernel's groups of replicas lie on the grid's y, at most 65535 of them.
  if (replicas > 65535 * k_z_group) {
    throw DeviceError("rank-one ensemble: " + std::to_string(replicas) + " replicas, more than " +
                      std::to_string(65535 * k_z_group) + " (" + std::to_string(k_z_group) +
                      " a CUDA block, 65535 blocks)");
  }
  auto impl = std::make_unique<RankOneEnsemble::Impl>(rows, replicas, diagonal, threads_per_block);
  require_device();
  require_memory(RankOneEnsemble::memory(rows, replicas).needed, "the rank-one ensemble");
  impl->a.upload(a.data(), a.size());
  impl->z_partial.allocate(static_cast<std::size_t>(z_blocks(rows) * 2 * replicas));
  impl->z.allocate(static_cast<std::size_t>(2 * replicas));
  if (ranks.global_rows > 0) impl->inverse_n = 1.0 / static_cast<double>(ranks.global_rows);
  if (ranks.sum_over_ranks) impl->host_z.assign(static_cast<std::size_t>(2 * replicas), 0.0);
  impl->ranks = std::move(ranks);
  impl->allocate();
  return impl;
}

}  // namespace

RankOneEnsemble::RankOneEnsemble(const std::vector<double>& a, bool diagonal, int replicas,
                                 int threads_per_block)
    : DeviceEnsemble(rank_one_cells(a, diagonal, replicas, {}, threads_per_block)) {}

RankOneEnsemble::RankOneEnsemble(const std::vector<double>& a, bool diagonal, int replicas,
                                 RankExchange ranks, int threads_per_block)
    : DeviceEnsemble(rank_one_cells(a, diagonal, replicas, std::move(ranks), threads_per_block)) {}

}  // namespace hmfnet::cuda
