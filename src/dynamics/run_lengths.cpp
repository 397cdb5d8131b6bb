#include "dynamics/run_lengths.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace hmfnet {

RunLengths::RunLengths(int segments, std::size_t rows)
    : m_rows(rows),
      m_length(static_cast<std::size_t>(segments) * rows, 0),
      m_block_start(static_cast<std::size_t>(segments) * blocks(), 0),
      m_long_start(static_cast<std::size_t>(segments) + 1, 0) {}

bool RunLengths::finish(const std::function<std::uint32_t(int, NodeIndex)>& long_length) {
  m_long.clear();
  const std::size_t segments = m_long_start.size() - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    std::uint64_t start = 0;
    for (std::size_t r = 0; r < m_rows; ++r) {
      if (r % k_run_block == 0)
        m_block_start[s * blocks() + r / k_run_block] = static_cast<std::uint32_t>(start);
      std::uint32_t n = m_length[s * m_rows + r];
      if (n == k_long_run) {
        n = long_length(static_cast<int>(s), static_cast<NodeIndex>(r));
        m_long.push_back({static_cast<NodeIndex>(r), n});
      }
      start += n;
      if (start > UINT32_MAX) return false;
    }
    if (m_rows % k_run_block == 0)
      m_block_start[s * blocks() + m_rows / k_run_block] = static_cast<std::uint32_t>(start);
    m_long_start[s + 1] = m_long.size();
  }
  return true;
}

RunLengths::RunLengths(const std::vector<std::uint32_t>& counts, int segments, std::size_t rows)
    : RunLengths(segments, rows) {
  for (int s = 0; s < segments; ++s) {
    for (std::size_t r = 0; r < rows; ++r)
      set(s, static_cast<NodeIndex>(r), counts[static_cast<std::size_t>(s) * rows + r]);
  }
  const bool fits = finish([&](int s, NodeIndex r) {
    return counts[static_cast<std::size_t>(s) * rows + static_cast<std::size_t>(r)];
  });
  if (!fits) throw ParameterError("run lengths", "a segment of 2^32 entries or more", "< 2^32");
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
