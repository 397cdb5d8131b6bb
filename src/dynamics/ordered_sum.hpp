#pragma once
// Sums over rows whose result does not depend on the number of OpenMP threads: rows are cut into
// fixed blocks, each block summed in order (in parallel across blocks), then the block sums in
// order. 1 and 2 threads therefore give bit-identical observables.
#include <cstddef>
#include <vector>

namespace hmfnet {

/// out[b] = sum over rows r of values[r * width + b], for b < width. Opens its own parallel loop:
/// call it outside a step's team.
void ordered_column_sums(const std::vector<double>& values, std::size_t rows, int width,
                         std::vector<double>& out);

/// The same sums inside a step's team (team.hpp): the block partials live here, sized once by
/// `prepare` outside the region, so that every thread of the team writes the same buffer.
class OrderedColumnSums {
 public:
  /// Outside a region: sizes the partials for `rows` x `width` values.
  void prepare(std::size_t rows, int width);
  /// Called by every thread of the team (or outside one): the blocks are shared out, then the
  /// master thread adds the block sums in order into `out` (out.size() == width, sized by the
  /// caller). No barrier after it: `out` may be read by the master thread at once, by the others
  /// only after a later barrier (the end of the region at the latest).
  void sum(const double* values, double* out);

  // Fused use (a force that forms its values and sums them in one pass, without storing them):
  // in a worksharing loop over blocks(), the caller writes each block's sums into
  // partial(block), formed exactly as sum() forms them (from 0, rows first_row(block) ..
  // first_row(block + 1) - 1 in order, each column on its own), then add_blocks(out) on the
  // master thread after that loop's barrier. The same bits as sum() over the stored values.
  static constexpr std::size_t k_block_rows = 2048;
  std::size_t blocks() const { return (m_rows + k_block_rows - 1) / k_block_rows; }
  std::size_t first_row(std::size_t block) const {
    return block * k_block_rows < m_rows ? block * k_block_rows : m_rows;
  }
  double* partial(std::size_t block) { return m_partial.data() + block * m_width; }
  /// out[b] = the block sums of column b added in block order. Master thread (or outside a team).
  void add_blocks(double* out) const;

 private:
  std::size_t m_rows = 0;
  std::size_t m_width = 0;
  std::vector<double> m_partial;  // blocks x width
};

}  // namespace hmfnet
