#pragma once
// Vector lanes for the kernels that run one template in several instruction sets (the sincos,
// sincos.cpp; the kick and drift, kick_drift_lanes.cpp; the rank-one force's fused pass,
// rank_one_fused.cpp): GCC/Clang vector types, the
// lanes type kernel_arithmetic.hpp's sincos_lanes takes, and the [cos, sin] interleaving of the
// force's tables. Internal to those translation units' instruction-set versions.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace hmfnet::simd {

// Lanes in GCC/Clang vector types: four for the x86-64 baseline (two SSE2 registers) and AVX2
// (one register), eight for AVX-512 (one register; the sincos takes two side by side,
// TwiceLanes below). Every lane does the same IEEE operations as
// every other, and the tail is computed in a padded vector, so an angle's bits never depend on
// its place in the array or on the vector width.
using VecD4 = double __attribute__((vector_size(4 * sizeof(double))));
using VecU4 = std::uint64_t __attribute__((vector_size(4 * sizeof(double))));
using VecD8 = double __attribute__((vector_size(8 * sizeof(double))));
using VecU8 = std::uint64_t __attribute__((vector_size(8 * sizeof(double))));

// Everything here is inlined into each instruction-set version of its callers (sincos.cpp's
// sincos_block_baseline, _avx2, _avx512; kick_drift_lanes.cpp's and rank_one_fused.cpp's), so that
// the vectors stay in registers of that set and no 32- or 64-byte vector is ever passed between
// functions compiled for different sets (what GCC's -Wpsabi note is about).
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
// Masks: with MaskRegisters (AVX-512), a comparison's result used in selections, which AVX-512
// holds in a mask register and selects with in one blend (five fewer vector instructions a
// vector than the bit formula: 1.59 -> 1.43 ns an angle, docs/performance.md "sincos selections
// in mask registers"); otherwise -1 or 0 per lane combined by and/or: SSE2 has no 64-bit
// comparison (the comparisons made the baseline 1.17x slower) and AVX2's blends measured no
// faster. Both select without arithmetic: the same bits.
template <typename D, typename U, bool MaskRegisters>
struct VectorLanes {
  using Real = D;
  using Bits = U;
  using Mask = std::conditional_t<MaskRegisters, decltype(U{} <= U{}), U>;
  static constexpr std::size_t k_lanes = sizeof(D) / sizeof(double);
  static HMFNET_INLINE Bits bits(const Real& x) { return bits_as<Bits>(x); }
  static HMFNET_INLINE Real real(const Bits& b) { return bits_as<Real>(b); }
  static HMFNET_INLINE Mask at_most(const Bits& a, std::uint64_t b) {
    return bits_as<Mask>(a <= b);
  }
  static HMFNET_INLINE Mask odd(const Bits& a) {
    if constexpr (MaskRegisters) {
      return (a & 1U) != 0U;
    } else {
      return 0U - (a & 1U);
    }
  }
  static HMFNET_INLINE Bits select(const Mask& m, const Bits& a, const Bits& b) {
    if constexpr (MaskRegisters) {
      return m ? a : b;
    } else {
      return (a & m) | (b & ~m);
    }
  }
};
using Lanes4 = VectorLanes<VecD4, VecU4, false>;
using Lanes8 = VectorLanes<VecD8, VecU8, true>;

// Two registers of lanes side by side: each operation of the sincos template applied to both in
// adjacent instructions, so that two independent chains of dependent operations are in flight
// in the FP scheduler at once (the sincos's chain is ~70 cycles long; docs/performance.md, "The
// AVX-512 sincos in two registers"). Every lane does the same IEEE operations as in one
// register: the same bits.
template <typename V>
struct Twice {
  V lo;
  V hi;
  HMFNET_INLINE auto operator[](std::size_t l) const {
    constexpr std::size_t half = sizeof(V) / sizeof(lo[0]);
    return l < half ? lo[l] : hi[l - half];
  }
  HMFNET_INLINE Twice& operator&=(const Twice& o) {
    lo &= o.lo;
    hi &= o.hi;
    return *this;
  }
};

template <typename V>
HMFNET_INLINE Twice<V> operator~(const Twice<V>& a) {
  return {~a.lo, ~a.hi};
}

// Both operands side by side, or one side by side with a scalar (a constant of the template).
#define HMFNET_TWICE_OPERATOR(op)                                                         \
  template <typename V>                                                                   \
  HMFNET_INLINE Twice<V> operator op(const Twice<V>& a, const Twice<V>& b) {              \
    return {a.lo op b.lo, a.hi op b.hi};                                                  \
  }                                                                                       \
  template <typename V, typename S, typename = std::enable_if_t<std::is_arithmetic_v<S>>> \
  HMFNET_INLINE Twice<V> operator op(const Twice<V>& a, S b) {                            \
    return {a.lo op b, a.hi op b};                                                        \
  }                                                                                       \
  template <typename V, typename S, typename = std::enable_if_t<std::is_arithmetic_v<S>>> \
  HMFNET_INLINE Twice<V> operator op(S a, const Twice<V>& b) {                            \
    return {a op b.lo, a op b.hi};                                                        \
  }
HMFNET_TWICE_OPERATOR(+)
HMFNET_TWICE_OPERATOR(-)
HMFNET_TWICE_OPERATOR(*)
HMFNET_TWICE_OPERATOR(&)
HMFNET_TWICE_OPERATOR(^)
HMFNET_TWICE_OPERATOR(<<)
#undef HMFNET_TWICE_OPERATOR

// The lanes of two registers of L side by side, for the sincos template.
template <typename L>
struct TwiceLanes {
  using Real = Twice<typename L::Real>;
  using Bits = Twice<typename L::Bits>;
  using Mask = Twice<typename L::Mask>;
  static constexpr std::size_t k_lanes = 2 * L::k_lanes;
  static HMFNET_INLINE Bits bits(const Real& x) { return {L::bits(x.lo), L::bits(x.hi)}; }
  static HMFNET_INLINE Real real(const Bits& b) { return {L::real(b.lo), L::real(b.hi)}; }
  static HMFNET_INLINE Mask at_most(const Bits& a, std::uint64_t b) {
    return {L::at_most(a.lo, b), L::at_most(a.hi, b)};
  }
  static HMFNET_INLINE Mask odd(const Bits& a) { return {L::odd(a.lo), L::odd(a.hi)}; }
  static HMFNET_INLINE Bits select(const Mask& m, const Bits& a, const Bits& b) {
    return {L::select(m.lo, a.lo, b.lo), L::select(m.hi, a.hi, b.hi)};
  }
};
using Lanes8Twice = TwiceLanes<Lanes8>;
// Two registers with nothing between them: memcpy of consecutive doubles in and out is exact.
static_assert(sizeof(Twice<VecD8>) == 2 * sizeof(VecD8), "no padding between the registers");

// [c0, s0, c1, s1, ...] as two vectors of the lanes' width: register shuffles (unpack and
// permute) instead of one scalar store per value, which cost ~1 ns an angle in the AVX2 version.
HMFNET_INLINE void store_interleaved(const VecD4& c, const VecD4& s, double* cs) {
  const VecD4 lo = __builtin_shufflevector(c, s, 0, 4, 1, 5);
  const VecD4 hi = __builtin_shufflevector(c, s, 2, 6, 3, 7);
  std::memcpy(cs, &lo, sizeof lo);
  std::memcpy(cs + 4, &hi, sizeof hi);
}

HMFNET_INLINE void store_interleaved(const VecD8& c, const VecD8& s, double* cs) {
  const VecD8 lo = __builtin_shufflevector(c, s, 0, 8, 1, 9, 2, 10, 3, 11);
  const VecD8 hi = __builtin_shufflevector(c, s, 4, 12, 5, 13, 6, 14, 7, 15);
  std::memcpy(cs, &lo, sizeof lo);
  std::memcpy(cs + 8, &hi, sizeof hi);
}

template <typename V>
HMFNET_INLINE void store_interleaved(const Twice<V>& c, const Twice<V>& s, double* cs) {
  store_interleaved(c.lo, s.lo, cs);
  store_interleaved(c.hi, s.hi, cs + 2 * sizeof(V) / sizeof(double));
}

// A vector from / to consecutive doubles (any alignment).
template <typename V>
HMFNET_INLINE V load(const double* x) {
  V v;
  std::memcpy(&v, x, sizeof v);
  return v;
}

template <typename V>
HMFNET_INLINE void store(double* x, const V& v) {
  std::memcpy(x, &v, sizeof v);
}

// (c, s) from [c0, s0, c1, s1, ...]: store_interleaved's inverse.
HMFNET_INLINE void load_interleaved(const double* cs, VecD4& c, VecD4& s) {
  VecD4 lo;
  VecD4 hi;
  std::memcpy(&lo, cs, sizeof lo);
  std::memcpy(&hi, cs + 4, sizeof hi);
  c = __builtin_shufflevector(lo, hi, 0, 2, 4, 6);
  s = __builtin_shufflevector(lo, hi, 1, 3, 5, 7);
}

HMFNET_INLINE void load_interleaved(const double* cs, VecD8& c, VecD8& s) {
  VecD8 lo;
  VecD8 hi;
  std::memcpy(&lo, cs, sizeof lo);
  std::memcpy(&hi, cs + 8, sizeof hi);
  c = __builtin_shufflevector(lo, hi, 0, 2, 4, 6, 8, 10, 12, 14);
  s = __builtin_shufflevector(lo, hi, 1, 3, 5, 7, 9, 11, 13, 15);
}

}  // namespace hmfnet::simd
