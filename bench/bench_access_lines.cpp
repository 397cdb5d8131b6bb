// The cache lines a leap-frog step of the sparse force must bring into each core's L1 and L2:
// the counts behind the line terms of the step's bound (bench/ensemble_table.sh,
// docs/performance.md "Cache lines in the bound"). Nothing is timed: the kernel's own access stream
// is replayed through an ideal cache.
//
// AccessLines/N/degree/replicas/threads/precision walks the ER network of LeapFrogStep in the
// order the kernel reads it (network_force.cpp: the rows in the static share of each thread,
// the unblocked kernel's passes over a row's partials; for the segmented kernel, panel by panel,
// segment by segment, with the segment width of the automatic rule on this CPU) and counts, per
// thread and level (L1d and L2 of the core the thread runs on, sizes read at run time):
//  - the gathered [cos, sin] records' lines: the misses of Belady's optimal replacement in a
//    fully associative cache of the level's size, taken over the stream in parts of
//    k_part_accesses, each part from an empty cache less one cache of lines (a warm cache can
//    save at most that many): no cache of that size, whatever its associativity or replacement,
//    brings fewer lines in (a prefetched line is brought in too). For L2 under the segments, only
//    each (panel, segment) pass's first touch of a line is replayed: a subsequence, whose optimal
//    misses are no more than the whole stream's;
//  - the streams read once a step (the column indices, 4 or 2 B an entry; the run lengths, 1 B
//    a row and segment), less the level's size, and the carried sums each segment after a
//    panel's first reads back (the row cursors, and the partials its runs add to), less the
//    level's size per pass;
// each class alone at the level's whole size, so the sum is at most what any run brings in. L2
// is taken with L1 beside it (what a core holds short of L3), and the replayed order is the
// CSR's within a run (the AVX2 runs take a block of four in a rotated order and load up to seven
// records past a run: more lines, not fewer).
// Counters (summed over threads, per step, bytes): l1_fill_bytes, l2_fill_bytes; beside them
// index_bytes (indices and run lengths), segments, and the two sizes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

#include "cached_network.hpp"
#include "core/cpu_caches.hpp"
#include "dynamics/column_segments.hpp"
#include "dynamics/sincos.hpp"
#include "dynamics/wide_rows.hpp"

using namespace hmfnet;

namespace {

constexpr std::size_t k_line = 64;
constexpr std::size_t k_part_accesses = std::size_t{1} << 22;
constexpr std::uint32_t k_no_line = UINT32_MAX;

// Belady's optimal replacement over one part from an empty cache of `capacity` lines: the misses.
// `next_seen` (all k_no_line) and `cached` (all 0) are scratch indexed by line, of the table's
// line count, and are left as they came.
std::int64_t optimal_misses(const std::vector<std::uint32_t>& part, std::size_t capacity,
                            std::vector<std::uint32_t>& next_seen, std::vector<char>& cached) {
  const std::size_t n = part.size();
  if (capacity == 0) return static_cast<std::int64_t>(n);
  std::vector<std::uint32_t> next(n);
  for (std::size_t k = n; k-- > 0;) {
    const std::uint32_t line = part[k];
    // Never used again: a distinct key past the part, so that the latest of them goes first.
    next[k] = next_seen[line] != k_no_line ? next_seen[line] : static_cast<std::uint32_t>(n + k);
    next_seen[line] = static_cast<std::uint32_t>(k);
  }
  for (const std::uint32_t line : part) next_seen[line] = k_no_line;
  // Max-heap of (next use, line); entries whose next use is stale are dropped when met.
  std::priority_queue<std::pair<std::uint32_t, std::uint32_t>> heap;
  std::int64_t misses = 0;
  std::size_t held = 0;
  // A held line's current next use, kept in next_seen's place once the backward pass cleared it.
  std::vector<std::uint32_t>& key = next_seen;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t line = part[k];
    if (cached[line] == 0) {
      ++misses;
      if (held == capacity) {
        for (;;) {
          const auto [use, victim] = heap.top();
          heap.pop();
          if (cached[victim] != 0 && key[victim] == use) {
            cached[victim] = 0;
            key[victim] = k_no_line;
            break;
          }
        }
      } else {
        ++held;
      }
      cached[line] = 1;
    }
    key[line] = next[k];
    heap.emplace(next[k], line);
  }
  for (const std::uint32_t line : part) {
    cached[line] = 0;
    key[line] = k_no_line;
  }
  return misses;
}

// The lower bound on lines brought into a cache of `capacity_lines` over a stream: the optimal
// misses of each k_part_accesses from empty, less what a warm cache could have held. With
// `first_touch_only`, only the first access to a line in each of the caller's passes
// (end_pass) is kept.
class LineCounter {
 public:
  LineCounter(std::size_t table_lines, std::size_t capacity_lines, bool first_touch_only)
      : m_capacity(capacity_lines),
        m_first_touch(first_touch_only),
        m_next_seen(table_lines, k_no_line),
        m_cached(table_lines, 0),
        m_touched(first_touch_only ? table_lines : 0, 0) {}

  void access(std::uint32_t line) {
    if (m_first_touch) {
      if (m_touched[line] != 0) return;
      m_touched[line] = 1;
    }
    m_part.push_back(line);
    if (m_part.size() == k_part_accesses) flush();
  }
  /// Ends one of the segmented kernel's (panel, segment) passes.
  void end_pass() {
    if (!m_first_touch) return;
    for (std::size_t k = m_pass_start; k < m_part.size(); ++k) m_touched[m_part[k]] = 0;
    m_pass_start = m_part.size();
  }
  std::int64_t lines() {
    flush();
    return m_lines;
  }

 private:
  void flush() {
    if (m_part.empty()) return;
    const std::int64_t misses = optimal_misses(m_part, m_capacity, m_next_seen, m_cached);
    m_lines += std::max<std::int64_t>(0, misses - static_cast<std::int64_t>(m_capacity));
    // A pass cut by a full buffer goes on with its touches forgotten: more of the stream kept.
    if (m_first_touch) {
      for (std::size_t k = m_pass_start; k < m_part.size(); ++k) m_touched[m_part[k]] = 0;
    }
    m_part.clear();
    m_pass_start = 0;
  }

  std::size_t m_capacity;
  bool m_first_touch;
  std::vector<std::uint32_t> m_next_seen;
  std::vector<char> m_cached;
  std::vector<char> m_touched;
  std::vector<std::uint32_t> m_part;
  std::size_t m_pass_start = 0;
  std::int64_t m_lines = 0;
};

// The bytes of `bytes` read in a pass that a cache of `capacity` bytes cannot have kept from
// before it.
double beyond(double bytes, double capacity) { return std::max(0.0, bytes - capacity); }

struct Shape {
  const Network* net;
  std::size_t record;  // bytes of one node's [cos, sin] of every replica
  int partials_per_pass;
  NodeIndex width;  // columns per segment (k_unsegmented: one)
  int segments;
};

// The bytes of a row's carried partials that a run of n entries starting at `place` in a row of
// d entries reads: the partials its entries add to (segment_runs.hpp: entry place + i of the
// first 4 floor(d / 4) into partial (place + i) mod 4, the rest into partial 0), each 2B values.
// The AVX2 runs load all four where any entry is before the last d mod 4: a superset.
double carry_read(EdgeOffset place, EdgeOffset n, EdgeOffset d, std::size_t record) {
  const EdgeOffset full = d / 4 * 4;
  bool partial[4] = {false, false, false, false};
  for (EdgeOffset i = 0; i < n && i < 4; ++i) {
    partial[place + i < full ? (place + i) % 4 : 0] = true;
  }
  if (n > 0 && place + n > full) partial[0] = true;
  const int count = partial[0] + partial[1] + partial[2] + partial[3];
  return count * static_cast<double>(record);
}

// Feeds the thread's gathers to `visit(column)` in the kernel's order, and after each (panel,
// segment) pass of the segmented kernel `end_pass(carry)`: the bytes of carried partials and row
// cursors that the pass read back (0 for the unblocked kernel and a panel's first segment).
void walk_thread(const Shape& s, int thread, int threads,
                 const std::function<void(NodeIndex)>& visit,
                 const std::function<void(double)>& end_pass) {
  const auto& cols = s.net->cols();
  const auto ptr = [&](NodeIndex r) { return s.net->row_ptr()[static_cast<std::size_t>(r)]; };
  const auto col = [&](EdgeOffset k) { return cols[static_cast<std::size_t>(k)]; };
  const NodeIndex rows = s.net->size();
  if (s.segments == 1) {
    // GCC's schedule(static): the first rows % threads threads take one row more.
    const NodeIndex q = rows / threads, extra = rows % threads;
    const NodeIndex r0 = thread * q + std::min<NodeIndex>(thread, extra);
    const NodeIndex r1 = r0 + q + (thread < extra ? 1 : 0);
    for (NodeIndex r = r0; r < r1; ++r) {
      const EdgeOffset begin = ptr(r), end = ptr(r + 1);
      const EdgeOffset full = begin + (end - begin) / 4 * 4;
      // rows_kernel: pass p forms partials [p C, p C + C); entry k of the first full groups
      // goes to partial (k - begin) mod 4, the rest to partial 0.
      for (int p = 0; p < 4; p += s.partials_per_pass) {
        for (EdgeOffset k = begin; k < end; ++k) {
          const int partial = k < full ? static_cast<int>((k - begin) % 4) : 0;
          if (partial >= p && partial < p + s.partials_per_pass) visit(col(k));
        }
      }
    }
    end_pass(0.0);
    return;
  }
  const NodeIndex panel = carried_rows(rows);
  for (std::int64_t p0 = 0; p0 < rows; p0 += panel) {
    const std::int64_t panel_rows = std::min<std::int64_t>(panel, rows - p0);
    const auto r0 = static_cast<NodeIndex>(p0 + panel_rows * thread / threads);
    const auto r1 = static_cast<NodeIndex>(p0 + panel_rows * (thread + 1) / threads);
    // Where each row's next run starts, as the kernel's cursors keep it.
    std::vector<EdgeOffset> cursor(static_cast<std::size_t>(r1 - r0));
    for (NodeIndex r = r0; r < r1; ++r) cursor[static_cast<std::size_t>(r - r0)] = ptr(r);
    for (int seg = 0; seg < s.segments; ++seg) {
      const NodeIndex c1 = static_cast<NodeIndex>(seg + 1) * s.width;
      // After the first segment every row's cursor (4 B) is read, and its partials where its
      // run adds to them.
      double carry = seg == 0 ? 0.0 : 4.0 * (r1 - r0);
      for (NodeIndex r = r0; r < r1; ++r) {
        EdgeOffset& k = cursor[static_cast<std::size_t>(r - r0)];
        const EdgeOffset start = k;
        for (; k < ptr(r + 1) && col(k) < c1; ++k) visit(col(k));
        if (seg > 0) carry += carry_read(start - ptr(r), k - start, ptr(r + 1) - ptr(r), s.record);
      }
      end_pass(carry);
    }
  }
}

// Belady's own example (IBM Systems Journal 5 (1966) 78): 1 2 3 4 1 2 5 1 2 3 4 5 takes 7
// misses in 3 lines and 6 in 4 under optimal replacement.
bool optimal_misses_hold() {
  const std::vector<std::uint32_t> stream{1, 2, 3, 4, 1, 2, 5, 1, 2, 3, 4, 5};
  std::vector<std::uint32_t> next_seen(6, k_no_line);
  std::vector<char> cached(6, 0);
  return optimal_misses(stream, 3, next_seen, cached) == 7 &&
         optimal_misses(stream, 4, next_seen, cached) == 6;
}

void AccessLines(benchmark::State& state) {
  if (!optimal_misses_hold()) {
    state.SkipWithError("optimal replacement miscounts Belady's example");
    return;
  }
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const auto replicas = static_cast<std::size_t>(state.range(2));
  const auto threads = static_cast<int>(state.range(3));
  const std::size_t value = state.range(4) == 0 ? sizeof(double) : sizeof(float);
  const std::size_t record = 2 * replicas * value;
  const NodeIndex rows = net.size();
  const NodeIndex width = automatic_segment_width(
      rows, net.nnz(), rows, record, this_cpu_caches(threads), available_memory_bytes());
  const int segments =
      width >= rows ? 1 : static_cast<int>((static_cast<std::int64_t>(rows) + width - 1) / width);
  // The walks of the unblocked kernel this CPU runs (dynamics/wide_rows.hpp).
  const int b = static_cast<int>(replicas);
  const int partials = value == sizeof(double) ? row_walk_partials<double>(b, sincos_isa())
                                               : row_walk_partials<float>(b, sincos_isa());
  const Shape shape{&net, record, partials, width, segments};
  const std::size_t l1 = l1_cache_bytes(), l2 = l2_cache_bytes();
  // What a core holds without going to L3: its L1 and L2 together, as an L2 need not hold what
  // L1 does (Intel's is not inclusive).
  const std::size_t l2_reach = l1 + l2;
  const std::size_t table_lines = (static_cast<std::size_t>(rows) * record + k_line - 1) / k_line;
  const std::size_t index_entry = segments == 1 ? sizeof(NodeIndex) : segment_index_bytes(width);
  double l1_fill = 0.0, l2_fill = 0.0, index_bytes = 0.0;
  for (auto _ : state) {
    l1_fill = l2_fill = index_bytes = 0.0;
    for (int t = 0; t < threads; ++t) {
      LineCounter in_l1(table_lines, l1 / k_line, false);
      LineCounter in_l2(table_lines, l2_reach / k_line, segments > 1);
      std::int64_t entries = 0;
      // Each pass's carry: what the level held when the pass began (at most its size) need not
      // come again; the rest must.
      double carry_l1 = 0.0, carry_l2 = 0.0;
      walk_thread(
          shape, t, threads,
          [&](NodeIndex c) {
            ++entries;
            // Records are 2^k bytes and the table starts on a line (core/cache_aligned.hpp): a
            // record lies in one line or spans whole ones.
            const std::size_t first = static_cast<std::size_t>(c) * record / k_line;
            const std::size_t last = (static_cast<std::size_t>(c) * record + record - 1) / k_line;
            for (std::size_t line = first; line <= last; ++line) {
              in_l1.access(static_cast<std::uint32_t>(line));
              in_l2.access(static_cast<std::uint32_t>(line));
            }
          },
          [&](double carry) {
            in_l1.end_pass();
            in_l2.end_pass();
            carry_l1 += beyond(carry, static_cast<double>(l1));
            carry_l2 += beyond(carry, static_cast<double>(l2_reach));
          });
      const double thread_rows = static_cast<double>(rows) / threads;
      const double index = static_cast<double>(entries) * static_cast<double>(index_entry) +
                           (segments > 1 ? thread_rows * segments : 0.0);
      index_bytes += index;
      const auto line_bytes = [](std::int64_t count) {
        return static_cast<double>(count) * static_cast<double>(k_line);
      };
      l1_fill += line_bytes(in_l1.lines()) + beyond(index, static_cast<double>(l1)) + carry_l1;
      l2_fill +=
          line_bytes(in_l2.lines()) + beyond(index, static_cast<double>(l2_reach)) + carry_l2;
    }
  }
  state.counters["l1_fill_bytes"] = l1_fill;
  state.counters["l2_fill_bytes"] = l2_fill;
  state.counters["index_bytes"] = index_bytes;
  state.counters["segments"] = segments;
  state.counters["l1_bytes"] = static_cast<double>(l1);
  state.counters["l2_bytes"] = static_cast<double>(l2);
}

}  // namespace

// Args as LeapFrogStep's (bench_dynamics.cpp): N, mean degree, replicas, threads, precision.
BENCHMARK(AccessLines)
    ->ArgsProduct({{10000, 1000000}, {100}, {1, 4, 8}, {1, 2}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
