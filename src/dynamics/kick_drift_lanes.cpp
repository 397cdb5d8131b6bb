#include "dynamics/kick_drift_lanes.hpp"

#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/vector_lanes.hpp"

namespace hmfnet {

namespace {

// Four lanes: two SSE2 registers on the x86-64 baseline, one AVX2 register; everything inlined
// into each instruction-set version below (vector_lanes.hpp).
using simd::load;
using simd::store;
using simd::VecD4;

// x in every lane, by copies (V{} + x would turn -0.0 into +0.0).
template <typename V>
HMFNET_INLINE V broadcast(double x) {
  V v;
  for (std::size_t l = 0; l < sizeof(V) / sizeof(double); ++l) v[l] = x;
  return v;
}

// `n` consecutive cells with the coupling factors ck[i] (a lane's c_i K_b for each of the
// Kicks kicks) in V and ck_one[i] for one cell: the vector body in V, the rest one cell at a time,
// each cell's kicks then its drift.
template <typename V, std::size_t Kicks, bool Drift>
HMFNET_INLINE void cells_with(double* p, double* theta, const double* g, const V* ck,
                              const double* ck_one, double c_drift, std::size_t n) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(double);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    const V gk = load<V>(g + k);
    V pk = load<V>(p + k);
    for (std::size_t i = 0; i < Kicks; ++i) pk = pk + ck[i] * gk;
    store(p + k, pk);
    if constexpr (Drift) store(theta + k, load<V>(theta + k) + c_drift * pk);
  }
  for (; k < n; ++k) {
    for (std::size_t i = 0; i < Kicks; ++i) p[k] = p[k] + ck_one[i] * g[k];
    if constexpr (Drift) theta[k] = drifted_angle(theta[k], c_drift, p[k]);
  }
}

// Rows [r0, r1). One replica: the rows as one flat run of cells with one factor a kick. Several:
// per row, the replicas in groups of the vector's width, each group's factors c K_b formed as
// kicked_momentum forms them (c K rounded first), and the last replicas (w mod the width) one
// at a time.
template <typename V, std::size_t Kicks, bool Drift>
HMFNET_INLINE void rows_with(const KickDriftCells& cells, const KickDriftCoefficients& c,
                             std::size_t r0, std::size_t r1) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(double);
  const std::size_t w = cells.replicas;
  double* theta = Drift ? cells.theta : nullptr;
  if (w == 1) {
    double ck_one[Kicks];
    V ck[Kicks];
    for (std::size_t i = 0; i < Kicks; ++i) {
      ck_one[i] = c.kicks[i] * cells.K[0];
      ck[i] = broadcast<V>(ck_one[i]);
    }
    cells_with<V, Kicks, Drift>(cells.p + r0, Drift ? theta + r0 : nullptr, cells.g + r0, ck,
                                ck_one, c.drift, r1 - r0);
    return;
  }
  for (std::size_t r = r0; r < r1; ++r) {
    const std::size_t row = r * w;
    std::size_t b = 0;
    for (; b + lanes <= w; b += lanes) {
      V ck[Kicks];
      for (std::size_t i = 0; i < Kicks; ++i) ck[i] = c.kicks[i] * load<V>(cells.K + b);
      cells_with<V, Kicks, Drift>(cells.p + row + b, Drift ? theta + row + b : nullptr,
                                  cells.g + row + b, ck, nullptr, c.drift, lanes);
    }
    for (; b < w; ++b) {
      const std::size_t k = row + b;
      for (std::size_t i = 0; i < Kicks; ++i)
        cells.p[k] = kicked_momentum(cells.p[k], c.kicks[i], cells.K[b], cells.g[k]);
      if constexpr (Drift) cells.theta[k] = drifted_angle(cells.theta[k], c.drift, cells.p[k]);
    }
  }
}

template <typename V>
HMFNET_INLINE void rows_in(const KickDriftCells& cells, const KickDriftCoefficients& c,
                           std::size_t r0, std::size_t r1) {
  const bool drift = cells.theta != nullptr;
  if (c.kick_count == 2) {
    if (drift) {
      rows_with<V, 2, true>(cells, c, r0, r1);
    } else {
      rows_with<V, 2, false>(cells, c, r0, r1);
    }
  } else if (drift) {
    rows_with<V, 1, true>(cells, c, r0, r1);
  } else {
    rows_with<V, 1, false>(cells, c, r0, r1);
  }
}

void rows_baseline(const KickDriftCells& cells, const KickDriftCoefficients& c, std::size_t r0,
                   std::size_t r1) {
  rows_in<VecD4>(cells, c, r0, r1);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HMFNET_KICK_X86 1
__attribute__((target("avx2"))) void rows_avx2(const KickDriftCells& cells,
                                               const KickDriftCoefficients& c, std::size_t r0,
                                               std::size_t r1) {
  rows_in<VecD4>(cells, c, r0, r1);
}
#endif

// AVX2's four lanes also where the sincos runs in AVX-512: eight lanes in AVX-512 measured 4%
// slower at ER N = 10^6 (one replica, where the pass streams from memory in 64-byte accesses that
// straddle cache lines: std::vector aligns to 16 bytes) and 4-6% faster on K_N N = 2000 (bench
// RankOneStep, Intel Xeon, docs/performance.md): not worth a third version.
void run(SincosIsa isa, const KickDriftCells& cells, const KickDriftCoefficients& c, std::size_t r0,
         std::size_t r1) {
#ifdef HMFNET_KICK_X86
  if (isa == SincosIsa::avx512 || isa == SincosIsa::avx2) {
    rows_avx2(cells, c, r0, r1);
    return;
  }
#endif
  (void)isa;
  rows_baseline(cells, c, r0, r1);
}

}  // namespace

void kick_drift_rows(const KickDriftCells& cells, const KickDriftCoefficients& c, std::size_t r0,
                     std::size_t r1) {
  run(sincos_isa(), cells, c, r0, r1);
}

void kick_drift_rows_isa(SincosIsa isa, const KickDriftCells& cells, const KickDriftCoefficients& c,
                         std::size_t r0, std::size_t r1) {
  run(sincos_isa_up_to(isa), cells, c, r0, r1);
}

}  // namespace hmfnet
