#pragma once
// Registers of V bytes of T for the replica lanes of the sparse kernel's wide loops
// (wide_rows.cpp): 32 (AVX2's ymm) or 64 (AVX-512's zmm), as GCC vector types. Everything here is
// always inlined into a function compiled for the set (a `target` attribute), so no vector
// crosses a function compiled for another one; vectors pass by reference, never by value.
#include <cstddef>
#include <cstring>

namespace hmfnet {

template <typename T, std::size_t V>
using Lanes [[gnu::vector_size(V)]] = T;

#define HMFNET_LANES_INLINE inline __attribute__((always_inline))

/// The lanes at p (any alignment).
template <typename T, std::size_t V>
HMFNET_LANES_INLINE void load_lanes(Lanes<T, V>& v, const T* p) {
  static_assert(sizeof(Lanes<T, V>) == V, "the compiler made V bytes of T one vector");
  std::memcpy(&v, p, V);
}

/// One gathered record of R values of T added to the accumulators in acc[0, R / (V / sizeof(T))),
/// register by register: acc += w q on a weighted network, acc += q on a 0/1 one. Each lane does
/// what add_record (segment_runs.hpp) does to its value: the product (never contracted: the
/// wide loops' translation unit has -ffp-contract=off), then the sum.
template <typename T, std::size_t V, std::size_t R, bool Weighted>
HMFNET_LANES_INLINE void add_lanes(Lanes<T, V>* acc, const T* q, T w) {
  constexpr std::size_t per_register = V / sizeof(T);
  static_assert(R % per_register == 0, "a record fills whole registers");
#pragma GCC unroll 4
  for (std::size_t v = 0; v < R / per_register; ++v) {
    Lanes<T, V> x;
    load_lanes<T, V>(x, q + v * per_register);
    if constexpr (Weighted) x = w * x;
    acc[v] += x;
  }
}

/// The same into a record of accumulators in memory (a row's carried partial sums), register by
/// register: an array of the record's registers copied in and out left GCC 12 storing a dead copy
/// on the stack, two stores an entry more for 128-byte records (bench SegmentedStep/10000/100/8/
/// 0/256, float64: 1.10x without it, median of 6 alternated rounds, Intel Xeon family 6 model 106).
template <typename T, std::size_t V, std::size_t R, bool Weighted>
HMFNET_LANES_INLINE void add_lanes_at(T* acc, const T* q, T w) {
  constexpr std::size_t per_register = V / sizeof(T);
#pragma GCC unroll 4
  for (std::size_t v = 0; v < R / per_register; ++v) {
    Lanes<T, V> a;
    load_lanes<T, V>(a, acc + v * per_register);
    add_lanes<T, V, per_register, Weighted>(&a, q + v * per_register, w);
    std::memcpy(acc + v * per_register, &a, V);
  }
}

}  // namespace hmfnet
