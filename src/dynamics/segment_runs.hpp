#pragma once
// One segment's pass of the segmented sparse kernel (column_segments.hpp, network_force.cpp):
// each row's run of entries in the segment added to the row's four carried partial sums of
// every replica. At N = 10^6, degree 100 a run is ~6 entries, and the scalar loop took ~15 ns a
// run on the Intel Xeon of docs/performance.md: instructions, not misses (N = 10^4 cut into 16
// segments with its table in L2 ran at 0.41 G entries/s against 2.0 uncut; bench
// SegmentedStep/10000/100/1/0/10). The AVX2 version takes a run's entries four at a time, entry
// (j - place) mod 4 of each block into partial j, the slots past the run's end masked to +0.0:
// a partial starts at +0.0 and, rounding to nearest, a sum of two values is -0.0 only when both
// are, so a partial is never -0.0 and adding +0.0 leaves its bits (x + 0.0 = x for every other
// x, inf and quiet NaN included; the partials are sums, never signalling NaNs). The same
// additions in the same order as the scalar loop: the same bits
// (tests/dynamics/test_segment_runs.cpp).
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "dynamics/run_lengths.hpp"
#include "network/network.hpp"

namespace hmfnet {

/// Bytes of one gathered record, the [cos, sin] pairs of B replicas in T: 8 (float32, B = 1),
/// 16 (float64, B = 1; float32, B = 2) up to 128 (float64, B = 8).
template <typename T, int B>
inline constexpr std::size_t k_record_bytes = 2 * static_cast<std::size_t>(B) * sizeof(T);

/// acc[b] += w q[b] for the n values of one gathered record. The lanes are independent sums, so
/// vectorising them keeps each one's order (the same bits). GCC 12 leaves the float32 lanes
/// scalar (addss and shuffles) unless told: `omp simd` doubles float32 B = 4 (bench/
/// ensemble_table.sh); on float64 it measured ~5% slower at B = 8, so float64 keeps the
/// compiler's own choice.
template <typename T>
inline void add_record(T* acc, const T* q, T w, int n) {
  if constexpr (sizeof(T) == sizeof(float)) {
#pragma omp simd
    for (int b = 0; b < n; ++b) acc[b] += w * q[b];
  } else {
    for (int b = 0; b < n; ++b) acc[b] += w * q[b];
  }
}

/// How the scalar loop adds one record: add_record over its n values (wide_rows.cpp has the same
/// in AVX2 and AVX-512 registers).
struct ScalarRecordAdd {
  template <typename T, int B, bool Weighted>
  static void add(T* acc, const T* q, T w, int n) {
    add_record(acc, q, w, n);
  }
};

/// Adds entries place .. place + n - 1 of a row whose first `full` entries precede its last
/// d mod 4 to the row's carried partials p (partial j of value v at p[j x record + v]): entry
/// k < full into partial k mod 4, the others into partial 0, as the unblocked kernels sum them.
/// The scalar loop, for every replica count and for weighted networks: one loop whatever the
/// run's first place (in scalars, a rotation of four register accumulators with its remainder
/// branches measured no faster, bench SegmentedStep, Intel Xeon; records of one AVX2 or AVX-512
/// register take such a rotation in wide_rows.cpp, RegisterRun). Always inlined: a caller
/// compiled for a wider instruction set (wide_rows.cpp) compiles it in that set.
template <typename T, int B, bool Weighted, typename I, typename Add = ScalarRecordAdd>
[[gnu::always_inline]] inline void add_run(T* p, const T* table, const I* cols, const T* w,
                                           EdgeOffset place, EdgeOffset n, EdgeOffset full,
                                           int nb) {
  const auto record = 2 * static_cast<std::ptrdiff_t>(B > 0 ? B : nb);
  const EdgeOffset split = std::clamp<EdgeOffset>(full - place, 0, n);
  for (EdgeOffset i = 0; i < n; ++i) {
    T* acc = i < split ? p + ((place + i) & 3) * record : p;
    Add::template add<T, B, Weighted>(acc, table + record * cols[i], Weighted ? w[i] : T(1),
                                      static_cast<int>(record));
  }
}

/// Entries ColumnSegments keeps after its last column index: the two blocks of four that a run
/// takes at least may read up to seven past its end (their records are loaded, masked, and
/// never added).
inline constexpr std::size_t k_run_padding = 8;

/// How a run reaches its row's partials: add_run's loop, each record added by Add (the default:
/// add_record). A policy of this shape with a loop of its own may replace it (wide_rows.cpp: the
/// partials in registers for the run).
template <typename Add = ScalarRecordAdd>
struct RecordRun {
  template <typename T, int B, bool Weighted, typename I>
  [[gnu::always_inline]] static void add(T* p, const T* table, const I* cols, const T* w,
                                         EdgeOffset place, EdgeOffset n, EdgeOffset full, int nb) {
    add_run<T, B, Weighted, I, Add>(p, table, cols, w, place, n, full, nb);
  }
};

/// One segment's pass, as the kernel hands it over; I: the type of its column indices
/// (ColumnSegments: std::uint16_t or NodeIndex).
template <typename T, typename I>
struct SegmentPass {
  const EdgeOffset* row_ptr;  // the CSR: a row's degree fixes where its last d mod 4 entries begin
  const RunLengths* runs;     // where each row's run lies in `cols`: runs->walk(segment, r)
  int segment;                // which of runs' segments this pass walks
  const I* cols;              // the segment's column indices, k_run_padding readable after them
  const T* table;             // the gathered [cos, sin] from the segment's first column on, 2B
                              // values a column: cols index it
  T* carry;                   // 4 partials x 2B values a row, from row `origin` on
  std::uint32_t* cursor;      // the place in its row where each row's next run begins, likewise
  bool first;                 // the carry starts at +0.0 and the runs at place 0
  bool last;                  // the cursor is not written
  NodeIndex origin = 0;       // the row whose partials and cursor come first in carry and cursor
};

/// Rows [r0, r1) of one segment in the scalar loop, for every replica count (B > 0 fixed at
/// compile time, 0: nb at run time) and for weighted rows (`weights`: the CSR's, nullptr on a
/// 0/1 network); each run added by Run (wide_rows.cpp: its records in wide registers, or the
/// run's partials in them).
template <typename T, int B, bool Weighted, typename I, typename Run = RecordRun<>>
[[gnu::always_inline]] inline void scalar_segment_runs(const SegmentPass<T, I>& pass,
                                                       const T* weights, int nb, NodeIndex r0,
                                                       NodeIndex r1) {
  const std::size_t stride = 8 * static_cast<std::size_t>(B > 0 ? B : nb);
  RunWalk walk = pass.runs->walk(pass.segment, r0);
  for (NodeIndex r = r0; r < r1; ++r) {
    const auto slot = static_cast<std::size_t>(r - pass.origin);
    T* p = pass.carry + slot * stride;
    if (pass.first) std::fill(p, p + stride, T(0));
    const EdgeOffset begin = pass.row_ptr[r], degree = pass.row_ptr[r + 1] - begin;
    const EdgeOffset place = pass.first ? 0 : pass.cursor[slot];
    const RunSpan run = walk.next(r);
    const EdgeOffset n = run.n;
    const T* w = Weighted ? weights + begin + place : nullptr;
    Run::template add<T, B, Weighted, I>(p, pass.table, pass.cols + run.begin, w, place, n,
                                         degree / 4 * 4, nb);
    if (!pass.last) pass.cursor[slot] = static_cast<std::uint32_t>(place + n);
  }
}

/// Whether add_segment_runs runs its AVX2 version for `replicas` replicas of T on this CPU, in
/// the instruction set that sincos_isa() allows (HMFNET_SINCOS_ISA=baseline: none): records of 8
/// or 16 bytes (float64 B = 1, float32 B = 1 and 2), where it measured faster than the scalar
/// loop (docs/performance.md, "Segment runs in AVX2").
template <typename T>
bool segment_runs_vectorised(int replicas);

/// Rows [r0, r1) of one segment on a 0/1 network, `replicas` 1 or 2 (a precondition: it runs
/// inside a thread team, where nothing may throw): the AVX2 version where `vector` and
/// segment_runs_vectorised, else the scalar loop; the same bits either way.
template <typename T, typename I>
void add_segment_runs(const SegmentPass<T, I>& pass, int replicas, NodeIndex r0, NodeIndex r1,
                      bool vector);

}  // namespace hmfnet
