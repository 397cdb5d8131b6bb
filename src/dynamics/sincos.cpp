#include "dynamics/sincos.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

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

// pi/2 = kPio2[0] + kPio2[1] + kPio2[2] + kPio2[3] to ~2^-135; the first three have 26
// significant bits, so q kPio2[i] is exact for |q| < 2^27 (computed with mpmath at 300 bits).
constexpr double kPio2[4] = {0x1.921fb50000000p+0, 0x1.110b460000000p-26, 0x1.1a62630000000p-54,
                             0x1.8a2e03707344ap-81};
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// Adding and subtracting 1.5 2^52 rounds a double below 2^51 to the nearest integer (ties to
// even), and the sum's low mantissa bits then hold that integer in two's complement.
constexpr double kRoundShift = 0x1.8p52;
constexpr std::uint64_t kAbsMask = 0x7fffffffffffffffULL;
constexpr std::uint64_t kSignBit = 0x8000000000000000ULL;

// Minimax polynomials on [-pi/4, pi/4] (Cephes' sin.c coefficients):
// sin r = r + r^3 S(r^2), cos r = 1 - r^2 / 2 + r^4 C(r^2).
constexpr double kSin[6] = {1.58962301576546568060e-10, -2.50507477628578072866e-8,
                            2.75573136213857245213e-6,  -1.98412698295895385996e-4,
                            8.33333333332211858878e-3,  -1.66666666666666307295e-1};
constexpr double kCos[6] = {-1.13585365213876817300e-11, 2.08757008419747316778e-9,
                            -2.75573141792967388112e-7,  2.48015872888517045348e-5,
                            -1.38888888888730564116e-3,  4.16666666666665929218e-2};

// The lanes' cos and sin. A lane whose |x| exceeds kReducedRange (or is not finite) computes
// sin 0 instead; the caller overwrites it with the C library's value.
HMFNET_INLINE void sincos_lanes(const VecD& angle, VecD& c, VecD& s) {
  const auto range_bits = bits_as<std::uint64_t>(kReducedRange);
  // Integer comparison of |x|'s bits (a NaN's are above infinity's): a floating-point one may
  // trap and then stays a branch.
  const auto inside = bits_as<VecU>((bits_as<VecU>(angle) & kAbsMask) <= range_bits);
  const auto x = bits_as<VecD>(bits_as<VecU>(angle) & inside);
  const VecD t = x * kTwoOverPi + kRoundShift;
  const VecD q = t - kRoundShift;
  const VecU j = bits_as<VecU>(t);  // q mod 4 = j & 3
  // r + r_lo = x - q pi/2 to ~2^-105 |x|: x - q kPio2[0] and the next subtraction are exact;
  // b = q kPio2[2] + q kPio2[3] with its rounding error eb (Fast2Sum, |p2| >= |p3|); r = a - b
  // rounded once, and r_lo the rounding of r (Fast2Sum: exact because a is a multiple of a unit
  // at least ulp(b), also where |a| < |b|) less eb. Without r_lo the rounding of r costs 1 ulp
  // where |sin| or |cos| is just below 1/2 and |r| just above (measured 1.5 ulp); without eb,
  // angles within ~10^-10 of a multiple of pi/2 (|r| tiny) lose up to thousands of ulp.
  const VecD a = (x - q * kPio2[0]) - q * kPio2[1];
  const VecD p2 = q * kPio2[2];
  const VecD p3 = q * kPio2[3];
  const VecD b = p2 + p3;
  const VecD eb = p3 - (b - p2);
  const VecD r = a - b;
  const VecD r_lo = ((a - r) - b) - eb;
  const VecD z = r * r;
  const VecD ps =
      ((((kSin[0] * z + kSin[1]) * z + kSin[2]) * z + kSin[3]) * z + kSin[4]) * z + kSin[5];
  const VecD pc =
      ((((kCos[0] * z + kCos[1]) * z + kCos[2]) * z + kCos[3]) * z + kCos[4]) * z + kCos[5];
  // sin(r + r_lo) = sin r + r_lo cos r, cos(r + r_lo) = cos r - r_lo sin r, to first order in
  // r_lo (|r_lo| <= 2^-54 |r|); cos r = w + ((1 - w) - z / 2 + z^2 C) with w = 1 - z / 2: the
  // parenthesis recovers the rounding of w (fdlibm's kernel_cos).
  const VecD half_z = 0.5 * z;
  const VecD sin_r = r + (r * z * ps + r_lo * (1.0 - half_z));
  const VecD w = 1.0 - half_z;
  const VecD cos_r = w + (((1.0 - w) - half_z) + (z * z * pc - r * r_lo));
  // Quadrant j: (cos, sin)(x) = (cos r, sin r), (-sin r, cos r), (-cos r, -sin r), (sin r,
  // -cos r) for j = 0, 1, 2, 3: swap when j is odd, then flip the sign bits.
  const VecU swap = 0 - (j & 1U);
  const VecU sin_bits = (bits_as<VecU>(sin_r) & ~swap) | (bits_as<VecU>(cos_r) & swap);
  const VecU cos_bits = (bits_as<VecU>(cos_r) & ~swap) | (bits_as<VecU>(sin_r) & swap);
  s = bits_as<VecD>(sin_bits ^ ((j << 62) & kSignBit));
  c = bits_as<VecD>(cos_bits ^ (((j + 1U) << 62) & kSignBit));
}

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
    sincos_lanes(v, c, s);
    store_interleaved(c, s, kLanes, cs + 2 * k);
  }
  if (body < n) {
    VecD v = {0.0, 0.0, 0.0, 0.0};
    std::memcpy(&v, x + body, (n - body) * sizeof(double));
    sincos_lanes(v, c, s);
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
