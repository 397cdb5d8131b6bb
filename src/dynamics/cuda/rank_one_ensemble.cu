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

// One (block, replica): Z's share summed from 0 over the block's rows in order, as
// rank_one_force.cpp's z_block (a_m cos, a_m sin). The loads are unrolled so that the chain of
// additions, not the latency of each load, sets the pace.
__global__ void z_blocks_kernel(const double* a, const double* cs, std::int64_t rows, int replicas,
                                double* partial) {
  const std::int64_t i = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const std::int64_t blocks = (rows + k_z_block_rows - 1) / k_z_block_rows;
  if (i >= blocks * replicas) return;
  const std::int64_t block = i / replicas;
  const std::int64_t b = i % replicas;
  const std::int64_t end =
      (block + 1) * k_z_block_rows < rows ? (block + 1) * k_z_block_rows : rows;
  double re = 0.0, im = 0.0;
#pragma unroll 16
  for (std::int64_t r = block * k_z_block_rows; r < end; ++r) {
    const std::int64_t k = r * replicas + b;
    re += a[r] * cs[2 * k];
    im += a[r] * cs[2 * k + 1];
  }
  partial[2 * i] = re;
  partial[2 * i + 1] = im;
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
  double* terms;  // nullptr, or cells x [|y_n|, Re(e^{-i theta_n} y_n)]
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
}

std::int64_t z_blocks(std::int64_t rows) { return (rows + k_z_block_rows - 1) / k_z_block_rows; }

}  // namespace

struct RankOneEnsemble::Impl : EnsembleCells {
  Impl(std::int64_t rows, int replicas, bool diag, int threads)
      : EnsembleCells(rows, replicas, false, threads), diagonal(diag) {}
  bool diagonal;
  DeviceBuffer<double> a, z_partial, z;

  void evaluate(bool with_terms) override {
    const auto items = static_cast<std::size_t>(z_blocks(m_rows) * m_replicas);
    z_blocks_kernel<<<blocks_for(items, 128), 128>>>(a.data(), m_cs.data(), m_rows, m_replicas,
                                                     z_partial.data());
    check_launch("Z blocks kernel");
    z_total_kernel<<<blocks_for(static_cast<std::size_t>(m_replicas), 64), 64>>>(
        z_partial.data(), z_blocks(m_rows), m_replicas, z.data());
    check_launch("Z total kernel");
    const FieldArgs f{a.data(),   m_cs.data(), z.data(),
                      m_replicas, cells(),     1.0 / static_cast<double>(m_rows),
                      diagonal,   m_g.data(),  with_terms ? m_terms.data() : nullptr};
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
                                                      int replicas, int threads_per_block) {
  const auto rows = static_cast<std::int64_t>(a.size());
  auto impl = std::make_unique<RankOneEnsemble::Impl>(rows, replicas, diagonal, threads_per_block);
  require_device();
  require_memory(RankOneEnsemble::memory(rows, replicas).needed, "the rank-one ensemble");
  impl->a.upload(a.data(), a.size());
  impl->z_partial.allocate(static_cast<std::size_t>(z_blocks(rows) * 2 * replicas));
  impl->z.allocate(static_cast<std::size_t>(2 * replicas));
  impl->allocate();
  return impl;
}

}  // namespace

RankOneEnsemble::RankOneEnsemble(const std::vector<double>& a, bool diagonal, int replicas,
                                 int threads_per_block)
    : DeviceEnsemble(rank_one_cells(a, diagonal, replicas, threads_per_block)) {}

}  // namespace hmfnet::cuda
