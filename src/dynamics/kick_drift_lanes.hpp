#pragma once
// The leap-frog kick p += (c K_b) g and drift theta += c' p (theta' = p and eq:dMomentum_dT:
// Hamilton's equations of eq:hamiltonianNetworkCase) over a range of rows, every replica of a
// row, in four vector lanes: two SSE2 registers on the x86-64 baseline, or one AVX2 register where
// sincos_isa() allows AVX2 or more (one template, chosen at run time). Every cell does
// kernel_arithmetic.hpp's kicked_momentum and drifted_angle, the same IEEE operations in the same
// order in every lane and set (no contraction: src/CMakeLists.txt), so the bits never depend on
// the set, the lane or the thread (tests/dynamics/test_kick_drift_lanes.cpp). The build is x86-64
// baseline, where these loops ran two cells an instruction with c K_b formed again for every
// cell (docs/performance.md, "sincos selections in mask registers; the kick and drift in four
// lanes").
#include <cstddef>

#include "dynamics/sincos.hpp"

namespace hmfnet {

/// The cells of one pass: rows x replicas, row-major (RotorState's layout).
struct KickDriftCells {
  double* p;
  double* theta;    // nullptr: a kick alone
  const double* g;  // the force, cell by cell
  const double* K;  // one coupling per replica
  std::size_t replicas;
};

/// For rows [r0, r1): p += (c_kick K_b) g and, where cells.theta, then theta += c_drift p.
void kick_drift_rows(const KickDriftCells& cells, double c_kick, double c_drift, std::size_t r0,
                     std::size_t r1);

/// The same in `isa`, or the widest set below it that this CPU runs (the tests compare them).
void kick_drift_rows_isa(SincosIsa isa, const KickDriftCells& cells, double c_kick, double c_drift,
                         std::size_t r0, std::size_t r1);

}  // namespace hmfnet
