#pragma once
// The CSR's column indices in 16 bits for the unblocked row loops, where every column fits
// (at most k_narrow_segment_columns columns: networks of up to 65,536 nodes on one rank, a
// rank's owned and ghost columns under MPI). Each stored entry's index is read once a step
// beside its gathered record; half the bytes keep more of the [cos, sin] table in L2 while the
// index stream passes through it. Alone (against the terms-only-where-read change), ER
// N = 10^4, degree 100, 1 thread, through `hmfnet simulate`: 1.06x (float32, 8 replicas), 1.07x
// (float32, 4) and 1.12x (float64, 8) on the AMD EPYC family 25 model 17 (docs/performance.md,
// "16-bit column indices and the terms only where the sums are read"). The indices are the
// CSR's own, so the row loops add the same records in the same order: the same bits.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

class NarrowColumns {
 public:
  /// No indices (the row loops read the 32-bit ones).
  NarrowColumns() = default;

  /// A 16-bit copy of `cols`, each below `columns`, which must fit (fits(columns)).
  NarrowColumns(const std::vector<NodeIndex>& cols, NodeIndex columns);

  /// As above, taking `cols` over: its pages go back to the system as they are copied (the peak
  /// holds the 4-byte indices or the copy, not both), and `cols` is left empty.
  static NarrowColumns taking(std::vector<NodeIndex>& cols, NodeIndex columns);

  /// Moved from, a copy holds no indices (empty()), as a default one.
  NarrowColumns(NarrowColumns&& other) noexcept
      : m_size(std::exchange(other.m_size, 0)), m_cols(std::move(other.m_cols)) {}
  NarrowColumns& operator=(NarrowColumns&& other) noexcept {
    m_size = std::exchange(other.m_size, 0);
    m_cols = std::move(other.m_cols);
    return *this;
  }
  NarrowColumns(const NarrowColumns&) = delete;
  NarrowColumns& operator=(const NarrowColumns&) = delete;
  ~NarrowColumns() = default;

  /// Whether `columns` columns have 16-bit indices.
  static bool fits(NodeIndex columns);

  /// The indices in 32 bits again (to cut the rows into segments once the CSR's own were taken).
  std::vector<NodeIndex> widened() const;

  bool empty() const { return m_size == 0; }
  std::size_t size() const { return m_size; }
  const std::uint16_t* data() const { return m_cols.get(); }
  std::size_t bytes() const { return m_size * sizeof(std::uint16_t); }

 private:
  NarrowColumns(const std::vector<NodeIndex>& cols, NodeIndex columns, bool release);

  std::size_t m_size = 0;
  // Left uninitialised until the copy writes it, so its pages are taken only as it goes.
  std::unique_ptr<std::uint16_t[]> m_cols;
};

}  // namespace hmfnet
