#include "dynamics/rank_one_fused.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/vector_lanes.hpp"

namespace hmfnet {

namespace {

using simd::Lanes4;
using simd::Lanes8;

using simd::load;
using simd::store;

// Where a new angle was beyond the sincos's reduced range (or not finite): its [cos, sin] from
// the C library, as sincos_interleaved gives it, and the group's Z share summed again from the
// stored values in the same order (the vector sums took the lanes' meaningless values, NaN
// among them).
void outside_range(const RankOneFusedCells& f, std::size_t r0, std::size_t r1, std::size_t b0,
                   double* z_out) {
  const std::size_t w = f.replicas;
  double acc[2 * k_fused_group] = {};
  for (std::size_t r = r0; r < r1; ++r) {
    for (std::size_t j = 0; j < k_fused_group; ++j) {
      const std::size_t k = r * w + b0 + j;
      if (!sincos_reduces(f.theta[k])) ::sincos(f.theta[k], &f.cs[2 * k + 1], &f.cs[2 * k]);
    }
    for (std::size_t j = 0; j < 2 * k_fused_group; ++j)
      acc[j] += f.a[r] * f.cs[2 * (r * w + b0) + j];
  }
  std::memcpy(z_out + 2 * b0, acc, sizeof acc);
}

// Rows a stage of the pass takes: the field, kicks and drift of these rows, then their sin/cos
// and Z, their cells in L1 between the two. One stage a row measured 1.16x slower than the
// separate passes (K_N N = 400, 16 replicas, Intel Xeon): a cell's chain of dependent operations,
// ~35 from its [cos, sin] to its new ones, left too few rows in flight.
constexpr std::size_t k_rows_a_stage = 8;

// One stage, rows [q0, q1), of the group of replicas [b0, b0 + k_fused_group) in `Lanes`, the
// group as k_fused_group / lanes vectors: the field, kicks and drift of the stage's rows, then
// their sin/cos, each row's a_n [cos, sin] added to the group's running share of Z at z_out (a
// double's store and load are exact: the bits of one sum in registers over all the rows); Kicks
// kicks a cell; with ReadG, the last evaluation's g read from f.g instead of formed again.
// `inside` clears the lanes whose angle was beyond the reduced range.
template <typename Lanes, std::size_t Kicks, bool ReadG>
HMFNET_INLINE void fused_stage(const RankOneFusedCells& f, const KickDriftCoefficients& c,
                               std::size_t q0, std::size_t q1, std::size_t b0, double* z_out,
                               typename Lanes::Mask& inside) {
  using Real = typename Lanes::Real;
  constexpr std::size_t lanes = Lanes::k_lanes;
  constexpr std::size_t parts = k_fused_group / lanes;
  const std::size_t w = f.replicas;
  const std::uint64_t range_bits = ScalarLane::bits(k_reduced_range);
  Real zc[parts], zs[parts], ck[parts][Kicks], acc_c[parts], acc_s[parts];
  for (std::size_t v = 0; v < parts; ++v) {
    simd::load_interleaved(f.z + 2 * (b0 + v * lanes), zc[v], zs[v]);
    // c K_b rounded first, as kick_drift_lanes.cpp and kicked_momentum form it.
    for (std::size_t i = 0; i < Kicks; ++i)
      ck[v][i] = c.kicks[i] * load<Real>(f.K + b0 + v * lanes);
    simd::load_interleaved(z_out + 2 * (b0 + v * lanes), acc_c[v], acc_s[v]);
  }
  // Locals, not the struct's fields: the stores through the cells' pointers could alias those,
  // and the loops would load them again every row. A scalar operand of a vector operation is
  // broadcast, the same bits as a vector of copies.
  const double* const a = f.a;
  const double* const g_formed = f.g;
  double* const cs = f.cs;
  double* const p = f.p;
  double* const theta = f.theta;
  const double inverse_n = f.inverse_n;
  const double drift = c.drift;
  const bool diagonal = f.diagonal;
  // The field, kicks and drift of the stage's rows.
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
        Real yc = ar * zc[v];
        Real ys = ar * zs[v];
        if (!diagonal) {
          yc = yc - aa * cos_n;
          ys = ys - aa * sin_n;
        }
        g = inverse_n * (cos_n * ys - sin_n * yc);
      }
      Real pk = load<Real>(p + k);
      for (std::size_t i = 0; i < Kicks; ++i) pk = pk + ck[v][i] * g;
      store(p + k, pk);
      store(theta + k, load<Real>(theta + k) + drift * pk);
    }
  }
  // The new [cos, sin] and their share of Z, the rows in order.
  for (std::size_t r = q0; r < q1; ++r) {
    const double ar = a[r];
    for (std::size_t v = 0; v < parts; ++v) {
      const std::size_t k = r * w + b0 + v * lanes;
      const Real angle = load<Real>(theta + k);
      Real cos_n;
      Real sin_n;
      sincos_lanes<Lanes>(angle, cos_n, sin_n);
      inside &= Lanes::at_most(Lanes::bits(angle) & sincos_constants::k_abs_mask, range_bits);
      simd::store_interleaved(cos_n, sin_n, cs + 2 * k);
      acc_c[v] = acc_c[v] + ar * cos_n;
      acc_s[v] = acc_s[v] + ar * sin_n;
    }
  }
  for (std::size_t v = 0; v < parts; ++v)
    simd::store_interleaved(acc_c[v], acc_s[v], z_out + 2 * (b0 + v * lanes));
}

// The pass over rows [r0, r1) of the groups in replicas [b0, b1), a stage of rows at a time and
// in each stage every group: a row's cells are then read and written whole (w replicas side by
// side) within a stage, not one group's part of every row of a block and, a block later, the
// next group's. That order ran 1.16-1.20x faster a cell (K_N, N = 2 10^5 with 8 replicas against
// N = 10^5 with 16, the same bytes, AMD EPYC family 25 model 17; docs/performance.md "The
// rank-one groups side by side"). Each group's sums are its own, so the bits are those of one
// group at a time.
template <typename Lanes, std::size_t Kicks, bool ReadG>
HMFNET_INLINE void fused_rows(const RankOneFusedCells& f, const KickDriftCoefficients& c,
                              std::size_t r0, std::size_t r1, std::size_t b0, std::size_t b1,
                              double* z_out) {
  for (std::size_t j = 2 * b0; j < 2 * b1; ++j) z_out[j] = 0.0;
  typename Lanes::Mask inside = ~typename Lanes::Mask{};
  for (std::size_t q0 = r0; q0 < r1; q0 += k_rows_a_stage) {
    const std::size_t q1 = q0 + k_rows_a_stage < r1 ? q0 + k_rows_a_stage : r1;
    for (std::size_t b = b0; b < b1; b += k_fused_group)
      fused_stage<Lanes, Kicks, ReadG>(f, c, q0, q1, b, z_out, inside);
  }
  std::uint64_t all_inside = ~std::uint64_t{0};
  for (std::size_t l = 0; l < Lanes::k_lanes; ++l)
    all_inside &= static_cast<std::uint64_t>(inside[l]);
  if (all_inside != 0) return;
  for (std::size_t b = b0; b < b1; b += k_fused_group) outside_range(f, r0, r1, b, z_out);
}

template <typename Lanes>
HMFNET_INLINE void fused_in(const RankOneFusedCells& f, const KickDriftCoefficients& c,
                            std::size_t r0, std::size_t r1, std::size_t b0, std::size_t b1,
                            double* z_out) {
  const bool read_g = f.g != nullptr;
  if (c.kick_count == 2) {
    read_g ? fused_rows<Lanes, 2, true>(f, c, r0, r1, b0, b1, z_out)
           : fused_rows<Lanes, 2, false>(f, c, r0, r1, b0, b1, z_out);
  } else {
    read_g ? fused_rows<Lanes, 1, true>(f, c, r0, r1, b0, b1, z_out)
           : fused_rows<Lanes, 1, false>(f, c, r0, r1, b0, b1, z_out);
  }
}

void fused_baseline(const RankOneFusedCells& f, const KickDriftCoefficients& c, std::size_t r0,
                    std::size_t r1, std::size_t b0, std::size_t b1, double* z_out) {
  fused_in<Lanes4>(f, c, r0, r1, b0, b1, z_out);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HMFNET_FUSED_X86 1
__attribute__((target("avx2"))) void fused_avx2(const RankOneFusedCells& f,
                                                const KickDriftCoefficients& c, std::size_t r0,
                                                std::size_t r1, std::size_t b0, std::size_t b1,
                                                double* z_out) {
  fused_in<Lanes4>(f, c, r0, r1, b0, b1, z_out);
}
__attribute__((target("avx512f,avx512dq"))) void fused_avx512(const RankOneFusedCells& f,
                                                              const KickDriftCoefficients& c,
                                                              std::size_t r0, std::size_t r1,
                                                              std::size_t b0, std::size_t b1,
                                                              double* z_out) {
  fused_in<Lanes8>(f, c, r0, r1, b0, b1, z_out);
}
#endif

}  // namespace

void rank_one_fused_groups(SincosIsa isa, const RankOneFusedCells& cells,
                           const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                           std::size_t b0, std::size_t b1, double* z_out) {
#ifdef HMFNET_FUSED_X86
  if (isa == SincosIsa::avx512) return fused_avx512(cells, c, r0, r1, b0, b1, z_out);
  if (isa == SincosIsa::avx2) return fused_avx2(cells, c, r0, r1, b0, b1, z_out);
#endif
  fused_baseline(cells, c, r0, r1, b0, b1, z_out);
}

}  // namespace hmfnet
