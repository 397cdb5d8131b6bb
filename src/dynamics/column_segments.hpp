#pragma once
// CSR segmenting of the sparse force kernel's gather (Zhang, Kiriansky, Mendis, Amarasinghe,
// Zaharia, Shun, "Making caches work for graph analytics", IEEE BigData 2017, "CSR segmenting"):
// the column space is cut into segments of `width` consecutive columns whose slice of the
// gathered [cos, sin] table fits in the L2 cache, and the kernel walks the rows once per segment,
// each row's partial sums carried from one segment to the next. The rows are sorted by column,
// so a row's entries in a segment are one contiguous run of its CSR entries and the segments,
// taken in order, add them in the CSR order: the same additions as the unblocked kernel, the
// same bits (network_force.cpp). As in the paper, each segment is a CSR of its own (its column
// indices contiguous, so the index stream is read once a step, not once a segment per row).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/cpu_caches.hpp"
#include "dynamics/run_lengths.hpp"
#include "network/network.hpp"

namespace hmfnet {

/// A core complex's L3 (CacheSizes::l3_core_complex) smaller than this is close enough to hold
/// the segments' slices: the AMD EPYC's 8 MiB (512 KiB L2), where ER N = 10^6, degree 100,
/// float64, one replica ran 1.8x faster in slices of 4 MiB than of 1 MiB and a table of 0.6-1.3 MB
/// (N = 10^4, 4 and 8 replicas) 2x faster unsegmented than in L2 slices; not the AMD EPYC's
/// socket-wide 64 MiB that glibc reports where sysfs does not answer (docs/performance.md,
/// "Segment slices in a core complex's L3"). An Intel L3 is no core complex's, whatever its size:
/// on the Intel Xeon with a 48 MiB L3 (1.25 MiB L2) float64 with one replica ran 1.6x faster in
/// the L2 rule's 1 MiB slices than unblocked in that L3 in one run, 1.26x in the median of three
/// alternated with the old rule (docs/performance.md, "An Intel Xeon's L3 is no core
/// complex's"), as 1 MiB slices beat 4 MiB ones on the one with 260 MiB.
inline constexpr std::size_t k_near_l3_max_bytes = std::size_t{64} << 20;

/// The L3 one thread can count on filling, whatever the core complex's L3 is said to hold: a
/// host may leave a guest only part of an L3 it shares. On the AMD EPYC family 25 model 1 under
/// KVM (512 KiB L2; sysfs: a 32 MiB L3 shared by the guest's 2 CPUs) one thread's sequential
/// re-reads ran at L3 speed up to 8 MiB and at memory speed from 16 MiB (29.6 and 10.2 GB/s),
/// two threads' up to 12 MiB of both; slices of half the reported L3 (16 MiB a thread) left ER
/// N = 10^6, degree 100, float64 with one replica unsegmented there, at 0.116 G/s against 0.199
/// in 4 MiB slices (docs/performance.md, "The L3 a guest can count on"). The AMD EPYC's 8 MiB core
/// complex is within the cap and keeps its slices.
inline constexpr std::size_t k_l3_thread_share_bytes = std::size_t{8} << 20;

/// Whether the slices live in L3 (a core complex's, more than twice the L2 and below
/// k_near_l3_max_bytes) rather than in L2.
bool slices_in_l3(CacheSizes caches);

/// Segments hold at least this many stored entries per row on average: each row pays, per
/// segment, a carry of its four partial sums of every replica (read and written) and a short
/// run's loop, which outweigh the L2 hits of fewer entries. Measured on the Intel Xeon
/// (docs/performance.md, "Segmented rows"; ER N = 10^6, degree 100, 1 thread): float64 with 8
/// replicas ran 1.3x faster in 8 segments (12.5 entries) than in 31 (3.2), float32 with 8
/// replicas fastest in 16 (6.25) of 4, 16, 31 and 62.
inline constexpr double k_min_entries_per_segment = 6.0;

/// Records longer than this (more than 8 float64 or 16 float32 replicas) stay unblocked where the
/// unblocked rows run in wide registers (wide_rows.hpp's groups; not measured for the baseline
/// loop, which keeps the rule's segments): the carry moves 8 x record bytes a row and segment,
/// and the unblocked rows add them in registers where a segment's runs add them in memory.
/// Measured (Intel Xeon
/// family 6 model 106, 1.25 MiB L2, 48 MiB L3; float64, 16 replicas, 256-byte records, 1 thread,
/// bench SegmentedStep): ER N = 10^4, degree 100, 1.32 G entries x replicas / s unblocked against
/// 0.68 in the rule's 4 slices; N = 10^6 0.234 against 0.199 in its 16 segments.
inline constexpr std::size_t k_max_segmented_record_bytes = 128;

/// A segment width in columns: automatic (automatic_segment_width), none (unblocked) or forced.
inline constexpr NodeIndex k_automatic_segments = 0;
inline constexpr NodeIndex k_unsegmented = INT32_MAX;

/// The segmented kernel walks the rows in at most this many panels of carried_rows(rows) rows,
/// every segment for one panel before the next, so the carried partial sums (4 x 2B values a
/// row) are held for a quarter of the rows:
/// 128 MB instead of 512 at ER N = 10^6, degree 100, float64, 8 replicas. Each panel reads the
/// table's slices again; measured on the Intel Xeon (docs/performance.md, "Carried sums in four
/// panels"; 1 thread): float64 B = 1 1.15x faster, float64 B = 8 ~0.95x, float32 ~0.95-0.97x,
/// against one panel; panels of 1000-16,000 rows (a carry in L2) ran 1.1-2.4x slower than one.
inline constexpr NodeIndex k_carry_panels = 4;

/// The rows of one panel (the last may hold fewer): ceil(rows / k_carry_panels).
inline NodeIndex carried_rows(NodeIndex rows) {
  return static_cast<NodeIndex>((static_cast<std::int64_t>(rows) + k_carry_panels - 1) /
                                k_carry_panels);
}

/// The memory this process may still take, in bytes: MemAvailable of /proc/meminfo, else the
/// free pages (sysconf), else no limit known (the largest size_t).
std::size_t available_memory_bytes();

/// What segmenting `rows` rows of `nnz` entries into `segments` segments of `width` columns adds
/// to the force: the column index copy (nnz x segment_index_bytes(width)), the run lengths
/// (RunLengths: about segments x rows x 1 B; long runs, which only wide segments and hubs have,
/// not counted), the carried partial sums (carried_rows(rows) x 4 x record_bytes) and the row
/// cursors (carried_rows(rows) x 4 B).
std::size_t segmented_bytes(EdgeOffset nnz, NodeIndex rows, int segments, NodeIndex width,
                            std::size_t record_bytes);

/// The rule: the whole column space (one segment) when the table, columns x record_bytes, fits
/// in the L2; else as many segments as slices of half the cache they live in (slices_in_l3:
/// the L3 where it is a core complex's own, shared by the team's threads and at most
/// k_l3_thread_share_bytes a thread, else the L2; at two
/// threads on the AMD EPYC, float64 with one replica ran 0.84x as fast as in the L2 rule's 1 MiB
/// slices in slices of 4 MiB, 1.19x in 2 MiB; the other half holds the streams of
/// column indices, run lengths and carried sums; 1 MiB slices measured faster than 512 KiB and
/// 2 MiB ones on the 2 MiB L2 of the Intel Xeon), but no more than leave
/// k_min_entries_per_segment entries per row and segment, and one segment when that leaves
/// fewer than two, or when the segments' memory (segmented_bytes: +346 MB at ER N = 10^6,
/// degree 100, float64, 8 replicas) exceeds half of `memory_bytes`: a network that runs
/// unblocked is never pushed out of memory for the speed-up (counted as added even where the
/// force takes the network's indices and the copy replaces them: the rule errs on the side of
/// memory), and none for records over k_max_segmented_record_bytes when `rows_in_registers`
/// (the unblocked rows run wide_rows.hpp's loops for this count). Slices in L3 also leave the
/// rows unblocked where the carried sums would move more bytes than the gathered lines they save,
/// both from memory (a record of 64 bytes or more fills its lines: float64 with 4 and 8
/// replicas, float32 with 8, ran 1.2-2.2x faster unsegmented at N = 10^6 on the AMD EPYC family
/// 25 model 1 guest; a run tries those slices too: trial_segment_width); an L3 as large as the
/// Intel Xeon's holds the carry. record_bytes = 2 x replicas x sizeof(the
/// table's type).
NodeIndex automatic_segment_width(NodeIndex columns, EdgeOffset nnz, NodeIndex rows,
                                  std::size_t record_bytes, CacheSizes caches,
                                  std::size_t memory_bytes, bool rows_in_registers = true);

/// The slices in L3 that automatic_segment_width left unblocked only because the carried sums
/// would move more bytes than the gathered lines they save, both counted from memory: their
/// width, else k_unsegmented. Where a guest's L3 holds the slices beside the streams the carry
/// comes from L3 instead, and 64-byte records ran 1.5-2.3x faster in those slices (ER N = 10^6,
/// degree 100, the AMD EPYC family 25 model 17 guest); on a guest that reports the same caches
/// but holds less of them (family 25 model 1) they ran 1.2-2.2x slower (docs/performance.md,
/// "64-byte records on the AMD EPYC family 25 model 17"). No reading of the caches told the two
/// apart, so a run times both on its first steps (NetworkForce::segment_candidates,
/// step_trial.hpp).
NodeIndex trial_segment_width(NodeIndex columns, EdgeOffset nnz, NodeIndex rows,
                              std::size_t record_bytes, CacheSizes caches, std::size_t memory_bytes,
                              bool rows_in_registers = true);

/// Segments of at most this many columns keep their column indices in 16 bits, relative to the
/// segment's first column: half the copy's bytes (200 MB instead of 400 at ER N = 10^6, degree
/// 100). The automatic rule's widths there: 62,500 columns for float64 (one replica: slices of
/// 1 MiB; more: the d / 6 cap) and float32 with 2 or more replicas, 16-bit; 125,000 for float32
/// with one replica (8-byte records, 8 slices of 1 MiB), 32-bit: forcing 16 segments of 65,536
/// columns there ran 0.84x as fast (bench SegmentedStep/1000000/100/1/1/512 against .../1024).
inline constexpr NodeIndex k_narrow_segment_columns = NodeIndex{1} << 16;

/// The bytes of one stored column index of segments `width` columns wide.
std::size_t segment_index_bytes(NodeIndex width);

/// The rows cut by columns, as the paper stores them: one CSR per segment (its column indices
/// in one array, segment after segment, and per segment where each row's run lies: RunLengths,
/// its length in a byte). The indices are relative to the segment's first column
/// (first_column), in 16 bits where the segments are at most k_narrow_segment_columns wide
/// (narrow()), else in 32. Memory: (nnz + k_run_padding) x 2 or 4 bytes (one more column index
/// array, or in place of the CSR's own where taking() takes them; the padding: segment_runs.hpp)
/// plus about segments x rows x 1 byte (at most nnz / k_min_entries_per_segment under the
/// automatic rule). The weights are not copied: a row's run in a segment continues where its run
/// in the previous segment ended. (Reading each run from
/// the network's own CSR instead of a copy saves the array and ran 0.20x as fast at ER N = 10^6,
/// degree 100, one replica: one cache line fetched per row and segment, at strides the prefetcher
/// cannot follow; docs/performance.md.)
class ColumnSegments {
 public:
  /// One segment: the unblocked kernel.
  ColumnSegments() = default;

  /// Cuts [0, columns) into segments of `width` columns (width >= 1). Rows whose columns are not
  /// ascending cannot be cut (a segment's entries would not be contiguous in the row), nor can a
  /// segment of 2^32 or more entries: then one segment. `allow_narrow` false keeps 32-bit
  /// indices whatever the width (the tests compare both). Runs on its own threads (outside a
  /// team).
  ColumnSegments(const std::vector<EdgeOffset>& row_ptr, const std::vector<NodeIndex>& cols,
                 NodeIndex columns, NodeIndex width, bool allow_narrow = true);

  /// As above, taking `cols` over where the rows are cut: each page of `cols` is given back to
  /// the system as soon as its entries are copied, so the peak holds the 4-byte indices or the
  /// copy but not both (+0 MB for the copy at ER N = 10^6, degree 100, instead of +200), and
  /// `cols` is left empty. Where the rows are not cut (one segment), `cols` is left as it was.
  static ColumnSegments taking(const std::vector<EdgeOffset>& row_ptr, std::vector<NodeIndex>& cols,
                               NodeIndex columns, NodeIndex width);

  /// The rows' column indices in CSR order, put back together from the segments (to cut them
  /// again at another width once the CSR's own were taken). Empty for one segment.
  std::vector<NodeIndex> csr_columns() const;

  int count() const { return m_count; }
  /// Whether the indices are 16-bit (cols<std::uint16_t>) or 32-bit (cols<NodeIndex>).
  bool narrow() const { return m_narrow; }
  /// The global column of segment s's local index 0.
  NodeIndex first_column(int s) const { return static_cast<NodeIndex>(s) * m_width; }
  /// Where the rows' runs lie: runs().walk(s, r).next(r) is row r's run in segment s, cols<I>(s)
  /// [begin] .. cols<I>(s)[begin + n - 1], each index relative to first_column(s); I is
  /// std::uint16_t where narrow(), else NodeIndex.
  const RunLengths& runs() const { return m_runs; }
  template <typename I>
  const I* cols(int s) const;
  std::size_t bytes() const {
    return m_indices * (m_narrow ? sizeof(std::uint16_t) : sizeof(NodeIndex)) + m_runs.bytes() +
           m_segment_start.size() * sizeof(std::size_t);
  }

 private:
  // The constructors' work; `taken`: cols itself, whose pages go back as they are copied.
  ColumnSegments(const std::vector<EdgeOffset>& row_ptr, const std::vector<NodeIndex>& cols,
                 NodeIndex columns, NodeIndex width, bool allow_narrow,
                 std::vector<NodeIndex>* taken);
  // Each row's runs into `out`, segment by segment, relative to the segment's first column;
  // where `release`, the pages of cols behind each thread's copy go back to the system.
  template <typename I>
  void copy_local(const std::vector<EdgeOffset>& row_ptr, const std::vector<NodeIndex>& cols,
                  I* out, bool release) const;

  int m_count = 1;
  NodeIndex m_width = 0;
  bool m_narrow = false;
  std::size_t m_rows = 0;
  std::vector<std::size_t> m_segment_start;  // count + 1: where each segment's entries begin
  RunLengths m_runs;
  // nnz + k_run_padding indices, segment-major: 16-bit where narrow(), else 32-bit. Arrays left
  // uninitialised until the copy writes them, so their pages are taken only as it goes.
  std::size_t m_indices = 0;
  std::unique_ptr<std::uint16_t[]> m_cols16;
  std::unique_ptr<NodeIndex[]> m_cols32;
};

template <>
inline const std::uint16_t* ColumnSegments::cols<std::uint16_t>(int s) const {
  return m_cols16.get() + m_segment_start[static_cast<std::size_t>(s)];
}

template <>
inline const NodeIndex* ColumnSegments::cols<NodeIndex>(int s) const {
  return m_cols32.get() + m_segment_start[static_cast<std::size_t>(s)];
}

}  // namespace hmfnet
