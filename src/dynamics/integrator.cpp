#include "dynamics/integrator.hpp"

#include "core/error.hpp"

namespace hmfnet {

void kick(RotorState& state, double c, const std::vector<double>& K, const std::vector<double>& g) {
  const auto w = static_cast<std::size_t>(state.replicas);
  const auto rows = static_cast<std::size_t>(state.rows);
#pragma omp parallel for schedule(static)
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t b = 0; b < w; ++b) state.p[r * w + b] += c * K[b] * g[r * w + b];
}

void drift(RotorState& state, double c) {
  const std::size_t cells = state.p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < cells; ++k) state.theta[k] += c * state.p[k];
}

void LeapFrog::step(RotorState& state, double h, const std::vector<double>& K,
                    ForceEvaluation& f) const {
  kick(state, 0.5 * h, K, f.g());
  drift(state, h);
  f.update(state);
  kick(state, 0.5 * h, K, f.g());
}

std::unique_ptr<Integrator> make_integrator(const std::string& name) {
  if (name == "leapfrog") return std::make_unique<LeapFrog>();
  throw ParameterError("integrator", name, "leapfrog");
}

}  // namespace hmfnet
