#include "dynamics/segment_runs.hpp"

#include <cstring>

#include "dynamics/sincos.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define HMFNET_SEGMENT_RUNS_AVX2 1
#endif

namespace hmfnet {

namespace {

// A row's run in this segment: where it starts in the row, its length, and how many of its
// entries come before the row's last d mod 4.
struct Run {
  EdgeOffset place;  // the run's first entry's place in the row
  EdgeOffset n;      // entries in the run
  EdgeOffset split;  // the run's entries before the row's last d mod 4
};

template <typename T, typename I>
inline Run run_of(const SegmentPass<T, I>& pass, NodeIndex r, EdgeOffset n) {
  const EdgeOffset place = pass.first ? 0 : pass.cursor[r - pass.origin];
  const EdgeOffset full = (pass.row_ptr[r + 1] - pass.row_ptr[r]) / 4 * 4;
  return {place, n, std::clamp<EdgeOffset>(full - place, 0, n)};
}

#if defined(HMFNET_SEGMENT_RUNS_AVX2)
#define HMFNET_AVX2 __attribute__((target("avx2")))

// The 256-bit registers of a row's four partials: 4 x 2B values of T, 32 bytes each.
template <typename T, int B>
inline constexpr std::size_t k_registers = 8 * static_cast<std::size_t>(B) * sizeof(T) / 32;

HMFNET_AVX2 inline __m256d add_bits(__m256d acc, __m256d v, double /*type*/) {
  return _mm256_add_pd(acc, v);
}
HMFNET_AVX2 inline __m256d add_bits(__m256d acc, __m256d v, float /*type*/) {
  return _mm256_castps_pd(_mm256_add_ps(_mm256_castpd_ps(acc), _mm256_castpd_ps(v)));
}

// The four records of a block, partial j's in the j-th quarter of the registers (all of a
// register's 64-bit lanes from one record when a record fills it).
template <typename T, int B, typename I>
HMFNET_AVX2 inline void load_block(const char* table, const I* const at[4], EdgeOffset i,
                                   __m256d v[k_registers<T, B>]) {
  constexpr std::size_t bytes = k_record_bytes<T, B>;
  const char* q[4];
  for (int j = 0; j < 4; ++j) q[j] = table + bytes * static_cast<std::size_t>(at[j][i]);
  if constexpr (bytes == 8) {
    long long bits[4];  // one 8-byte load each (memcpy: the table is float)
    for (int j = 0; j < 4; ++j) std::memcpy(&bits[j], q[j], sizeof bits[j]);
    v[0] = _mm256_castsi256_pd(_mm256_setr_epi64x(bits[0], bits[1], bits[2], bits[3]));
  } else {
    static_assert(bytes == 16, "records of 8 or 16 bytes");
    for (std::size_t h = 0; h < 2; ++h) {
      v[h] = _mm256_loadu2_m128d(reinterpret_cast<const double*>(q[2 * h + 1]),
                                 reinterpret_cast<const double*>(q[2 * h]));
    }
  }
}

// The 64-bit lanes of each register whose record is that of a valid slot: `valid` holds slot j's
// mask in lane j.
template <typename T, int B>
HMFNET_AVX2 inline void spread_mask(__m256i valid, __m256d m[k_registers<T, B>]) {
  constexpr std::size_t bytes = k_record_bytes<T, B>;
  if constexpr (bytes == 8) {
    m[0] = _mm256_castsi256_pd(valid);
  } else {
    m[0] = _mm256_castsi256_pd(_mm256_permute4x64_epi64(valid, 0x50));  // lanes 0 0 1 1
    m[1] = _mm256_castsi256_pd(_mm256_permute4x64_epi64(valid, 0xFA));  // lanes 2 2 3 3
  }
}

// A run's entries before `split` into the partials at p: block by block, slot j of the block at
// i taking entry i + (j - place) mod 4 where that is before split, else +0.0 (the slots' loads
// read at most seven entries past the run: k_run_padding).
template <typename T, int B, typename I>
HMFNET_AVX2 void add_blocks(T* p, const char* table, const I* cols, const Run& run) {
  constexpr std::size_t regs = k_registers<T, B>;
  __m256d acc[regs];
  for (std::size_t k = 0; k < regs; ++k)
    acc[k] = _mm256_loadu_pd(reinterpret_cast<const double*>(p) + 4 * k);
  const I* at[4];
  for (int j = 0; j < 4; ++j) at[j] = cols + ((j - run.place) & 3);
  // Slot j of the block at i is valid while i < split - (j - place) mod 4. Formed in registers:
  // four scalar stores read back as one vector stalled every run on the failed store forwarding.
  const __m256i offsets = _mm256_and_si256(
      _mm256_sub_epi64(_mm256_setr_epi64x(0, 1, 2, 3), _mm256_set1_epi64x(run.place)),
      _mm256_set1_epi64x(3));
  const __m256i limits = _mm256_sub_epi64(_mm256_set1_epi64x(run.split), offsets);
  // Two blocks a trip: the trip count of a run of up to 8 entries (4 in 5 at N = 10^6,
  // degree 100, 16 segments) is one, so the loop's exit is predicted.
  EdgeOffset i = 0;
  do {
    for (int half = 0; half < 2; ++half, i += 4) {
      __m256d v[regs], m[regs];
      load_block<T, B, I>(table, at, i, v);
      spread_mask<T, B>(_mm256_cmpgt_epi64(limits, _mm256_set1_epi64x(i)), m);
      for (std::size_t k = 0; k < regs; ++k)
        acc[k] = add_bits(acc[k], _mm256_and_pd(v[k], m[k]), T{});
    }
  } while (i < run.split);
  for (std::size_t k = 0; k < regs; ++k)
    _mm256_storeu_pd(reinterpret_cast<double*>(p) + 4 * k, acc[k]);
}

template <typename T, int B, typename I>
HMFNET_AVX2 void vector_runs(const SegmentPass<T, I>& pass, NodeIndex r0, NodeIndex r1) {
  constexpr std::size_t stride = 8 * static_cast<std::size_t>(B);
  const auto* table = reinterpret_cast<const char*>(pass.table);
  RunWalk walk = pass.runs->walk(pass.segment, r0);
  for (NodeIndex r = r0; r < r1; ++r) {
    T* p = pass.carry + static_cast<std::size_t>(r - pass.origin) * stride;
    if (pass.first) std::memset(p, 0, stride * sizeof(T));
    const RunSpan span = walk.next(r);
    const Run run = run_of(pass, r, span.n);
    const I* cols = pass.cols + span.begin;
    if (run.split > 0) add_blocks<T, B, I>(p, table, cols, run);
    constexpr auto record = std::ptrdiff_t{2} * B;
    for (EdgeOffset e = run.split; e < run.n; ++e)  // the row's last d mod 4: partial 0
      add_record(p, pass.table + record * cols[e], T(1), 2 * B);
    if (!pass.last) pass.cursor[r - pass.origin] = static_cast<std::uint32_t>(run.place + run.n);
  }
}
#undef HMFNET_AVX2
#endif

template <typename T, int B, typename I>
void runs(const SegmentPass<T, I>& pass, NodeIndex r0, NodeIndex r1, bool vector) {
#if defined(HMFNET_SEGMENT_RUNS_AVX2)
  if constexpr (k_record_bytes<T, B> <= 16) {
    if (vector && segment_runs_vectorised<T>(B)) {
      vector_runs<T, B, I>(pass, r0, r1);
      return;
    }
  }
#else
  static_cast<void>(vector);
#endif
  scalar_segment_runs<T, B, false, I>(pass, nullptr, B, r0, r1);
}

}  // namespace

template <typename T>
bool segment_runs_vectorised(int replicas) {
#if defined(HMFNET_SEGMENT_RUNS_AVX2)
  // Records of 8 and 16 bytes. float64 B = 2 (32-byte records) measured 0.90x the scalar loop
  // (ER N = 10^6, degree 100, 1 thread, bench/segmented_rows_table.sh), also with the slots
  // past a run pointed at a zero record instead of masked.
  const bool small_record = replicas == 1 || (replicas == 2 && sizeof(T) == sizeof(float));
  return small_record && sincos_isa() >= SincosIsa::avx2;
#else
  static_cast<void>(replicas);
  return false;
#endif
}

template <typename T, typename I>
void add_segment_runs(const SegmentPass<T, I>& pass, int replicas, NodeIndex r0, NodeIndex r1,
                      bool vector) {
  if (replicas == 2) {
    runs<T, 2, I>(pass, r0, r1, vector);
  } else {
    runs<T, 1, I>(pass, r0, r1, vector);
  }
}

template bool segment_runs_vectorised<double>(int);
template bool segment_runs_vectorised<float>(int);
template void add_segment_runs(const SegmentPass<double, std::uint16_t>&, int, NodeIndex, NodeIndex,
                               bool);
template void add_segment_runs(const SegmentPass<double, NodeIndex>&, int, NodeIndex, NodeIndex,
                               bool);
template void add_segment_runs(const SegmentPass<float, std::uint16_t>&, int, NodeIndex, NodeIndex,
                               bool);
template void add_segment_runs(const SegmentPass<float, NodeIndex>&, int, NodeIndex, NodeIndex,
                               bool);

}  // namespace hmfnet
