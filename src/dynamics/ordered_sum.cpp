#include "dynamics/ordered_sum.hpp"

#include <algorithm>

namespace hmfnet {

namespace {
constexpr std::size_t k_block = 2048;
}

void OrderedColumnSums::prepare(std::size_t rows, int width) {
  m_rows = rows;
  m_width = static_cast<std::size_t>(width);
  m_partial.resize((rows + k_block - 1) / k_block * m_width);
}

void OrderedColumnSums::sum(const double* values, double* out) {
  const std::size_t w = m_width;
  const std::size_t blocks = (m_rows + k_block - 1) / k_block;
  double* partial = m_partial.data();
#pragma omp for schedule(static)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    const std::size_t end = std::min(m_rows, (blk + 1) * k_block);
    for (std::size_t b = 0; b < w; ++b) partial[blk * w + b] = 0.0;
    for (std::size_t r = blk * k_block; r < end; ++r)
      for (std::size_t b = 0; b < w; ++b) partial[blk * w + b] += values[r * w + b];
  }
  // The loop's barrier above makes every block sum visible to the master.
#pragma omp master
  {
    for (std::size_t b = 0; b < w; ++b) out[b] = 0.0;
    for (std::size_t blk = 0; blk < blocks; ++blk)
      for (std::size_t b = 0; b < w; ++b) out[b] += partial[blk * w + b];
  }
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
