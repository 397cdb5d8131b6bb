#include "dynamics/ordered_sum.hpp"

#include <omp.h>

#include <algorithm>

namespace hmfnet {

namespace {

constexpr std::size_t k_block_rows = OrderedColumnSums::k_block_rows;

// A block's sum of one column is one chain of dependent additions, each waiting for the last
// (~4 cycles), so with few columns one block at a time runs at the adder's latency: ER N = 10^4
// with one replica (2 columns, 5 blocks) spent 3.8% of a two-thread leap-frog step here, 0.7%
// side by side (perf; docs/performance.md). G blocks walked side by side give G x W independent
// chains, every one still added from 0 in row order, so the bits are those of one block at a
// time.
//
// Blocks `block` .. block + G - 1 of `values` (W columns), all of 2048 rows but perhaps the last
// (the array's last block), which has `last_rows`. Their sums go to partial[(block + g) W + b].
template <std::size_t W, std::size_t G>
void sum_block_group(const double* values, std::size_t block, std::size_t last_rows,
                     double* partial) {
  double acc[G][W] = {};
  const double* first = values + block * k_block_rows * W;
  const auto add_rows = [&](std::size_t i0, std::size_t i1, std::size_t groups) {
    for (std::size_t i = i0; i < i1; ++i) {
      for (std::size_t g = 0; g < groups; ++g)
        for (std::size_t b = 0; b < W; ++b) acc[g][b] += first[(g * k_block_rows + i) * W + b];
    }
  };
  add_rows(0, last_rows, G);
  add_rows(last_rows, k_block_rows, G - 1);  // the full blocks go on past a short last one
  for (std::size_t g = 0; g < G; ++g)
    for (std::size_t b = 0; b < W; ++b) partial[(block + g) * W + b] = acc[g][b];
}

// sum_block_group with G = groups, for groups in 1 .. G.
template <std::size_t W, std::size_t G>
void sum_block_group_of(std::size_t groups, const double* values, std::size_t block,
                        std::size_t last_rows, double* partial) {
  if constexpr (G > 1) {
    if (groups < G) {
      sum_block_group_of<W, G - 1>(groups, values, block, last_rows, partial);
      return;
    }
  }
  sum_block_group<W, G>(values, block, last_rows, partial);
}

// Blocks [b0, b1) of `rows` rows, W columns: groups of up to 16 / W blocks (16 chains: twice the
// adds two ports keep in flight at a latency of 4).
template <std::size_t W>
void sum_blocks_fixed(const double* values, std::size_t rows, std::size_t b0, std::size_t b1,
                      double* partial) {
  constexpr std::size_t k_group = W >= 16 ? 1 : 16 / W;
  while (b0 < b1) {
    const std::size_t groups = std::min(k_group, b1 - b0);
    const std::size_t last = b0 + groups - 1;
    const std::size_t last_rows = std::min(rows - last * k_block_rows, k_block_rows);
    sum_block_group_of<W, k_group>(groups, values, b0, last_rows, partial);
    b0 += groups;
  }
}

// Other widths (already w >= 3 chains a row): one block at a time, the sums kept in a local
// copy of the block's partials when they fit (the shared buffer may alias `values` for the
// compiler, which then stores every addition).
void sum_blocks_any(const double* values, std::size_t rows, std::size_t w, std::size_t b0,
                    std::size_t b1, double* partial) {
  constexpr std::size_t k_local = 64;
  double acc[k_local];
  for (std::size_t blk = b0; blk < b1; ++blk) {
    const std::size_t r0 = blk * k_block_rows, r1 = std::min(rows, r0 + k_block_rows);
    for (std::size_t c0 = 0; c0 < w; c0 += k_local) {
      const std::size_t cn = std::min(k_local, w - c0);
      std::fill(acc, acc + cn, 0.0);
      for (std::size_t r = r0; r < r1; ++r)
        for (std::size_t b = 0; b < cn; ++b) acc[b] += values[r * w + c0 + b];
      std::copy(acc, acc + cn, partial + blk * w + c0);
    }
  }
}

}  // namespace

void OrderedColumnSums::prepare(std::size_t rows, int width) {
  m_rows = rows;
  m_width = static_cast<std::size_t>(width);
  m_partial.resize(blocks() * m_width);
}

void OrderedColumnSums::sum(const double* values, double* out) {
  // Each thread a contiguous range of blocks, summed side by side (sum_block_group).
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  const auto thread = static_cast<std::size_t>(omp_get_thread_num());
  const std::size_t count = blocks();
  const std::size_t b0 = count * thread / threads, b1 = count * (thread + 1) / threads;
  double* partial = m_partial.data();
  switch (m_width) {
    case 1:
      sum_blocks_fixed<1>(values, m_rows, b0, b1, partial);
      break;
    case 2:
      sum_blocks_fixed<2>(values, m_rows, b0, b1, partial);
      break;
    case 4:
      sum_blocks_fixed<4>(values, m_rows, b0, b1, partial);
      break;
    case 8:
      sum_blocks_fixed<8>(values, m_rows, b0, b1, partial);
      break;
    case 16:
      sum_blocks_fixed<16>(values, m_rows, b0, b1, partial);
      break;
    default:
      sum_blocks_any(values, m_rows, m_width, b0, b1, partial);
      break;
  }
    // Every block sum visible to the master before it adds them.
#pragma omp barrier
#pragma omp master
  add_blocks(out);
}

void OrderedColumnSums::add_blocks(double* out) const {
  const std::size_t w = m_width;
  for (std::size_t b = 0; b < w; ++b) out[b] = 0.0;
  for (std::size_t blk = 0; blk < blocks(); ++blk)
    for (std::size_t b = 0; b < w; ++b) out[b] += m_partial[blk * w + b];
}

void ordered_column_sums(const std::vector<double>& values, std::size_t rows, int width,
                         std::vector<double>& out) {
  OrderedColumnSums sums;
  sums.prepare(rows, width);
  out.assign(static_cast<std::size_t>(width), 0.0);
#pragma omp parallel
  sums.sum(values.data(), out.data());
}

}  // namespace hmfnet
