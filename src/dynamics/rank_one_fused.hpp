#pragma once
// The rank-one force's kick, drift and evaluation in one pass over groups of 8 replicas
// (CouplingForce::kick_drift_evaluate, which RankOneForce implements: rank_one_force.hpp), a
// stage of rows at a time, their cells in L1 from the field to the share of the new Z. The
// separate passes (the kick-drift pass, the sin/cos, Z,
// the field) each streamed every cell's theta, p, g or [cos, sin] through L2 and back and
// measured ~1.4 ns a rotor and replica step on top of the sincos at K_N N = 400, 16 replicas
// (Intel Xeon, docs/performance.md "The rank-one step in one pass"). Every lane does their IEEE
// operations in their order (kernel_arithmetic.hpp's rank_one_field, kicked_momentum and
// drifted_angle; sincos.hpp's sincos_interleaved_isa; no contraction: src/CMakeLists.txt), and
// Z's rows are added in the same order, so the same bits in every instruction set (tests/
// dynamics/test_rank_one_fused.cpp).
#include <cstddef>

#include "dynamics/kick_drift_lanes.hpp"
#include "dynamics/sincos.hpp"

namespace hmfnet {

/// Replicas in one group of the fused pass (one AVX-512 register, two AVX2 ones).
inline constexpr std::size_t k_fused_group = 8;

/// What the fused pass reads and writes: the cells rows x replicas, row-major.
struct RankOneFusedCells {
  const double* a;  ///< this rank's a_n (A = a a^T)
  double* cs;       ///< [cos, sin] of the last evaluation, overwritten by the new phases'
  const double* z;  ///< replicas x [Re Z, Im Z] of the last evaluation
  /// The last evaluation's g where it formed it (the same bits as forming it again from cs and
  /// z, one load a cell instead of the field's operations), else nullptr.
  const double* g;
  double inverse_n;
  bool diagonal;  ///< A_nn = a_n^2 stored; false: y_n less a_n^2 e^{i theta_n}
  double* p;
  double* theta;
  const double* K;  ///< one coupling per replica
  std::size_t replicas;
  /// Every a_n is 1 (the complete graph): the pass leaves out its products by a_n and a_n^2,
  /// exact there, for the same bits.
  bool unit_a = false;
};

/// Rows [r0, r1) of the groups of replicas [b0, b1) (whole groups: b0 and b1 multiples of
/// k_fused_group): per cell, the force g = (cos Im y - sin Re y) / N at the last [cos, sin] and Z
/// (or cells.g's), the kicks p += (c_i K_b) g, the drift theta += c.drift p, the [cos, sin] of the
/// new theta; and z_out[2 b] (Re), z_out[2 b + 1] (Im) for those replicas = sum over the rows in
/// order of a_n [cos, sin] from 0 (a block's share of Z: OrderedColumnSums), the same bits for
/// any split of the groups into calls. With sums_out (else nullptr), also sums_out[2 b] =
/// sum |y_n| and sums_out[2 b + 1] = sum Re(e^{-i theta_n} y_n) of those replicas over the rows
/// in order from 0, y_n the field at the phases the pass starts from (the bits of the field
/// pass's block sums, rank_one_force.cpp: field_block; cells.g is then not read). In `isa`,
/// which this CPU must run (sincos_isa(), or one that sincos_isa_available() accepts).
void rank_one_fused_groups(SincosIsa isa, const RankOneFusedCells& cells,
                           const KickDriftCoefficients& c, std::size_t r0, std::size_t r1,
                           std::size_t b0, std::size_t b1, double* z_out,
                           double* sums_out = nullptr);

}  // namespace hmfnet
