#include "dynamics/rotor_state.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/random.hpp"

namespace hmfnet {

RotorState initial_state(NodeIndex first_row, NodeIndex rows,
                         const std::vector<InitialCondition>& replicas) {
  if (replicas.empty()) throw ParameterError("replicas", "0", ">= 1");
  for (const auto& ic : replicas) {
    if (!(ic.sigma0 >= 0.0) || !std::isfinite(ic.sigma0)) {
      throw ParameterError("sigma0", std::to_string(ic.sigma0), "finite and >= 0");
    }
    if (!std::isfinite(ic.omega)) throw ParameterError("omega", "not finite", "finite");
    if (ic.momenta == MomentumDistribution::waterbag && !(ic.sigma0 > 0.0)) {
      throw ParameterError("sigma0", std::to_string(ic.sigma0), "> 0 for the water-bag");
    }
  }
  RotorState s;
  s.replicas = static_cast<int>(replicas.size());
  s.rows = rows;
  s.first_row = first_row;
  s.theta.resize(static_cast<std::size_t>(rows) * replicas.size());
  s.p.resize(s.theta.size());
  constexpr double two_pi = 6.283185307179586476925286766559;
  for (int b = 0; b < s.replicas; ++b) {
    const InitialCondition& ic = replicas[static_cast<std::size_t>(b)];
    const double D = waterbag_half_width(ic.sigma0);
    for (NodeIndex r = 0; r < rows; ++r) {
      Rng rng(ic.seed, static_cast<std::uint64_t>(first_row + r));
      s.theta[s.at(r, b)] = two_pi * rng.uniform();
      s.p[s.at(r, b)] = ic.momenta == MomentumDistribution::waterbag
                            ? ic.omega + D * (2.0 * rng.uniform() - 1.0)
                            : ic.omega + ic.sigma0 * rng.normal();
    }
  }
  return s;
}

}  // namespace hmfnet
