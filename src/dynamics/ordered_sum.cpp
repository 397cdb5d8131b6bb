#include "dynamics/ordered_sum.hpp"

#include <algorithm>

namespace hmfnet {

namespace {
constexpr std::size_t k_block = 2048;
}

void ordered_column_sums(const std::vector<double>& values, std::size_t rows, int width,
                         std::vector<double>& out) {
  const auto w = static_cast<std::size_t>(width);
  const std::size_t blocks = (rows + k_block - 1) / k_block;
  std::vector<double> partial(blocks * w, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    const std::size_t end = std::min(rows, (blk + 1) * k_block);
    for (std::size_t r = blk * k_block; r < end; ++r)
      for (std::size_t b = 0; b < w; ++b) partial[blk * w + b] += values[r * w + b];
  }
  out.assign(w, 0.0);
  for (std::size_t blk = 0; blk < blocks; ++blk)
    for (std::size_t b = 0; b < w; ++b) out[b] += partial[blk * w + b];
}

}  // namespace hmfnet
