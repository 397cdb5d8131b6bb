#pragma once
// Where each row's run of entries lies in each column segment (column_segments.hpp), in one byte
// a row and segment: the run's length, with the start of every k_run_block-th row's run kept
// beside it. The kernel walks a segment's rows in order from its first row, so a run starts
// where the previous one ended, and the first row's start is its block's start plus at most
// k_run_block - 1 lengths. A 4-byte start a row and segment held 64 MB at ER N = 10^6, degree
// 100, 16 segments; these hold 17 MB (docs/performance.md, "Run lengths in one byte").
// Lengths of k_long_run entries or more (a hub's run in a wide segment) are looked up in a list
// of long runs, in row order, that the walk steps through as it meets them.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

/// Rows a block start stands for: 4 bytes per 64 rows and segment, and at most 63 lengths added
/// to find a row's start.
inline constexpr NodeIndex k_run_block = 64;

/// The byte that marks a long run (its length in the long-run list): 255.
inline constexpr std::uint8_t k_long_run = UINT8_MAX;

/// A run of k_long_run entries or more.
struct LongRun {
  NodeIndex row;
  std::uint32_t length;
};

/// One row's run: its first entry's index in the segment's column indices, and its length.
struct RunSpan {
  std::uint32_t begin;
  std::uint32_t n;
};

/// One segment's runs walked row by row: next(r) for r, r + 1, ... from the row the walk was
/// made for (RunLengths::walk).
struct RunWalk {
  const std::uint8_t* length;  // the segment's lengths, indexed by row
  const LongRun* long_run;     // the first long run at or after the next row
  std::uint32_t start;         // where the next row's run begins

  RunSpan next(NodeIndex r) {
    std::uint32_t n = length[r];
    if (n == k_long_run) n = (long_run++)->length;
    const RunSpan span{start, n};
    start += n;
    return span;
  }
};

class RunLengths {
 public:
  RunLengths() = default;
  /// Built in two steps, so that no 4-byte length is held a run: every length set (set, from
  /// any thread for distinct runs), then finish. Until then, `segments` x `rows` empty runs.
  RunLengths(int segments, std::size_t rows);
  /// Row r's run in segment s has n entries.
  void set(int s, NodeIndex r, std::uint32_t n) {
    m_length[static_cast<std::size_t>(s) * m_rows + static_cast<std::size_t>(r)] =
        n >= k_long_run ? k_long_run : static_cast<std::uint8_t>(n);
  }
  /// The block starts and the list of long runs, whose lengths long_length(s, r) gives again
  /// (they are rare: none in ER at N = 10^6). False, and nothing usable, where a segment holds
  /// 2^32 entries or more (the starts are 32-bit). Ordered: on the calling thread.
  [[nodiscard]] bool finish(const std::function<std::uint32_t(int, NodeIndex)>& long_length);
  /// Both steps from the lengths counts[s x rows + r] (tests).
  RunLengths(const std::vector<std::uint32_t>& counts, int segments, std::size_t rows);

  /// The walk of segment s from row r on (0 <= r <= rows).
  RunWalk walk(int s, NodeIndex r) const;
  std::size_t bytes() const {
    return m_length.size() * sizeof(std::uint8_t) + m_block_start.size() * sizeof(std::uint32_t) +
           m_long.size() * sizeof(LongRun) + m_long_start.size() * sizeof(std::size_t);
  }
  /// The bytes `segments` x `rows` runs take without long ones (the automatic rule's estimate).
  static std::size_t bytes_without_long_runs(int segments, std::size_t rows);

 private:
  std::size_t blocks() const { return m_rows / k_run_block + 1; }

  std::size_t m_rows = 0;
  std::vector<std::uint8_t> m_length;        // segments x rows, k_long_run: in m_long
  std::vector<std::uint32_t> m_block_start;  // segments x blocks(): row b x 64's run start
  std::vector<LongRun> m_long;               // segment by segment, in row order
  std::vector<std::size_t> m_long_start;     // segments + 1: where each segment's long runs begin
};

}  // namespace hmfnet
