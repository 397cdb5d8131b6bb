#include "dynamics/kick_drift_lanes.hpp"

#include <cstring>

#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet {

namespace {

// Four lanes: two SSE2 registers on the x86-64 baseline, one AVX2 register.
using VecD4 = double __attribute__((vector_size(4 * sizeof(double))));

// Inlined into each instruction-set version below, so that no vector crosses a function compiled
// for another set.
#define HMFNET_INLINE inline __attribute__((always_inline))

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

// `n` consecutive cells with the coupling factors ck (a lane's c_kick K_b): the vector body in V,
// the rest one cell at a time, each cell kicked_momentum then drifted_angle.
template <typename V, bool Drift>
HMFNET_INLINE void cells_with(double* p, double* theta, const double* g, const V& ck, double ck_one,
                              double c_drift, std::size_t n) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(double);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    const V pk = load<V>(p + k) + ck * load<V>(g + k);
    store(p + k, pk);
    if constexpr (Drift) store(theta + k, load<V>(theta + k) + c_drift * pk);
  }
  for (; k < n; ++k) {
    p[k] = p[k] + ck_one * g[k];
    if constexpr (Drift) theta[k] = drifted_angle(theta[k], c_drift, p[k]);
  }
}

// Rows [r0, r1). One replica: the rows as one flat run of cells with one factor. Several: per
// row, the replicas in groups of the vector's width, each group's factors c_kick K_b formed as
// kicked_momentum forms them (c K rounded first), and the last replicas (w mod the width) one
// at a time.
template <typename V, bool Drift>
HMFNET_INLINE void rows_with(const KickDriftCells& cells, double c_kick, double c_drift,
                             std::size_t r0, std::size_t r1) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(double);
  const std::size_t w = cells.replicas;
  if (w == 1) {
    const double ck = c_kick * cells.K[0];
    const V ckv = V{} + ck;
    cells_with<V, Drift>(cells.p + r0, Drift ? cells.theta + r0 : nullptr, cells.g + r0, ckv, ck,
                         c_drift, r1 - r0);
    return;
  }
  for (std::size_t r = r0; r < r1; ++r) {
    const std::size_t row = r * w;
    std::size_t b = 0;
    for (; b + lanes <= w; b += lanes) {
      const V ck = c_kick * load<V>(cells.K + b);
      cells_with<V, Drift>(cells.p + row + b, Drift ? cells.theta + row + b : nullptr,
                           cells.g + row + b, ck, 0.0, c_drift, lanes);
    }
    for (; b < w; ++b) {
      const std::size_t k = row + b;
      cells.p[k] = kicked_momentum(cells.p[k], c_kick, cells.K[b], cells.g[k]);
      if constexpr (Drift) cells.theta[k] = drifted_angle(cells.theta[k], c_drift, cells.p[k]);
    }
  }
}

template <typename V>
HMFNET_INLINE void rows_in(const KickDriftCells& cells, double c_kick, double c_drift,
                           std::size_t r0, std::size_t r1) {
  if (cells.theta != nullptr) {
    rows_with<V, true>(cells, c_kick, c_drift, r0, r1);
  } else {
    rows_with<V, false>(cells, c_kick, c_drift, r0, r1);
  }
}

void rows_baseline(const KickDriftCells& cells, double c_kick, double c_drift, std::size_t r0,
                   std::size_t r1) {
  rows_in<VecD4>(cells, c_kick, c_drift, r0, r1);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HMFNET_KICK_X86 1
__attribute__((target("avx2"))) void rows_avx2(const KickDriftCells& cells, double c_kick,
                                               double c_drift, std::size_t r0, std::size_t r1) {
  rows_in<VecD4>(cells, c_kick, c_drift, r0, r1);
}
#endif

// AVX2's four lanes also where the sincos runs in AVX-512: eight lanes in AVX-512 measured 4%
// slower at ER N = 10^6 (one replica, where the pass streams from memory in 64-byte accesses that
// straddle cache lines: std::vector aligns to 16 bytes) and 4-6% faster on K_N N = 2000 (bench
// RankOneStep, Intel Xeon, docs/performance.md): not worth a third version.
void run(SincosIsa isa, const KickDriftCells& cells, double c_kick, double c_drift, std::size_t r0,
         std::size_t r1) {
#ifdef HMFNET_KICK_X86
  if (isa == SincosIsa::avx512 || isa == SincosIsa::avx2) {
    rows_avx2(cells, c_kick, c_drift, r0, r1);
    return;
  }
#endif
  (void)isa;
  rows_baseline(cells, c_kick, c_drift, r0, r1);
}

}  // namespace

void kick_drift_rows(const KickDriftCells& cells, double c_kick, double c_drift, std::size_t r0,
                     std::size_t r1) {
  run(sincos_isa(), cells, c_kick, c_drift, r0, r1);
}

void kick_drift_rows_isa(SincosIsa isa, const KickDriftCells& cells, double c_kick, double c_drift,
                         std::size_t r0, std::size_t r1) {
  run(sincos_isa_up_to(isa), cells, c_kick, c_drift, r0, r1);
}

}  // namespace hmfnet
