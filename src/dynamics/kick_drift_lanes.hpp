#pragma once
// The leap-frog kick p += (c K_b) g and drift theta += c' p (theta' = p and eq:dMomentum_dT:
// Hamilton's equations of eq:hamiltonianNetworkCase) over a range of rows, every replica of a
// row, in four vector lanes: two SSE2 registers on the x86-64 baseline, or one AVX2 register where
// sincos_isa() allows AVX2 or more (one template, chosen at run time). A pass may apply two kicks
// before its drift: a step's closing kick and the next step's opening one (Integrator::steps), one
// pass over the cells instead of two. Every cell does kernel_arithmetic.hpp's kicked_momentum and
// drifted_angle, the same IEEE operations in the same order in every lane and set (no
// contraction: src/CMakeLists.txt), so the bits never depend on the set, the lane, the thread or
// the joining of passes (tests/dynamics/test_kick_drift_lanes.cpp). The build is x86-64
// baseline, where these loops ran two cells an instruction with c K_b formed again for every cell
// (docs/performance.md, "sincos selections in mask registers; the kick and drift in four lanes,
// joined across steps").
#include <cstddef>

#include "dynamics/sincos.hpp"

namespace hmfnet {

/// The cells of one pass: rows x replicas, row-major (RotorState's layout).
struct KickDriftCells {
  double* p;
  double* theta;    // nullptr: kicks alone
  const double* g;  // the force, cell by cell
  const double* K;  // one coupling per replica
  std::size_t replicas;
};

/// A pass's coefficients: p += (c K_b) g for each c of `kicks` (one, or two: a step's closing
/// kick and the next step's opening one, in that order, as two passes would apply them), then,
/// where the cells have theta, theta += drift p.
struct KickDriftCoefficients {
  double kicks[2];
  int kick_count;  // 1 or 2
  double drift;
};

/// The pass over rows [r0, r1).
void kick_drift_rows(const KickDriftCells& cells, const KickDriftCoefficients& c, std::size_t r0,
                     std::size_t r1);

/// The same in `isa`, or the widest set below it that this CPU runs (the tests compare them).
void kick_drift_rows_isa(SincosIsa isa, const KickDriftCells& cells, const KickDriftCoefficients& c,
                         std::size_t r0, std::size_t r1);

}  // namespace hmfnet
