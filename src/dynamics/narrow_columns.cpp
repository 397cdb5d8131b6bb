#include "dynamics/narrow_columns.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "core/page_release.hpp"
#include "dynamics/column_segments.hpp"

namespace hmfnet {

bool NarrowColumns::fits(NodeIndex columns) { return columns <= k_narrow_segment_columns; }

NarrowColumns::NarrowColumns(const std::vector<NodeIndex>& cols, NodeIndex columns)
    : NarrowColumns(cols, columns, false) {}

NarrowColumns NarrowColumns::taking(std::vector<NodeIndex>& cols, NodeIndex columns) {
  NarrowColumns narrow(cols, columns, true);
  std::vector<NodeIndex>().swap(cols);
  return narrow;
}

NarrowColumns::NarrowColumns(const std::vector<NodeIndex>& cols, NodeIndex columns, bool release)
    : m_size(cols.size()) {
  if (!fits(columns)) {
    throw ParameterError("16-bit column indices", std::to_string(columns) + " columns",
                         "at most " + std::to_string(k_narrow_segment_columns));
  }
  m_cols.reset(new std::uint16_t[m_size]);  // NOLINT(cppcoreguidelines-owning-memory)
  const auto n = static_cast<std::int64_t>(m_size);
#pragma omp parallel
  {
    // Each thread copies one block and gives back the pages wholly inside it as it passes them.
    const auto threads = static_cast<std::int64_t>(omp_get_num_threads());
    const auto thread = static_cast<std::int64_t>(omp_get_thread_num());
    const std::int64_t k0 = n * thread / threads, k1 = n * (thread + 1) / threads;
    PageRelease behind(cols.data() + k0);
    constexpr std::int64_t k_block = std::int64_t{1} << 16;
    for (std::int64_t b = k0; b < k1; b += k_block) {
      const std::int64_t e = std::min(k1, b + k_block);
      for (std::int64_t k = b; k < e; ++k) {
        m_cols[static_cast<std::size_t>(k)] =
            static_cast<std::uint16_t>(cols[static_cast<std::size_t>(k)]);
      }
      if (release) behind.up_to(cols.data() + e);
    }
  }
}

std::vector<NodeIndex> NarrowColumns::widened() const {
  return std::vector<NodeIndex>(m_cols.get(), m_cols.get() + m_size);
}

}  // namespace hmfnet
