#pragma once
// The sparse kernel's row loops for 2, 4 or 8 replicas in AVX2 or AVX-512 registers: the
// unblocked rows (wide_rows) and a segment's runs (wide_segment_runs); other counts in groups:
// unblocked rows in groups of 8, 4 and 2 replicas and single replicas (24 = 8 + 8 + 8, 11 = 8 +
// 2 + 1); a segment's records in pairs of the widest registers, then one, then a 32-byte one
// (AVX-512), the values left in scalars. The
// build is x86-64 baseline, where a gathered record of 2B values of T takes 2B sizeof(T) / 16 SSE2
// loads and adds (eight of each for float64, B = 8) and the row is walked up to four times (float64
// B = 8; twice for float64 B = 4 and float32 B = 8) to keep the accumulators in 16 registers. Here
// a record is one or two 64-byte registers (AVX-512) or one to four 32-byte ones (AVX2), and the
// row is walked once (AVX-512) or at most twice (AVX2, float64 B = 8).
//
// The same sums as rows_kernel in network_force.cpp, bit for bit: the replicas' values are
// independent lanes, each lane receives the same IEEE additions (and, on a weighted network, the
// same products w q, never contracted into a fused multiply-add: src/CMakeLists.txt) in the same
// order: partial j over the row's entries j, j + 4, ... of its first 4 floor(d / 4), the last
// d mod 4 into partial 0, every partial from +0.0, combined by finish_row
// (tests/dynamics/test_wide_rows.cpp). A segment's runs are segment_runs.hpp's scalar loop with
// each record added in these registers, to the carried partials in memory, or, where a record
// fills one register, the same additions with a run's four partials held in registers.
#include "dynamics/row_kernel_args.hpp"
#include "dynamics/segment_runs.hpp"
#include "dynamics/sincos.hpp"

namespace hmfnet {

/// Whether wide_rows has a version for `replicas` replicas of T in `isa` (which this CPU must
/// run): records of at least 32 bytes (float64 B = 2, 4, 8; float32 B = 4, 8) in AVX2 or
/// AVX-512; nothing in the baseline set or off x86-64.
template <typename T>
bool wide_rows_serve(int replicas, SincosIsa isa);

/// Whether wide_rows and wide_segment_runs run `replicas` replicas of T in `isa` in groups: every
/// count other than 1, 2, 4 and 8 in AVX2 or AVX-512 (which this CPU must run). Rows of a count
/// that the baseline loops serve at a run-time width: float64 ER N = 2000, degree 100, 16 and 24
/// replicas, 1 thread on an Intel Xeon (family 6 model 106) gathered 0.59 and 0.72 G entries x
/// replicas / s there, against 2.88 for 8 replicas.
template <typename T>
bool wide_groups_serve(int replicas, SincosIsa isa);

/// Whether wide_rows and wide_segment_runs run `replicas` replicas of T in `isa` at all, in a
/// version of their own (wide_rows_serve) or in groups (wide_groups_serve): every count but one
/// replica (rows_kernel_single) and float32 with two (a 16-byte record, the baseline loops') in
/// AVX2 or AVX-512. The one predicate the force's kernel choice, its segment rule and the tests
/// read, so they cannot disagree on which loops run.
template <typename T>
bool wide_loops_serve(int replicas, SincosIsa isa) {
  return wide_rows_serve<T>(replicas, isa) || wide_groups_serve<T>(replicas, isa);
}

/// The partial sums one walk of a row forms in the unblocked kernel that runs `replicas`
/// replicas of T in `isa` (4: the row is walked once; 2: twice; 1: four times): wide_rows'
/// version where wide_rows_serve, as many as keep their accumulators within half the register
/// file (AVX-512: 32 registers of 64 bytes, AVX2: 16 of 32); else network_force.cpp's baseline
/// loops (row_kernel_args.hpp: baseline_walk_partials; one walk at a run-time count there and
/// for the single replicas of a grouped count, whose groups walk as 8, 4 or 2 replicas do).
template <typename T>
int row_walk_partials(int replicas, SincosIsa isa);

/// Rows [0, rows) as rows_kernel forms them, in `isa`, where wide_loops_serve: an orphaned
/// `omp for` (every thread of a team calls it; outside one, one thread does all the rows). I:
/// the column indices' type (RowKernelArgs).
template <typename T, typename I>
void wide_rows(const RowKernelArgs<T, I>& a, NodeIndex rows, int replicas, SincosIsa isa);

/// Rows [r0, r1) of one segment as scalar_segment_runs adds them (`weights`: the CSR's, nullptr
/// on a 0/1 network), in `isa`, where wide_loops_serve (the same records).
template <typename T, typename I>
void wide_segment_runs(const SegmentPass<T, I>& pass, const T* weights, int replicas, NodeIndex r0,
                       NodeIndex r1, SincosIsa isa);

}  // namespace hmfnet
