#pragma once
// The incoherent variance mu0 of a simulated run, from its conserved energy and momentum: the
// self-consistent theory depends on the initial state only through them (eq:Hsub0,
// eq:MomentumConserved), mu0 = sigma0^2 + 2 U0 / N = 2 E / N - (P / N)^2. Comparing a run with
// eq:rSigmaBesselMain at its own mu0 removes the O(sqrt(2/N)) sample error of sigma0^2 (3% at
// N = 2000, which moves K_c by as much). Shared by simulation_vs_theory and
// theory_breaking_networks.
#include <cstddef>

#include "dynamics/simulation.hpp"

namespace hmfnet::verification {

/// mu0 of replica b at coupling K, from the last record at K (E is constant within a K up to
/// the integrator's error).
inline double incoherent_variance(const SimulationResult& sim, double K, std::size_t b, double n) {
  const auto B = sim.points.front().R_mean.size();
  std::size_t last = 0;
  for (std::size_t i = 0; i < sim.series.K.size(); ++i) {
    if (sim.series.K[i] == K) last = i;
  }
  const double P = sim.series.momentum[last * B + b] / n;
  return 2.0 * sim.series.energy[last * B + b] / n - P * P;
}

}  // namespace hmfnet::verification
