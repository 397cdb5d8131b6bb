#include "dynamics/ordered_sum.hpp"

namespace hmfnet {

void OrderedColumnSums::prepare(std::size_t rows, int width) {
  m_rows = rows;
  m_width = static_cast<std::size_t>(width);
  m_partial.resize(blocks() * m_width);
}

void OrderedColumnSums::sum(const double* values, double* out) {
  const std::size_t w = m_width;
  const std::size_t count = blocks();
#pragma omp for schedule(static)
  for (std::size_t blk = 0; blk < count; ++blk) {
    double* block_sum = partial(blk);
    for (std::size_t b = 0; b < w; ++b) block_sum[b] = 0.0;
    for (std::size_t r = first_row(blk); r < first_row(blk + 1); ++r)
      for (std::size_t b = 0; b < w; ++b) block_sum[b] += values[r * w + b];
  }
  // The loop's barrier above makes every block sum visible to the master.
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
