#include "dynamics/column_segments.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/cache_aligned.hpp"
#include "core/huge_pages.hpp"
#include "core/page_release.hpp"
#include "dynamics/segment_runs.hpp"

namespace hmfnet {

namespace {

// The segments' carried partial sums against the lines they save, per row and step, where both
// come from memory: each of `segments` reads and writes a row's four partials of the record,
// and unsegmented each of the row's `degree` entries takes its record's whole lines.
bool carry_pays(double segments, double degree, std::size_t record_bytes) {
  const auto record = static_cast<double>(record_bytes);
  const double carried = segments * 2 * 4 * record;
  const double gathered = degree * std::max(record, static_cast<double>(k_cache_line_bytes));
  return carried < gathered;
}

}  // namespace

bool slices_in_l3(CacheSizes caches) {
  return caches.l3_core_complex && caches.l3 > 2 * caches.l2 && caches.l3 < k_near_l3_max_bytes;
}

std::size_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  unsigned long long kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return static_cast<std::size_t>(kib) << 10;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0)
    return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page);
  return SIZE_MAX;
}

std::size_t segment_index_bytes(NodeIndex width) {
  return width <= k_narrow_segment_columns ? sizeof(std::uint16_t) : sizeof(NodeIndex);
}

std::size_t segmented_bytes(EdgeOffset nnz, NodeIndex rows, int segments, NodeIndex width,
                            std::size_t record_bytes) {
  const auto n = static_cast<std::size_t>(rows);
  const auto panel = static_cast<std::size_t>(carried_rows(rows));
  return static_cast<std::size_t>(nnz) * segment_index_bytes(width) +
         RunLengths::bytes_without_long_runs(segments, n) + panel * 4 * record_bytes +
         panel * sizeof(std::uint32_t);
}

namespace {

/// The rule's cut before it weighs the carry: the width of its slices (k_unsegmented where the
/// table fits in the L2, the records are too long, fewer than two segments are left or the
/// memory would not allow them), and whether the carry pays for them.
struct RuleCut {
  NodeIndex width = k_unsegmented;
  bool carry_pays = true;
};

RuleCut rule_cut(NodeIndex columns, EdgeOffset nnz, NodeIndex rows, std::size_t record_bytes,
                 CacheSizes caches, std::size_t memory_bytes, bool rows_in_registers) {
  const auto table = static_cast<double>(columns) * static_cast<double>(record_bytes);
  if (columns <= 0 || rows <= 0 || table <= static_cast<double>(caches.l2)) return {};
  if (rows_in_registers && record_bytes > k_max_segmented_record_bytes) return {};
  const bool in_l3 = slices_in_l3(caches);
  const double l3 =
      std::min(static_cast<double>(caches.l3), static_cast<double>(caches.l3_threads) *
                                                   static_cast<double>(k_l3_thread_share_bytes));
  const double slice = in_l3 ? l3 / (2.0 * caches.l3_threads) : static_cast<double>(caches.l2) / 2;
  const double degree = static_cast<double>(nnz) / static_cast<double>(rows);
  const double by_entries = std::floor(degree / k_min_entries_per_segment);
  const double segments = std::min(std::ceil(table / slice), by_entries);
  if (segments < 2) return {};
  const auto width = static_cast<NodeIndex>(std::ceil(static_cast<double>(columns) / segments));
  if (segmented_bytes(nnz, rows, static_cast<int>(segments), width, record_bytes) >
      memory_bytes / 2) {
    return {};
  }
  return {width, !in_l3 || carry_pays(segments, degree, record_bytes)};
}

}  // namespace

NodeIndex automatic_segment_width(NodeIndex columns, EdgeOffset nnz, NodeIndex rows,
                                  std::size_t record_bytes, CacheSizes caches,
                                  std::size_t memory_bytes, bool rows_in_registers) {
  const RuleCut cut =
      rule_cut(columns, nnz, rows, record_bytes, caches, memory_bytes, rows_in_registers);
  return cut.carry_pays ? cut.width : k_unsegmented;
}

NodeIndex trial_segment_width(NodeIndex columns, EdgeOffset nnz, NodeIndex rows,
                              std::size_t record_bytes, CacheSizes caches, std::size_t memory_bytes,
                              bool rows_in_registers) {
  const RuleCut cut =
      rule_cut(columns, nnz, rows, record_bytes, caches, memory_bytes, rows_in_registers);
  return cut.carry_pays ? k_unsegmented : cut.width;
}

ColumnSegments::ColumnSegments(const std::vector<EdgeOffset>& row_ptr,
                               const std::vector<NodeIndex>& cols, NodeIndex columns,
                               NodeIndex width, bool allow_narrow)
    : ColumnSegments(row_ptr, cols, columns, width, allow_narrow, nullptr) {}

ColumnSegments ColumnSegments::taking(const std::vector<EdgeOffset>& row_ptr,
                                      std::vector<NodeIndex>& cols, NodeIndex columns,
                                      NodeIndex width) {
  return ColumnSegments(row_ptr, cols, columns, width, true, &cols);
}

ColumnSegments::ColumnSegments(const std::vector<EdgeOffset>& row_ptr,
                               const std::vector<NodeIndex>& cols, NodeIndex columns,
                               NodeIndex width, bool allow_narrow, std::vector<NodeIndex>* taken) {
  const NodeIndex rows = row_ptr.empty() ? 0 : static_cast<NodeIndex>(row_ptr.size() - 1);
  const NodeIndex count = width >= columns ? 1 : (columns - 1) / width + 1;
  if (count <= 1 || rows == 0) return;
  const auto nrows = static_cast<std::size_t>(rows);
  const auto row = [&](NodeIndex r) {
    return std::make_pair(cols.begin() + row_ptr[static_cast<std::size_t>(r)],
                          cols.begin() + row_ptr[static_cast<std::size_t>(r) + 1]);
  };
  bool cuttable = true;
#pragma omp parallel for schedule(static) reduction(&& : cuttable)
  for (NodeIndex r = 0; r < rows; ++r) {
    const auto [b, e] = row(r);
    cuttable = cuttable && e - b <= UINT32_MAX && std::is_sorted(b, e);
  }
  if (!cuttable) return;
  // Row r's run in segment s: its entries from the first column of s to the first of s + 1.
  const auto run_end = [&](NodeIndex r, NodeIndex s, std::vector<NodeIndex>::const_iterator k) {
    return s + 1 < count ? std::lower_bound(k, row(r).second, (s + 1) * width) : row(r).second;
  };
  RunLengths runs(count, nrows);
#pragma omp parallel for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    auto k = row(r).first;
    for (NodeIndex s = 0; s < count; ++s) {
      const auto next = run_end(r, s, k);
      runs.set(s, r, static_cast<std::uint32_t>(next - k));
      k = next;
    }
  }
  const bool fits = runs.finish([&](int s, NodeIndex r) {
    const auto first = std::lower_bound(row(r).first, row(r).second, s * width);
    return static_cast<std::uint32_t>(run_end(r, s, first) - first);
  });
  if (!fits) return;
  std::vector<std::size_t> segment_start(static_cast<std::size_t>(count) + 1, 0);
  for (int s = 0; s < count; ++s) {
    segment_start[static_cast<std::size_t>(s) + 1] = runs.walk(s, rows).start;
    segment_start[static_cast<std::size_t>(s) + 1] += segment_start[static_cast<std::size_t>(s)];
  }
  m_count = count;
  m_width = width;
  m_narrow = allow_narrow && segment_index_bytes(width) == sizeof(std::uint16_t);
  m_rows = nrows;
  m_segment_start = std::move(segment_start);
  m_runs = std::move(runs);
  m_indices = cols.size() + k_run_padding;
  // Not value-initialised (make_unique would write every page now); the zeros past the end,
  // local index 0 of the last segment, are a readable record.
  // In huge pages: the copy, its pages faulted in as the copy goes (16 regions at once,
  // interleaved with pages the network's indices gave back), ran 0.93-1.00x the zero-filled one
  // through simulate at ER N = 10^6, degree 100; in huge pages 0.96-1.07x (docs/performance.md,
  // "The segments in place of the network's indices").
  if (m_narrow) {
    m_cols16.reset(new std::uint16_t[m_indices]);  // NOLINT(cppcoreguidelines-owning-memory)
    prefer_huge_pages(m_cols16.get(), m_indices * sizeof(std::uint16_t));
    std::fill(m_cols16.get() + cols.size(), m_cols16.get() + m_indices, std::uint16_t{0});
    copy_local(row_ptr, cols, m_cols16.get(), taken != nullptr);
  } else {
    m_cols32.reset(new NodeIndex[m_indices]);  // NOLINT(cppcoreguidelines-owning-memory)
    prefer_huge_pages(m_cols32.get(), m_indices * sizeof(NodeIndex));
    std::fill(m_cols32.get() + cols.size(), m_cols32.get() + m_indices, NodeIndex{0});
    copy_local(row_ptr, cols, m_cols32.get(), taken != nullptr);
  }
  if (taken != nullptr) std::vector<NodeIndex>().swap(*taken);
}

std::vector<NodeIndex> ColumnSegments::csr_columns() const {
  if (m_count == 1) return {};
  std::vector<NodeIndex> out(m_indices - k_run_padding);
  std::size_t k = 0;
  std::vector<RunWalk> walks;
  walks.reserve(static_cast<std::size_t>(m_count));
  for (int s = 0; s < m_count; ++s) walks.push_back(m_runs.walk(s, 0));
  for (std::size_t r = 0; r < m_rows; ++r) {
    for (int s = 0; s < m_count; ++s) {
      const RunSpan span = walks[static_cast<std::size_t>(s)].next(static_cast<NodeIndex>(r));
      for (std::uint32_t j = 0; j < span.n; ++j) {
        const std::size_t at = m_segment_start[static_cast<std::size_t>(s)] + span.begin + j;
        out[k++] = first_column(s) + (m_narrow ? NodeIndex{m_cols16[at]} : m_cols32[at]);
      }
    }
  }
  return out;
}

template <typename I>
void ColumnSegments::copy_local(const std::vector<EdgeOffset>& row_ptr,
                                const std::vector<NodeIndex>& cols, I* out, bool release) const {
  const auto rows = static_cast<std::int64_t>(m_rows);
  const auto count = static_cast<std::size_t>(m_count);
  // Allocated here: nothing may throw inside the parallel region.
  std::vector<RunWalk> walks(static_cast<std::size_t>(omp_get_max_threads()) * count);
#pragma omp parallel
  {
    // A walk only goes forward from the row it was made for, so each thread takes one block of
    // rows and walks every segment's runs over it.
    const auto threads = static_cast<std::int64_t>(omp_get_num_threads());
    const auto thread = static_cast<std::int64_t>(omp_get_thread_num());
    const auto r0 = static_cast<NodeIndex>(rows * thread / threads);
    const auto r1 = static_cast<NodeIndex>(rows * (thread + 1) / threads);
    RunWalk* walk = walks.data() + static_cast<std::size_t>(thread) * count;
    for (int s = 0; s < m_count; ++s) walk[s] = m_runs.walk(s, r0);
    // The pages wholly inside this thread's entries are given back as its copy passes them.
    PageRelease behind(cols.data() + row_ptr[static_cast<std::size_t>(r0)]);
    for (NodeIndex r = r0; r < r1; ++r) {
      EdgeOffset k = row_ptr[static_cast<std::size_t>(r)];
      for (int s = 0; s < m_count; ++s) {
        const RunSpan span = walk[s].next(r);
        I* to = out + m_segment_start[static_cast<std::size_t>(s)] + span.begin;
        const NodeIndex base = first_column(s);
        for (std::uint32_t j = 0; j < span.n; ++j, ++k)
          to[j] = static_cast<I>(cols[static_cast<std::size_t>(k)] - base);
      }
      if (release) behind.up_to(cols.data() + k);
    }
  }
}

}  // namespace hmfnet
