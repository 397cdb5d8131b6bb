#include "dynamics/sincos.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet {

namespace {

// Four lanes in GCC/Clang vector types: the compiler maps them to two SSE2 registers on the
// x86-64 baseline (or one AVX register where enabled). Every lane does the same IEEE operations
// as every other, and the tail is computed in a padded vector, so an angle's bits never depend on
// its place in the array.
constexpr int kLanes = 4;
using VecD = double __attribute__((vector_size(kLanes * sizeof(double))));
using VecU = std::uint64_t __attribute__((vector_size(kLanes * sizeof(double))));

// Everything below is inlined into each instruction-set version (sincos_block and
// sincos_block_avx2), so that the vectors stay in registers of that set and no 32-byte vector is
// ever passed between functions compiled for different sets (what GCC's -Wpsabi note is about).
#define HMFNET_INLINE inline __attribute__((always_inline))

template <typename To, typename From>
HMFNET_INLINE To bits_as(const From& from) {
  static_assert(sizeof(To) == sizeof(From), "a reinterpretation keeps the size");
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

// The lanes of the shared sincos template (kernel_arithmetic.hpp: sincos_lanes, which a CUDA
// device and sincos_one also instantiate, on one double): the same operations, so the same bits
// by construction.
struct VectorLanes {
  using Real = VecD;
  using Bits = VecU;
  static HMFNET_INLINE Bits bits(const Real& x) { return bits_as<Bits>(x); }
  static HMFNET_INLINE Real real(const Bits& b) { return bits_as<Real>(b); }
  // A vector comparison gives -1 (all ones) or 0 per lane.
  static HMFNET_INLINE Bits at_most(const Bits& a, std::uint64_t b) {
    return bits_as<Bits>(a <= b);
  }
};

HMFNET_INLINE void store_interleaved(const VecD& c, const VecD& s, int lanes, double* cs) {
  for (int l = 0; l < lanes; ++l) {
    const auto at = 2 * static_cast<std::size_t>(l);
    cs[at] = c[l];
    cs[at + 1] = s[l];
  }
}

HMFNET_INLINE void sincos_block(const double* x, std::size_t n, double* cs) {
  VecD c;
  VecD s;
  const std::size_t body = n - n % kLanes;
  for (std::size_t k = 0; k < body; k += kLanes) {
    VecD v;
    std::memcpy(&v, x + k, sizeof v);
    sincos_lanes<VectorLanes>(v, c, s);
    store_interleaved(c, s, kLanes, cs + 2 * k);
  }
  if (body < n) {
    VecD v = {0.0, 0.0, 0.0, 0.0};
    std::memcpy(&v, x + body, (n - body) * sizeof(double));
    sincos_lanes<VectorLanes>(v, c, s);
    store_interleaved(c, s, static_cast<int>(n - body), cs + 2 * body);
  }
  // The rare angles beyond the reduced range, and non-finite ones, from the C library.
  for (std::size_t k = 0; k < n; ++k) {
    if (!(std::abs(x[k]) <= kReducedRange)) ::sincos(x[k], &cs[2 * k + 1], &cs[2 * k]);
  }
}

// The same code for AVX2 (4 lanes in one register instead of two): the same IEEE operations in
// the same order, no FMA (AVX2 does not bring it, and contraction is off), so the same bits;
// tests/dynamics/test_sincos.cpp compares the two versions. GCC and Clang on x86-64 only.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HMFNET_SINCOS_AVX2 1
__attribute__((target("avx2"))) void sincos_block_avx2(const double* x, std::size_t n, double* cs) {
  sincos_block(x, n, cs);
}
// Asked once, on first use (a namespace-scope initialiser could run before the runtime's own CPU
// detection; __builtin_cpu_init makes that order irrelevant).
bool has_avx2() {
  static const bool avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return avx2;
}
#endif

}  // namespace

void sincos_interleaved_baseline(const double* x, std::size_t n, double* cs) {
  sincos_block(x, n, cs);
}

bool sincos_uses_avx2() {
#ifdef HMFNET_SINCOS_AVX2
  return has_avx2();
#else
  return false;
#endif
}

void sincos_interleaved(const double* x, std::size_t n, double* cs) {
#ifdef HMFNET_SINCOS_AVX2
  if (has_avx2()) {
    sincos_block_avx2(x, n, cs);
    return;
  }
#endif
  sincos_block(x, n, cs);
}

void sincos_interleaved_team(const double* x, std::size_t n, double* cs) {
  // Blocks of 512 angles (8 KiB of output): long enough for the vector loop, short enough to
  // share out.
  constexpr std::size_t kBlock = 512;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < blocks; ++i) {
    const std::size_t begin = i * kBlock;
    const std::size_t count = begin + kBlock <= n ? kBlock : n - begin;
    sincos_interleaved(x + begin, count, cs + 2 * begin);
  }
}

}  // namespace hmfnet
