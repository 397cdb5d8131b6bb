#include "dynamics/rank_one_fused.hpp"

#include <cmath>
#include <cstring>

#include "dynamics/vector_lanes.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define HMFNET_FUSED_X86 1
#endif

namespace hmfnet {

namespace {

using simd::Lanes4;
using simd::Lanes8;

using simd::load;
using simd::store;

// The square root of every lane, correctly rounded as sqrtsd rounds it (IEEE 754): the bits of
// the field pass's std::sqrt and vsqrtpd (rank_one_force.cpp: field_one, field_block_avx512).
#ifdef HMFNET_FUSED_X86
HMFNET_INLINE simd::VecD4 sqrt_lanes(const simd::VecD4& x) {
  __m128d lo, hi;
  std::memcpy(&lo, &x, sizeof lo);
  std::memcpy(&hi, reinterpret_cast<const double*>(&x) + 2, sizeof hi);
  lo = _mm_sqrt_pd(lo);
  hi = _mm_sqrt_pd(hi);
  simd::VecD4 r;
  std::memcpy(&r, &lo, sizeof lo);
  std::memcpy(reinterpret_cast<double*>(&r) + 2, &hi, sizeof hi);
  return r;
}
// vsqrtpd written out: kick_drift_stage, a template of no instruction set, cannot call a
// function of AVX-512's (GCC refuses to inline across the mismatch), and the vector types have
// no square root of their own. Only fused_avx512 inlines this, so the register is a zmm there.
HMFNET_INLINE simd::VecD8 sqrt_lanes(simd::VecD8 x) {
  asm("vsqrtpd %0, %0" : "+v"(x));
  return x;
}
#else
template <typename Real>
HMFNET_INLINE Real sqrt_lanes(const Real& x) {
  Real r;
  for (std::size_t l = 0; l < sizeof(Real) / sizeof(double); ++l) r[l] = std::sqrt(x[l]);
  return r;
}
#endif

// Rows a stage of the pass takes: the field, kicks and drift of these rows, then their sin/cos,
// then their share of Z, their cells in L1 throughout (8 rows x 16 replicas: 4 KiB). One stage
// a row measured 1.16x slower than the separate passes (K_N N = 400, 16 replicas, Intel Xeon): a
// cell's chain of dependent operations, ~35 from its [cos, sin] to its new ones, left too few
// rows in flight. 4 and 16 rows ran alike at N = 400; at N = 10^5, whose cells come from memory,
// 16 and 64 rows ran 1.1-1.2x slower than 4 and 8 (AMD EPYC family 25 model 17).
constexpr std::size_t k_rows_a_stage = 8;

// The field, kicks and drift of rows [q0, q1) of the group of replicas [b0, b0 + k_fused_group)
// in `Lanes`, the group as k_fused_group / lanes vectors; Kicks kicks a cell; with ReadG, the
// last evaluation's g read from f.g instead of formed again. UnitA: every a_n is 1, whose
// products are exact (1 x = x for every double), so they are left out: the same bits, four
// multiplications fewer a vector.
// With StartSums (and not ReadG), also the group's running share of the sums at the phases the
// pass starts from at sums_out (replicas x [sum |y_n|, sum Re(e^{-i theta_n} y_n)]), the rows
// in order, as field_one and field_block_avx512 form them (rank_one_force.cpp; per lane
// kernel_arithmetic.hpp's order_term and coupling_term).
template <typename Lanes, std::size_t Kicks, bool ReadG, bool UnitA, bool StartSums>
HMFNET_INLINE void kick_drift_stage(const RankOneFusedCells& f, const KickDriftCoefficients& c,
                                    std::size_t q0, std::size_t q1, std::size_t b0,
                                    double* sums_out) {
  static_assert(!(ReadG && StartSums), "the sums need the field, which a stored g skips");
  using Real = typename Lanes::Real;
  constexpr std::size_t lanes = Lanes::k_lanes;
  constexpr std::size_t parts = k_fused_group / lanes;
  const std::size_t w = f.replicas;
  Real zc[parts], zs[parts], ck[parts][Kicks], order[parts], coupling[parts];
  for (std::size_t v = 0; v < parts; ++v) {
    simd::load_interleaved(f.z + 2 * (b0 + v * lanes), zc[v], zs[v]);
    // c K_b rounded first, as kick_drift_lanes.cpp and kicked_momentum form it.
    for (std::size_t i = 0; i < Kicks; ++i)
      ck[v][i] = c.kicks[i] * load<Real>(f.K + b0 + v * lanes);
    if constexpr (StartSums)
      simd::load_interleaved(sums_out + 2 * (b0 + v * lanes), order[v], coupling[v]);
  }
  // Locals, not the struct's fields: the stores through the cells' pointers could alias those,
  // and the loops would load them again every row. A scalar operand of a vector operation is
  // broadcast, the same bits as a vector of copies.
  const double* const a = f.a;
  const double* const g_formed = f.g;
  const double* const cs = f.cs;
  double* const p = f.p;
  double* const theta = f.theta;
  const double inverse_n = f.inverse_n;
  const double drift = c.drift;
  const bool diagonal = f.diagonal;
  for (std::size_t r = q0; r < q1; ++r) {
    const double ar = a[r];
    const double aa = ar * ar;
    for (std::size_t v = 0; v < parts; ++v) {
      const std::size_t k = r * w + b0 + v * lanes;
      Real g;
      if constexpr (ReadG) {
        g = load<Real>(g_formed + k);
      } else {
        Real cos_n;
        Real sin_n;
        simd::load_interleaved(cs + 2 * k, cos_n, sin_n);
        // rank_one_field, then g as field_one forms it.
        Real yc = zc[v];
        Real ys = zs[v];
        if constexpr (!UnitA) {
          yc = ar * yc;
          ys = ar * ys;
        }
        if (!diagonal) {
          if constexpr (UnitA) {
            yc = yc - cos_n;
            ys = ys - sin_n;
          } else {
            yc = yc - aa * cos_n;
            ys = ys - aa * sin_n;
          }
        }
        g = inverse_n * (cos_n * ys - sin_n * yc);
        if constexpr (StartSums) {
          order[v] = order[v] + sqrt_lanes(yc * yc + ys * ys);
          coupling[v] = coupling[v] + (cos_n * yc + sin_n * ys);
        }
      }
      Real pk = load<Real>(p + k);
      for (std::size_t i = 0; i < Kicks; ++i) pk = pk + ck[v][i] * g;
      store(p + k, pk);
      store(theta + k, load<Real>(theta + k) + drift * pk);
    }
  }
  if constexpr (StartSums) {
    for (std::size_t v = 0; v < parts; ++v)
      simd::store_interleaved(order[v], coupling[v], sums_out + 2 * (b0 + v * lanes));
  }
}

// The new [cos, sin] of rows [q0, q1), replicas [b0, b1): one call over the stage where its
// cells are contiguous (every group of the rows), one a row otherwise. In sincos.cpp's loop,
// whose AVX-512 version runs two registers side by side (two chains of dependent operations in
// flight, which the pass's own one-register sincos could not keep: with it the stage ran
// 1.17x slower, K_N N = 400, 16 replicas, AMD EPYC family 25 model 17; docs/performance.md "The
// rank-one stage in three loops"); it also takes the angles beyond the reduced range from the C
// library, so Z's sums below read only final values.
void sincos_stage(SincosIsa isa, const RankOneFusedCells& f, std::size_t q0, std::size_t q1,
                  std::size_t b0, std::size_t b1) {
  const std::size_t w = f.replicas;
  if (b1 - b0 == w) {
    sincos_interleaved_isa(isa, f.theta + q0 * w, (q1 - q0) * w, f.cs + 2 * q0 * w);
    return;
  }
  for (std::size_t r = q0; r < q1; ++r)
    sincos_interleaved_isa(isa, f.theta + r * w + b0, b1 - b0, f.cs + 2 * (r * w + b0));
}

// The group [b0, b0 + k_fused_group)'s running share of Z at z_out (replicas x [Re, Im]) plus
// a_n [cos, sin] of rows [q0, q1) in order, added on the interleaved values as they are stored:
// each lane one replica's Re or Im, the sum of OrderedColumnSums (from 0, the rows in order; a
// double's store and load between stages are exact).
template <typename Lanes, bool UnitA>
HMFNET_INLINE void z_share_stage(const RankOneFusedCells& f, std::size_t q0, std::size_t q1,
                                 std::size_t b0, double* z_out) {
  using Real = typename Lanes::Real;
  constexpr std::size_t parts = 2 * k_fused_group / Lanes::k_lanes;
  const std::size_t w = f.replicas;
  Real acc[parts];
  for (std::size_t v = 0; v < parts; ++v) acc[v] = load<Real>(z_out + 2 * b0 + v * Lanes::k_lanes);
  for (std::size_t r = q0; r < q1; ++r) {
    const double ar = f.a[r];
    const double* const row = f.cs + 2 * (r * w + b0);
    for (std::size_t v = 0; v < parts; ++v) {
      const Real value = load<Real>(row + v * Lanes::k_lanes);
      if constexpr (UnitA) {
        acc[v] = acc[v] + value;
      } else {
        acc[v] = acc[v] + ar * value;
      }
    }
  }
  for (std::size_t v = 0; v < parts; ++v) store(z_out + 2 * b0 + v * Lanes::k_lanes, acc[v]);
}

// The pass over rows [r0, r1) of the groups in replicas [b0, b1), a stage of rows at a time and
// in each stage every group: a row's cells are then read and written whole (w replicas side by
// side) within a stage, not one group's part of every row of a block and, a block later, the
// next group's. That order ran 1.16-1.20x faster a cell (K_N, N = 2 10^5 with 8 replicas against
// N = 10^5 with 16, the same bytes, AMD EPYC family 25 model 17; docs/performance.md "The
// rank-one groups side by side"). Each group's sums are its own, so the bits are those of one
// group at a time.
template <typename Lanes, std::size_t Kicks, bool ReadG, bool UnitA, bool StartSums>
HMFNET_INLINE void fused_rows(SincosIsa isa, const RankOneFusedCells& f,
                              const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                              std::size_t b0, std::size_t b1, double* z_out, double* sums_out) {
  for (std::size_t j = 2 * b0; j < 2 * b1; ++j) z_out[j] = 0.0;
  if constexpr (StartSums) {
    for (std::size_t j = 2 * b0; j < 2 * b1; ++j) sums_out[j] = 0.0;
  }
  for (std::size_t q0 = r0; q0 < r1; q0 += k_rows_a_stage) {
    const std::size_t q1 = q0 + k_rows_a_stage < r1 ? q0 + k_rows_a_stage : r1;
    for (std::size_t b = b0; b < b1; b += k_fused_group)
      kick_drift_stage<Lanes, Kicks, ReadG, UnitA, StartSums>(f, c, q0, q1, b, sums_out);
    sincos_stage(isa, f, q0, q1, b0, b1);
    for (std::size_t b = b0; b < b1; b += k_fused_group)
      z_share_stage<Lanes, UnitA>(f, q0, q1, b, z_out);
  }
}

template <typename Lanes, std::size_t Kicks, bool ReadG, bool StartSums>
HMFNET_INLINE void fused_unit(SincosIsa isa, const RankOneFusedCells& f,
                              const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                              std::size_t b0, std::size_t b1, double* z_out, double* sums_out) {
  f.unit_a
      ? fused_rows<Lanes, Kicks, ReadG, true, StartSums>(isa, f, c, r0, r1, b0, b1, z_out, sums_out)
      : fused_rows<Lanes, Kicks, ReadG, false, StartSums>(isa, f, c, r0, r1, b0, b1, z_out,
                                                          sums_out);
}

// The pass's variants: one or two kicks a cell; the field formed from [cos, sin] and Z, or the
// stored g read (a sampled step's field pass formed it), or the field formed with the sums at the
// start (a stored g is then not read: the same bits as forming it).
template <typename Lanes, std::size_t Kicks>
HMFNET_INLINE void fused_kicks(SincosIsa isa, const RankOneFusedCells& f,
                               const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                               std::size_t b0, std::size_t b1, double* z_out, double* sums_out) {
  if (sums_out != nullptr) {
    fused_unit<Lanes, Kicks, false, true>(isa, f, c, r0, r1, b0, b1, z_out, sums_out);
  } else if (f.g != nullptr) {
    fused_unit<Lanes, Kicks, true, false>(isa, f, c, r0, r1, b0, b1, z_out, nullptr);
  } else {
    fused_unit<Lanes, Kicks, false, false>(isa, f, c, r0, r1, b0, b1, z_out, nullptr);
  }
}

template <typename Lanes>
HMFNET_INLINE void fused_in(SincosIsa isa, const RankOneFusedCells& f,
                            const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                            std::size_t b0, std::size_t b1, double* z_out, double* sums_out) {
  if (c.kick_count == 2) {
    fused_kicks<Lanes, 2>(isa, f, c, r0, r1, b0, b1, z_out, sums_out);
  } else {
    fused_kicks<Lanes, 1>(isa, f, c, r0, r1, b0, b1, z_out, sums_out);
  }
}

void fused_baseline(const RankOneFusedCells& f, const KickDriftCoefficients& c, std::size_t r0,
                    std::size_t r1, std::size_t b0, std::size_t b1, double* z_out,
                    double* sums_out) {
  fused_in<Lanes4>(SincosIsa::baseline, f, c, r0, r1, b0, b1, z_out, sums_out);
}

#ifdef HMFNET_FUSED_X86
__attribute__((target("avx2"))) void fused_avx2(const RankOneFusedCells& f,
                                                const KickDriftCoefficients& c, std::size_t r0,
                                                std::size_t r1, std::size_t b0, std::size_t b1,
                                                double* z_out, double* sums_out) {
  fused_in<Lanes4>(SincosIsa::avx2, f, c, r0, r1, b0, b1, z_out, sums_out);
}
__attribute__((target("avx512f,avx512dq"))) void fused_avx512(const RankOneFusedCells& f,
                                                              const KickDriftCoefficients& c,
                                                              std::size_t r0, std::size_t r1,
                                                              std::size_t b0, std::size_t b1,
                                                              double* z_out, double* sums_out) {
  fused_in<Lanes8>(SincosIsa::avx512, f, c, r0, r1, b0, b1, z_out, sums_out);
}
#endif

}  // namespace

void rank_one_fused_groups(SincosIsa isa, const RankOneFusedCells& cells,
                           const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                           std::size_t b0, std::size_t b1, double* z_out, double* sums_out) {
#ifdef HMFNET_FUSED_X86
  if (isa == SincosIsa::avx512) return fused_avx512(cells, c, r0, r1, b0, b1, z_out, sums_out);
  if (isa == SincosIsa::avx2) return fused_avx2(cells, c, r0, r1, b0, b1, z_out, sums_out);
#endif
  fused_baseline(cells, c, r0, r1, b0, b1, z_out, sums_out);
}

}  // namespace hmfnet
