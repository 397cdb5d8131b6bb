#pragma once
// The integrator and step of one coupling K of a schedule. The cheapest method whose error in
// <R>_t stays under a figure's statistical floor depends on K / K_c (the fastest local frequency
// grows as sqrt(K max_n R_n)), so a sweep may change method between its K values
// (docs/choosing_a_method.md; the choices come from the work-precision driver).
#include <string>

namespace hmfnet {

struct StepChoice {
  std::string integrator = "leapfrog";  ///< a name make_integrator accepts
  double h = 0.01;                      ///< time step, > 0
};

inline bool operator==(const StepChoice& a, const StepChoice& b) {
  return a.integrator == b.integrator && a.h == b.h;
}

}  // namespace hmfnet
