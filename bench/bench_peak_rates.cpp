// The ceilings of the step's bound (bench/ensemble_table.sh, docs/performance.md "A bound that
// bounds"): rates no code on this core can beat for the work every step must do, measured at
// their best case, so that a step's time is at least the sum of its phases' least times:
//  - L1LoadAdd/width_bytes/threads: loads of `width` bytes from an L1-resident array (8 KiB a
//    thread), each added into one of 8 independent accumulators: the most (load, add) pairs a
//    second the core issues. Every gathered record of the sparse rows needs at least
//    ceil(record bytes / width) of them, whatever the code (a record of 16 B in one 16-byte
//    load and add; 128 B in two 64-byte ones). Widths 16, 32 and 64 (AVX2 and AVX-512 where
//    this CPU has them; 0 pairs/s otherwise).
//  - StreamRead/KiB/threads: a sequential sum over an int32 array of that size, in AVX-512 or
//    AVX2 where this CPU has them, each thread its contiguous share: the best rate at which the
//    column indices (4 B a stored entry, read once a step in order) can come from the cache level
//    or memory that holds an array of their size.
//  - StreamUpdate/KiB/threads: every double of an array of that size read, added to and written
//    back in place, each thread its contiguous share: the best rate at which a pass that must
//    read and rewrite every cell once (the complete graph's fused pass: theta, p and [cos, sin]
//    of every rotor and replica, 32 B a cell) moves its bytes, counted read and written.
// Rates: pairs_per_s and bytes_per_s counters. Each is measured in 3 repetitions and the table
// takes the best (a ceiling is the highest rate seen, never a mean): in one table of
// docs/performance.md the 256 KiB read measured 98.7 GB/s after its warm-up where the table
// before measured 175.8, on the same idle Intel Xeon.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace {

constexpr std::size_t k_l1_doubles = 1024;  // 8 KiB: in L1 on every x86-64 core
constexpr int k_passes = 4096;              // passes over it a measurement

// The sum of `passes` passes over x (k_l1_doubles) with 8 accumulators of W-byte vectors.
#if defined(__x86_64__)
__attribute__((target("avx512f"))) double load_add_64(const double* x, int passes) {
  __m512d a[8];
  for (auto& v : a) v = _mm512_setzero_pd();
  for (int p = 0; p < passes; ++p) {
    for (std::size_t k = 0; k < k_l1_doubles; k += 64) {
      for (std::size_t j = 0; j < 8; ++j) a[j] = _mm512_add_pd(a[j], _mm512_load_pd(x + k + 8 * j));
    }
  }
  double out[8];
  __m512d s = a[0];
  for (int j = 1; j < 8; ++j) s = _mm512_add_pd(s, a[j]);
  _mm512_storeu_pd(out, s);
  return out[0] + out[7];
}

__attribute__((target("avx2"))) double load_add_32(const double* x, int passes) {
  __m256d a[8];
  for (auto& v : a) v = _mm256_setzero_pd();
  for (int p = 0; p < passes; ++p) {
    for (std::size_t k = 0; k < k_l1_doubles; k += 32) {
      for (std::size_t j = 0; j < 8; ++j) a[j] = _mm256_add_pd(a[j], _mm256_load_pd(x + k + 4 * j));
    }
  }
  double out[4];
  __m256d s = a[0];
  for (int j = 1; j < 8; ++j) s = _mm256_add_pd(s, a[j]);
  _mm256_storeu_pd(out, s);
  return out[0] + out[3];
}

double load_add_16(const double* x, int passes) {
  __m128d a[8];
  for (auto& v : a) v = _mm_setzero_pd();
  for (int p = 0; p < passes; ++p) {
    for (std::size_t k = 0; k < k_l1_doubles; k += 16) {
      for (std::size_t j = 0; j < 8; ++j) a[j] = _mm_add_pd(a[j], _mm_load_pd(x + k + 2 * j));
    }
  }
  double out[2];
  __m128d s = a[0];
  for (int j = 1; j < 8; ++j) s = _mm_add_pd(s, a[j]);
  _mm_storeu_pd(out, s);
  return out[0] + out[1];
}

bool runs_width(int width) {
  __builtin_cpu_init();
  if (width == 64) return __builtin_cpu_supports("avx512f") != 0;
  if (width == 32) return __builtin_cpu_supports("avx2") != 0;
  return width == 16;
}
#endif

void L1LoadAdd(benchmark::State& state) {
  const auto width = static_cast<int>(state.range(0));
  const auto threads = static_cast<int>(state.range(1));
#if defined(__x86_64__)
  if (!runs_width(width)) {
    state.SkipWithError("this CPU has no loads of that width");
    return;
  }
  omp_set_num_threads(threads);
  for (auto _ : state) {
    double total = 0.0;
#pragma omp parallel reduction(+ : total)
    {
      alignas(64) double x[k_l1_doubles];
      for (std::size_t k = 0; k < k_l1_doubles; ++k) x[k] = 1e-3 * static_cast<double>(k);
      total += width == 64   ? load_add_64(x, k_passes)
               : width == 32 ? load_add_32(x, k_passes)
                             : load_add_16(x, k_passes);
    }
    benchmark::DoNotOptimize(total);
  }
  const double pairs = static_cast<double>(k_passes) * static_cast<double>(threads) *
                       static_cast<double>(k_l1_doubles * sizeof(double)) / width;
  state.counters["pairs_per_s"] =
      benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate);
#else
  static_cast<void>(width);
  static_cast<void>(threads);
  state.SkipWithError("x86-64 only");
#endif
}

// The sum of count int32 values at x (count a multiple of 64) in the widest vectors this CPU has
// (wrapping: only the reads matter), four independent accumulators.
#if defined(__x86_64__)
__attribute__((target("avx512f"))) std::int32_t stream_64(const std::int32_t* x,
                                                          std::size_t count) {
  __m512i a[4];
  for (auto& v : a) v = _mm512_setzero_si512();
  for (std::size_t k = 0; k < count; k += 64) {
    for (std::size_t j = 0; j < 4; ++j) {
      a[j] = _mm512_add_epi32(a[j], _mm512_loadu_si512(static_cast<const void*>(x + k + 16 * j)));
    }
  }
  alignas(64) std::int32_t lanes[16];
  _mm512_store_si512(static_cast<void*>(lanes),
                     _mm512_add_epi32(_mm512_add_epi32(a[0], a[1]), _mm512_add_epi32(a[2], a[3])));
  std::uint32_t total = 0;
  for (const std::int32_t v : lanes) total += static_cast<std::uint32_t>(v);
  return static_cast<std::int32_t>(total);
}

__attribute__((target("avx2"))) std::int32_t stream_32(const std::int32_t* x, std::size_t count) {
  __m256i a[4];
  for (auto& v : a) v = _mm256_setzero_si256();
  for (std::size_t k = 0; k < count; k += 32) {
    for (std::size_t j = 0; j < 4; ++j) {
      a[j] = _mm256_add_epi32(a[j],
                              _mm256_loadu_si256(reinterpret_cast<const __m256i*>(x + k + 8 * j)));
    }
  }
  alignas(32) std::int32_t lanes[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes),
                     _mm256_add_epi32(_mm256_add_epi32(a[0], a[1]), _mm256_add_epi32(a[2], a[3])));
  std::uint32_t total = 0;
  for (const std::int32_t v : lanes) total += static_cast<std::uint32_t>(v);
  return static_cast<std::int32_t>(total);
}
#endif

std::int32_t stream_scalar(const std::int32_t* x, std::size_t count) {
  std::uint32_t total = 0;
  for (std::size_t k = 0; k < count; ++k) total += static_cast<std::uint32_t>(x[k]);
  return static_cast<std::int32_t>(total);
}

// The sum of x[0, count) in the widest vectors this CPU has.
std::int32_t stream(const std::int32_t* x, std::size_t count) {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx512f") != 0) return stream_64(x, count);
  if (__builtin_cpu_supports("avx2") != 0) return stream_32(x, count);
#endif
  return stream_scalar(x, count);
}

void StreamRead(benchmark::State& state) {
  const auto bytes = static_cast<std::size_t>(state.range(0)) * 1024;
  const auto threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const std::size_t count = bytes / sizeof(std::int32_t) / 64 * 64;
  std::vector<std::int32_t> index(count);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < count; ++k) index[k] = static_cast<std::int32_t>(k & 1023U);
#if defined(__x86_64__)
  __builtin_cpu_init();
#endif
  // Small arrays are read again inside the region, so that its start and end do not count.
  const std::size_t passes = std::max<std::size_t>(1, (std::size_t{64} << 20) / bytes);
  for (auto _ : state) {
    std::int32_t total = 0;
#pragma omp parallel reduction(+ : total)
    {
      // Each thread its contiguous share, in whole 64-value groups.
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
      const auto n = static_cast<std::size_t>(omp_get_num_threads());
      const std::size_t groups = count / 64;
      const std::size_t first = groups * t / n * 64, last = groups * (t + 1) / n * 64;
      for (std::size_t pass = 0; pass < passes; ++pass) {
        total += stream(index.data() + first, last - first);
        benchmark::DoNotOptimize(total);  // every pass read, none hoisted as a pure call
      }
    }
    benchmark::DoNotOptimize(total);
  }
  state.counters["bytes_per_s"] =
      benchmark::Counter(static_cast<double>(passes * count * sizeof(std::int32_t)),
                         benchmark::Counter::kIsIterationInvariantRate);
}

// x[0, count) += 1 in place in the widest vectors this CPU has (count a multiple of 32), four
// vectors in flight; no chain between them, so only the stream limits it.
#if defined(__x86_64__)
__attribute__((target("avx512f"))) void update_64(double* x, std::size_t count) {
  const __m512d one = _mm512_set1_pd(1.0);
  for (std::size_t k = 0; k < count; k += 32) {
    for (std::size_t j = 0; j < 4; ++j) {
      double* const at = x + k + 8 * j;
      _mm512_storeu_pd(at, _mm512_add_pd(_mm512_loadu_pd(at), one));
    }
  }
}

__attribute__((target("avx2"))) void update_32(double* x, std::size_t count) {
  const __m256d one = _mm256_set1_pd(1.0);
  for (std::size_t k = 0; k < count; k += 16) {
    for (std::size_t j = 0; j < 4; ++j) {
      double* const at = x + k + 4 * j;
      _mm256_storeu_pd(at, _mm256_add_pd(_mm256_loadu_pd(at), one));
    }
  }
}
#endif

void update(double* x, std::size_t count) {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx512f") != 0) return update_64(x, count);
  if (__builtin_cpu_supports("avx2") != 0) return update_32(x, count);
#endif
  for (std::size_t k = 0; k < count; ++k) x[k] += 1.0;
}

void StreamUpdate(benchmark::State& state) {
  const auto bytes = static_cast<std::size_t>(state.range(0)) * 1024;
  const auto threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const std::size_t count = bytes / sizeof(double) / 32 * 32;
  std::vector<double> cells(count);
  // First touched by the thread that updates it (its own pages, as the force's cells are).
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < count; ++k) cells[k] = static_cast<double>(k & 1023U);
#if defined(__x86_64__)
  __builtin_cpu_init();
#endif
  for (auto _ : state) {
#pragma omp parallel
    {
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
      const auto n = static_cast<std::size_t>(omp_get_num_threads());
      const std::size_t groups = count / 32;
      const std::size_t first = groups * t / n * 32, last = groups * (t + 1) / n * 32;
      update(cells.data() + first, last - first);
    }
    benchmark::DoNotOptimize(cells.data());
    benchmark::ClobberMemory();
  }
  state.counters["bytes_per_s"] =
      benchmark::Counter(static_cast<double>(2 * count * sizeof(double)),
                         benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

constexpr int k_repetitions = 3;

BENCHMARK(L1LoadAdd)
    ->ArgsProduct({{16, 32, 64}, {1, 2}})
    ->MinWarmUpTime(0.3)
    ->Repetitions(k_repetitions)
    ->UseRealTime();
// Index arrays of the table's networks (ER, degree 100): N = 10^4, 4 MB; N = 10^6, 400 MB. And
// the line ceilings: 256 KiB, beyond every L1d and within every L2 measured so far (48 and 32
// KiB; 2 MiB and 512 KiB), the best rate of lines into L1; 16 MiB, beyond those L2s, into L2.
// Warmed up first: from an idle core the 256 KiB read ran at half its rate for ~0.1 s (95 against
// 169-176 GB/s, Intel Xeon), and a ceiling measured low would let code run above it.
BENCHMARK(StreamRead)
    ->ArgsProduct({{256, 3906, 16384, 390625}, {1, 2}})
    ->MinWarmUpTime(0.3)
    ->Repetitions(k_repetitions)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// The complete graph's cells in the rank-one table (bench/rank_one_table.sh): K_N N = 10^5 with 16
// replicas, 32 B a cell: 50,000 KiB, beyond the L3 a thread of the guests measured so far holds.
BENCHMARK(StreamUpdate)
    ->ArgsProduct({{50000, 390625}, {1, 2}})
    ->MinWarmUpTime(0.3)
    ->Repetitions(k_repetitions)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
