#include "dynamics/wide_rows.hpp"

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "dynamics/segment_runs.hpp"
#include "dynamics/wide_lanes.hpp"

#if defined(__x86_64__)
#define HMFNET_WIDE_ROWS_X86 1
#endif

namespace hmfnet {

namespace {

#if defined(HMFNET_WIDE_ROWS_X86)

// The register files: AVX-512's 32 registers of 64 bytes and AVX2's 16 of 32, half of each the
// budget for a walk's accumulators (the rest hold loads, and the weights where there are some).
inline constexpr std::size_t k_avx512_bytes = 64, k_avx512_budget = 16;
inline constexpr std::size_t k_avx2_bytes = 32, k_avx2_budget = 8;

// The partials one walk of a row forms: as many as keep their accumulators, `registers` each,
// within `budget`.
constexpr std::size_t partials_within(std::size_t registers, std::size_t budget) {
  return 4 * registers <= budget ? 4 : 2 * registers <= budget ? 2 : 1;
}

// The shape of one version: records of 2B values of T in V-byte registers.
template <typename T, int B, std::size_t V, std::size_t budget>
struct Shape {
  static constexpr std::size_t k_record = 2 * static_cast<std::size_t>(B);
  static constexpr std::size_t k_per_register = V / sizeof(T);
  static constexpr std::size_t k_registers = k_record / k_per_register;
  static constexpr std::size_t k_partials = partials_within(k_registers, budget);
  static_assert(k_record % k_per_register == 0, "a record fills whole registers");
};

// Where a group of replicas sits in the gathered table and the outputs: a node's record of
// `stride` values of T (2 nb, nb the run's replicas), the group's from `offset` (2 x its first
// replica) on. A run whose count has a version of its own is one group: stride 2B, offset 0,
// constants once inlined.
struct GroupPlace {
  std::size_t stride;
  std::size_t offset;
};

// acc += w q (or q on a 0/1 network) for the group's values of entry e's record.
template <typename T, typename S, std::size_t V, bool Weighted, typename I>
HMFNET_LANES_INLINE void add_entry(Lanes<T, V> (&acc)[S::k_registers], const RowKernelArgs<T, I>& a,
                                   EdgeOffset e, GroupPlace place) {
  const T* q = a.column_cs + place.stride * static_cast<std::size_t>(a.cols[e]) + place.offset;
  add_lanes<T, V, S::k_record, Weighted>(acc, q, Weighted ? a.weights[e] : T(1));
}

// A register's [cos, sin] pairs swapped, and the cos lanes of two registers interleaved
// ([a_0, b_0, a_2, b_2, ...]), for W = 4 or 8 doubles (GCC 12 and clang both have
// __builtin_shufflevector).
template <typename D>
HMFNET_LANES_INLINE D swap_pairs(const D& v) {
  if constexpr (sizeof(D) == 64) {
    return __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6);
  } else {
    static_assert(sizeof(D) == 32, "4 or 8 doubles");
    return __builtin_shufflevector(v, v, 1, 0, 3, 2);
  }
}
template <typename D>
HMFNET_LANES_INLINE D cos_lanes(const D& a, const D& b) {
  if constexpr (sizeof(D) == 64) {
    return __builtin_shufflevector(a, b, 0, 8, 2, 10, 4, 12, 6, 14);
  } else {
    return __builtin_shufflevector(a, b, 0, 4, 2, 6);
  }
}

// finish_row's outputs (float64) of the group's replicas whose values sit in [c, c + W) of the
// four partials at p (partial j at p[j 2B]; W doubles a register), lane by lane (float64 B = 4 and
// 8: 1.04-1.14x the scalar finish, N = 10^4, 1 and 2 threads): the same IEEE operations on the same
// operands in the same order. With y = (yc, ys) and the row's own o = (c, s) in adjacent lanes, and
// x~ the pairs of x swapped: y * y + (y * y)~ is yc yc + ys ys in the cos lane, o * y + (o * y)~ is
// c yc + s ys there, and o * y~ - (o * y~)~ is c ys - s yc; the terms take the cos lanes of the
// first two, g that of the third times 1/N. sqrt is correctly rounded in every set (vsqrtpd;
// -fno-math-errno lets GCC use it for the lanes).
template <typename T, int B, std::size_t W, typename I>
HMFNET_LANES_INLINE void finish_lanes(const RowKernelArgs<T, I>& a, NodeIndex r, const T* p,
                                      std::size_t c, GroupPlace place) {
  constexpr std::size_t record = 2 * static_cast<std::size_t>(B);
  using D = Lanes<double, W * sizeof(double)>;
  D s[4];
  for (std::size_t j = 0; j < 4; ++j) load_lanes<double, sizeof(D)>(s[j], p + j * record + c);
  const D y = (s[0] + s[1]) + (s[2] + s[3]);
  const std::size_t at = place.stride * static_cast<std::size_t>(r) + place.offset + c;
  D o;
  load_lanes<double, sizeof(D)>(o, a.owned_cs + at);
  const D cross = o * swap_pairs(y);
  const D g = a.inverse_n * (cross - swap_pairs(cross));
  std::memcpy(a.y + at, &y, sizeof y);
  for (std::size_t j = 0; j < W; j += 2) a.g[at / 2 + j / 2] = g[j];
  if (a.terms == nullptr) return;
  const D q = y * y, dot = o * y;
  D norm = q + swap_pairs(q);
  for (std::size_t j = 0; j < W; ++j) norm[j] = __builtin_sqrt(norm[j]);
  const D coupling = dot + swap_pairs(dot);
  const D terms = cos_lanes(norm, coupling);
  std::memcpy(a.terms + at, &terms, sizeof terms);
}

// Row r's walks for one group of B replicas: rows_kernel's walks, C = S::k_partials partials a
// walk, then the group's outputs.
template <typename T, int B, std::size_t V, std::size_t budget, bool Weighted, typename I>
HMFNET_LANES_INLINE void row_group(const RowKernelArgs<T, I>& a, NodeIndex r, GroupPlace place) {
  using S = Shape<T, B, V, budget>;
  constexpr std::size_t C = S::k_partials;
  const EdgeOffset begin = a.row_ptr[r], end = a.row_ptr[r + 1];
  const EdgeOffset full = begin + (end - begin) / 4 * 4;
  alignas(64) T partial[4][S::k_record];
#pragma GCC unroll 4
  for (std::size_t pass = 0; pass < 4; pass += C) {
    Lanes<T, V> acc[C][S::k_registers] = {};  // every lane +0.0
    for (EdgeOffset k = begin; k < full; k += 4) {
#pragma GCC unroll 4
      for (std::size_t c = 0; c < C; ++c)
        add_entry<T, S, V, Weighted>(acc[c], a, k + static_cast<EdgeOffset>(pass + c), place);
    }
    if (pass == 0) {
      for (EdgeOffset k = full; k < end; ++k) add_entry<T, S, V, Weighted>(acc[0], a, k, place);
    }
#pragma GCC unroll 4
    for (std::size_t c = 0; c < C; ++c) std::memcpy(partial[pass + c], acc[c], sizeof acc[c]);
  }
  if constexpr (sizeof(T) == sizeof(double)) {
    // Doubles a register: the set's, or the record's where it is shorter (B = 2 in AVX-512).
    constexpr std::size_t w = std::min(V, S::k_record * sizeof(double)) / sizeof(double);
#pragma GCC unroll 4
    for (std::size_t c = 0; c < S::k_record; c += w) {
      finish_lanes<T, B, w>(a, r, &partial[0][0], c, place);
    }
  } else {
    // float32: the lanes measured 0.95x the scalar finish (B = 8, N = 10^4, 1 thread, 5 rounds).
    const auto nb = static_cast<int>(place.stride / 2), first = static_cast<int>(place.offset / 2);
    finish_replicas(a, r, &partial[0][0], S::k_record, nb, first, B);
  }
}

// The row loop of one version: every row one group of all B replicas.
template <typename T, int B, std::size_t V, std::size_t budget, bool Weighted, typename I>
HMFNET_LANES_INLINE void rows_body(const RowKernelArgs<T, I>& a, NodeIndex rows) {
#pragma omp for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    row_group<T, B, V, budget, Weighted>(a, r, GroupPlace{2 * static_cast<std::size_t>(B), 0});
  }
}

// Replica b of a run of nb, alone, where no register of the set fits what is left of the count
// (float64: one replica; float32: one to three): rows_kernel_single's four partials, in scalars.
template <typename T, bool Weighted, typename I>
HMFNET_LANES_INLINE void row_lane(const RowKernelArgs<T, I>& a, NodeIndex r, int nb, int b) {
  const auto stride = 2 * static_cast<std::size_t>(nb), offset = 2 * static_cast<std::size_t>(b);
  const EdgeOffset begin = a.row_ptr[r], end = a.row_ptr[r + 1];
  const EdgeOffset full = begin + (end - begin) / 4 * 4;
  T p[4][2] = {};  // every partial +0.0
  const auto add = [&](T* acc, EdgeOffset e) {
    const T* q = a.column_cs + stride * static_cast<std::size_t>(a.cols[e]) + offset;
    const T w = Weighted ? a.weights[e] : T(1);
    acc[0] += w * q[0];
    acc[1] += w * q[1];
  };
  for (EdgeOffset k = begin; k < full; k += 4) {
    for (std::size_t j = 0; j < 4; ++j) add(p[j], k + static_cast<EdgeOffset>(j));
  }
  for (EdgeOffset k = full; k < end; ++k) add(p[0], k);
  finish_replicas(a, r, &p[0][0], 2, nb, b, 1);
}

// A run-time count nb in groups of 8, then 4 and 2 replicas, each of whole registers of at most
// V bytes, and the replicas left one at a time. Each replica's lane receives the additions it
// would receive in a run of its own (the replicas are independent lanes), so the grouping
// changes no bit; the row's indices are read once per group, from L1 after the first.
template <typename T, std::size_t V, std::size_t budget, bool Weighted, typename I>
HMFNET_LANES_INLINE void grouped_rows_body(const RowKernelArgs<T, I>& a, NodeIndex rows, int nb) {
  const auto stride = 2 * static_cast<std::size_t>(nb);
  const auto place = [stride](int b) {
    return GroupPlace{stride, 2 * static_cast<std::size_t>(b)};
  };
#pragma omp for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    int b = 0;
    for (; nb - b >= 8; b += 8) {
      row_group<T, 8, std::min(V, k_record_bytes<T, 8>), budget, Weighted>(a, r, place(b));
    }
    if (nb - b >= 4) {
      row_group<T, 4, std::min(V, k_record_bytes<T, 4>), budget, Weighted>(a, r, place(b));
      b += 4;
    }
    if constexpr (k_record_bytes<T, 2> >= 32) {
      if (nb - b >= 2) {
        row_group<T, 2, std::min(V, k_record_bytes<T, 2>), budget, Weighted>(a, r, place(b));
        b += 2;
      }
    }
    for (; b < nb; ++b) row_lane<T, Weighted>(a, r, nb, b);
  }
}

// 32 registers of 64 bytes; a record of 32 bytes takes a 32-byte register (AVX-512 has AVX2).
template <typename T, int B, bool Weighted, typename I>
__attribute__((target("avx512f,avx512dq"))) void rows_avx512(const RowKernelArgs<T, I>& a,
                                                             NodeIndex rows) {
  rows_body<T, B, std::min(k_avx512_bytes, k_record_bytes<T, B>), k_avx512_budget, Weighted>(a,
                                                                                             rows);
}

// 16 registers of 32 bytes.
template <typename T, int B, bool Weighted, typename I>
__attribute__((target("avx2"))) void rows_avx2(const RowKernelArgs<T, I>& a, NodeIndex rows) {
  rows_body<T, B, k_avx2_bytes, k_avx2_budget, Weighted>(a, rows);
}

template <typename T, bool Weighted, typename I>
__attribute__((target("avx512f,avx512dq"))) void grouped_rows_avx512(const RowKernelArgs<T, I>& a,
                                                                     NodeIndex rows, int nb) {
  grouped_rows_body<T, k_avx512_bytes, k_avx512_budget, Weighted>(a, rows, nb);
}

template <typename T, bool Weighted, typename I>
__attribute__((target("avx2"))) void grouped_rows_avx2(const RowKernelArgs<T, I>& a, NodeIndex rows,
                                                       int nb) {
  grouped_rows_body<T, k_avx2_bytes, k_avx2_budget, Weighted>(a, rows, nb);
}

template <typename T, int B, bool Weighted, typename I>
void rows_in(const RowKernelArgs<T, I>& a, NodeIndex rows, SincosIsa isa) {
  if constexpr (k_record_bytes<T, B> >= 32) {
    if (isa == SincosIsa::avx512) {
      rows_avx512<T, B, Weighted>(a, rows);
    } else {
      rows_avx2<T, B, Weighted>(a, rows);
    }
  }
}

// The counts wide_rows_serve allows, and in groups those wide_groups_serve allows; nothing for
// another (a precondition of the callers).
template <typename T, bool Weighted, typename I>
void dispatch(const RowKernelArgs<T, I>& a, NodeIndex rows, int replicas, SincosIsa isa) {
  switch (replicas) {
    case 2:
      rows_in<T, 2, Weighted>(a, rows, isa);
      break;
    case 4:
      rows_in<T, 4, Weighted>(a, rows, isa);
      break;
    case 8:
      rows_in<T, 8, Weighted>(a, rows, isa);
      break;
    default:
      if (isa == SincosIsa::avx512) {
        grouped_rows_avx512<T, Weighted>(a, rows, replicas);
      } else {
        grouped_rows_avx2<T, Weighted>(a, rows, replicas);
      }
      break;
  }
}

// The scalar segment loop's record added in registers of at most `widest` bytes.
template <std::size_t widest>
struct WideRecordAdd {
  template <typename T, int B, bool Weighted>
  static HMFNET_LANES_INLINE void add(T* acc, const T* q, T w, int /*n*/) {
    constexpr std::size_t bytes = k_record_bytes<T, B>;
    add_lanes_at<T, std::min(widest, bytes), 2 * static_cast<std::size_t>(B), Weighted>(acc, q, w);
  }
};

// A run of a compiled count whose record fills one register, with its row's four partials in
// four registers for the whole run: loaded once and stored once, where add_run loads and stores
// a partial at every entry (a chain through memory from one entry of a partial to its next). The
// same additions in the same order, entry place + i into partial (place + i) mod 4 before `full`
// and into partial 0 after it, so the same bits; the rotation is unrolled from the run's first
// place, as no register can be indexed at run time.
struct RegisterRun {
  template <typename T, int B, bool Weighted, typename I>
  static HMFNET_LANES_INLINE void add(T* p, const T* table, const I* cols, const T* w,
                                      EdgeOffset place, EdgeOffset n, EdgeOffset full, int /*nb*/) {
    constexpr std::size_t record = 2 * static_cast<std::size_t>(B), V = k_record_bytes<T, B>;
    if (n == 0) return;  // the partials as they are (a narrow segment leaves most runs empty)
    Lanes<T, V> acc[4];
    for (std::size_t j = 0; j < 4; ++j) load_lanes<T, V>(acc[j], p + j * record);
    // Always inlined, as everything holding a vector here (wide_lanes.hpp): a lambda's own
    // function would be compiled outside the caller's instruction set.
    const auto entry = [&](Lanes<T, V> & a, EdgeOffset i) __attribute__((always_inline)) {
      add_lanes<T, V, record, Weighted>(&a, table + record * static_cast<std::size_t>(cols[i]),
                                        Weighted ? w[i] : T(1));
    };
    const EdgeOffset split = std::clamp<EdgeOffset>(full - place, 0, n);
    const EdgeOffset first = place & 3;
    EdgeOffset i = 0;
    if (first == 1 && i < split) entry(acc[1], i++);
    if ((first == 1 || first == 2) && i < split) entry(acc[2], i++);
    if (first != 0 && i < split) entry(acc[3], i++);
    for (; i + 4 <= split; i += 4) {
      entry(acc[0], i);
      entry(acc[1], i + 1);
      entry(acc[2], i + 2);
      entry(acc[3], i + 3);
    }
    if (i < split) entry(acc[0], i++);
    if (i < split) entry(acc[1], i++);
    if (i < split) entry(acc[2], i++);
    for (; i < n; ++i) entry(acc[0], i);
    for (std::size_t j = 0; j < 4; ++j) std::memcpy(p + j * record, &acc[j], V);
  }
};

// A compiled count's runs: RegisterRun where a record fills one register of the set (float64
// B = 2 and 4, float32 B = 4 and 8 in AVX-512; float64 B = 2, float32 B = 4 in AVX2), else
// add_run's loop over records in registers of at most V bytes. ER N = 10^5, degree 100 (the
// rule's ~16 segments, runs of ~6 entries), 1 thread, `hmfnet simulate`, against the loop,
// medians of 7 alternated rounds (Intel Xeon family 6 model 106): float64 B = 2 and 4 1.21x;
// float32 B = 4 1.13x and B = 8 1.02x, within the scatter of the unchanged float64 B = 8
// (0.82-1.04x). Records of two AVX-512 registers (float64 B = 8: 8 partial registers loaded and
// stored a run) measured 0.81-0.89x in registers, so records of two registers keep the loop
// (AVX2's float64 B = 4 and float32 B = 8 by that measurement, not their own).
template <typename T, int B, std::size_t V>
using CompiledRun =
    std::conditional_t<k_record_bytes<T, B> <= V, RegisterRun, RecordRun<WideRecordAdd<V>>>;

// The same for a run-time count's record of n values: in registers of `widest` bytes, pairs of
// them first (8 replicas of float64 in AVX-512), then one, then a 32-byte one (AVX-512), the
// values left in scalars. Each value is its own sum, so how the record is cut changes no bit.
template <std::size_t widest>
struct GroupedRecordAdd {
  template <typename T, int B, bool Weighted>
  static HMFNET_LANES_INLINE void add(T* acc, const T* q, T w, int n) {
    static_assert(B == 0, "a run-time count");
    constexpr int per = static_cast<int>(widest / sizeof(T));
    int v = 0;
    for (; n - v >= 2 * per; v += 2 * per) {
      add_lanes_at<T, widest, 2 * per, Weighted>(acc + v, q + v, w);
    }
    if (n - v >= per) {
      add_lanes_at<T, widest, per, Weighted>(acc + v, q + v, w);
      v += per;
    }
    if constexpr (widest > 32) {
      constexpr int half = static_cast<int>(32 / sizeof(T));
      if (n - v >= half) {
        add_lanes_at<T, 32, half, Weighted>(acc + v, q + v, w);
        v += half;
      }
    }
    for (; v < n; ++v) acc[v] += (Weighted ? w : T(1)) * q[v];
  }
};

template <typename T, bool Weighted, typename I>
__attribute__((target("avx512f,avx512dq"))) void grouped_runs_avx512(const SegmentPass<T, I>& pass,
                                                                     const T* weights, int nb,
                                                                     NodeIndex r0, NodeIndex r1) {
  scalar_segment_runs<T, 0, Weighted, I, RecordRun<GroupedRecordAdd<k_avx512_bytes>>>(pass, weights,
                                                                                      nb, r0, r1);
}

template <typename T, bool Weighted, typename I>
__attribute__((target("avx2"))) void grouped_runs_avx2(const SegmentPass<T, I>& pass,
                                                       const T* weights, int nb, NodeIndex r0,
                                                       NodeIndex r1) {
  scalar_segment_runs<T, 0, Weighted, I, RecordRun<GroupedRecordAdd<k_avx2_bytes>>>(pass, weights,
                                                                                    nb, r0, r1);
}

template <typename T, typename I>
void grouped_runs_in(const SegmentPass<T, I>& pass, const T* weights, int nb, NodeIndex r0,
                     NodeIndex r1, SincosIsa isa) {
  const bool avx512 = isa == SincosIsa::avx512;
  if (weights == nullptr) {
    avx512 ? grouped_runs_avx512<T, false, I>(pass, weights, nb, r0, r1)
           : grouped_runs_avx2<T, false, I>(pass, weights, nb, r0, r1);
  } else {
    avx512 ? grouped_runs_avx512<T, true, I>(pass, weights, nb, r0, r1)
           : grouped_runs_avx2<T, true, I>(pass, weights, nb, r0, r1);
  }
}

template <typename T, int B, bool Weighted, typename I>
__attribute__((target("avx512f,avx512dq"))) void runs_avx512(const SegmentPass<T, I>& pass,
                                                             const T* weights, NodeIndex r0,
                                                             NodeIndex r1) {
  scalar_segment_runs<T, B, Weighted, I, CompiledRun<T, B, k_avx512_bytes>>(pass, weights, B, r0,
                                                                            r1);
}

template <typename T, int B, bool Weighted, typename I>
__attribute__((target("avx2"))) void runs_avx2(const SegmentPass<T, I>& pass, const T* weights,
                                               NodeIndex r0, NodeIndex r1) {
  scalar_segment_runs<T, B, Weighted, I, CompiledRun<T, B, k_avx2_bytes>>(pass, weights, B, r0, r1);
}

template <typename T, int B, typename I>
void runs_in(const SegmentPass<T, I>& pass, const T* weights, NodeIndex r0, NodeIndex r1,
             SincosIsa isa) {
  if constexpr (k_record_bytes<T, B> >= 32) {
    const bool avx512 = isa == SincosIsa::avx512;
    if (weights == nullptr) {
      avx512 ? runs_avx512<T, B, false, I>(pass, weights, r0, r1)
             : runs_avx2<T, B, false, I>(pass, weights, r0, r1);
    } else {
      avx512 ? runs_avx512<T, B, true, I>(pass, weights, r0, r1)
             : runs_avx2<T, B, true, I>(pass, weights, r0, r1);
    }
  }
}

template <typename T, typename I>
void dispatch_runs(const SegmentPass<T, I>& pass, const T* weights, int replicas, NodeIndex r0,
                   NodeIndex r1, SincosIsa isa) {
  switch (replicas) {
    case 2:
      runs_in<T, 2, I>(pass, weights, r0, r1, isa);
      break;
    case 4:
      runs_in<T, 4, I>(pass, weights, r0, r1, isa);
      break;
    case 8:
      runs_in<T, 8, I>(pass, weights, r0, r1, isa);
      break;
    default:
      grouped_runs_in<T, I>(pass, weights, replicas, r0, r1, isa);
      break;
  }
}

#endif

}  // namespace

template <typename T>
bool wide_rows_serve(int replicas, SincosIsa isa) {
#if defined(HMFNET_WIDE_ROWS_X86)
  const bool counted = replicas == 2 || replicas == 4 || replicas == 8;
  const std::size_t record = 2 * static_cast<std::size_t>(replicas) * sizeof(T);
  return counted && record >= 32 && isa != SincosIsa::baseline && sincos_isa_available(isa);
#else
  static_cast<void>(replicas);
  static_cast<void>(isa);
  return false;
#endif
}

template <typename T>
bool wide_groups_serve(int replicas, SincosIsa isa) {
#if defined(HMFNET_WIDE_ROWS_X86)
  const bool counted = replicas == 1 || replicas == 2 || replicas == 4 || replicas == 8;
  return replicas > 0 && !counted && isa != SincosIsa::baseline && sincos_isa_available(isa);
#else
  static_cast<void>(replicas);
  static_cast<void>(isa);
  return false;
#endif
}

template <typename T>
int row_walk_partials(int replicas, SincosIsa isa) {
  const std::size_t record = 2 * static_cast<std::size_t>(replicas) * sizeof(T);
#if defined(HMFNET_WIDE_ROWS_X86)
  if (wide_rows_serve<T>(replicas, isa)) {
    const bool avx512 = isa == SincosIsa::avx512;
    const std::size_t width = std::min(avx512 ? k_avx512_bytes : k_avx2_bytes, record);
    return static_cast<int>(
        partials_within(record / width, avx512 ? k_avx512_budget : k_avx2_budget));
  }
#else
  static_cast<void>(isa);
#endif
  const bool compiled = replicas == 1 || replicas == 2 || replicas == 4 || replicas == 8;
  return compiled ? baseline_walk_partials(record) : 4;  // run-time counts: one walk
}

template <typename T, typename I>
void wide_rows(const RowKernelArgs<T, I>& a, NodeIndex rows, int replicas, SincosIsa isa) {
#if defined(HMFNET_WIDE_ROWS_X86)
  if (a.weights == nullptr) {
    dispatch<T, false>(a, rows, replicas, isa);
  } else {
    dispatch<T, true>(a, rows, replicas, isa);
  }
#else
  static_cast<void>(a);
  static_cast<void>(rows);
  static_cast<void>(replicas);
  static_cast<void>(isa);
#endif
}

template <typename T, typename I>
void wide_segment_runs(const SegmentPass<T, I>& pass, const T* weights, int replicas, NodeIndex r0,
                       NodeIndex r1, SincosIsa isa) {
#if defined(HMFNET_WIDE_ROWS_X86)
  dispatch_runs(pass, weights, replicas, r0, r1, isa);
#else
  static_cast<void>(pass);
  static_cast<void>(weights);
  static_cast<void>(replicas);
  static_cast<void>(r0);
  static_cast<void>(r1);
  static_cast<void>(isa);
#endif
}

template bool wide_rows_serve<double>(int, SincosIsa);
template bool wide_groups_serve<double>(int, SincosIsa);
template bool wide_groups_serve<float>(int, SincosIsa);
template int row_walk_partials<double>(int, SincosIsa);
template int row_walk_partials<float>(int, SincosIsa);
template bool wide_rows_serve<float>(int, SincosIsa);
template void wide_rows(const RowKernelArgs<double>&, NodeIndex, int, SincosIsa);
template void wide_rows(const RowKernelArgs<float>&, NodeIndex, int, SincosIsa);
template void wide_rows(const RowKernelArgs<double, std::uint16_t>&, NodeIndex, int, SincosIsa);
template void wide_rows(const RowKernelArgs<float, std::uint16_t>&, NodeIndex, int, SincosIsa);

template void wide_segment_runs(const SegmentPass<double, std::uint16_t>&, const double*, int,
                                NodeIndex, NodeIndex, SincosIsa);
template void wide_segment_runs(const SegmentPass<double, NodeIndex>&, const double*, int,
                                NodeIndex, NodeIndex, SincosIsa);
template void wide_segment_runs(const SegmentPass<float, std::uint16_t>&, const float*, int,
                                NodeIndex, NodeIndex, SincosIsa);
template void wide_segment_runs(const SegmentPass<float, NodeIndex>&, const float*, int, NodeIndex,
                                NodeIndex, SincosIsa);

}  // namespace hmfnet
