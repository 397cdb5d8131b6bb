#include "dynamics/run_lengths.hpp"

#include <algorithm>

namespace hmfnet {

RunLengths::RunLengths(const std::vector<std::uint32_t>& counts, int segments, std::size_t rows)
    : m_rows(rows),
      m_length(static_cast<std::size_t>(segments) * rows),
      m_block_start(static_cast<std::size_t>(segments) * blocks()),
      m_long_start(static_cast<std::size_t>(segments) + 1, 0) {
  const auto count = static_cast<std::ptrdiff_t>(m_length.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::uint32_t n = counts[static_cast<std::size_t>(k)];
    m_length[static_cast<std::size_t>(k)] =
        n >= k_long_run ? k_long_run : static_cast<std::uint8_t>(n);
  }
  // Block starts and long runs: one ordered pass a segment.
  for (std::size_t s = 0; s < static_cast<std::size_t>(segments); ++s) {
    std::uint32_t start = 0;
    for (std::size_t r = 0; r < rows; ++r) {
      if (r % k_run_block == 0) m_block_start[s * blocks() + r / k_run_block] = start;
      const std::uint32_t n = counts[s * rows + r];
      if (n >= k_long_run) m_long.push_back({static_cast<NodeIndex>(r), n});
      start += n;
    }
    if (rows % k_run_block == 0) m_block_start[s * blocks() + rows / k_run_block] = start;
    m_long_start[s + 1] = m_long.size();
  }
}

RunWalk RunLengths::walk(int s, NodeIndex r) const {
  const auto seg = static_cast<std::size_t>(s);
  const NodeIndex first = r / k_run_block * k_run_block;
  const LongRun* long_begin = m_long.data() + m_long_start[seg];
  const LongRun* long_end = m_long.data() + m_long_start[seg + 1];
  RunWalk w{m_length.data() + seg * m_rows,
            std::lower_bound(long_begin, long_end, first,
                             [](const LongRun& run, NodeIndex row) { return run.row < row; }),
            m_block_start[seg * blocks() + static_cast<std::size_t>(r / k_run_block)]};
  for (NodeIndex q = first; q < r; ++q) w.next(q);
  return w;
}

std::size_t RunLengths::bytes_without_long_runs(int segments, std::size_t rows) {
  const auto n = static_cast<std::size_t>(segments);
  return n * rows + n * (rows / k_run_block + 1) * sizeof(std::uint32_t) +
         (n + 1) * sizeof(std::size_t);
}

}  // namespace hmfnet
