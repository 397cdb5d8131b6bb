#include "spectral/component_radii.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hmfnet {

ComponentRadii component_radii(const Network& network, const Components& components,
                               double tolerance, int max_iterations) {
  return component_radii(NetworkProduct(network), components, tolerance, max_iterations);
}

ComponentRadii component_radii(const AdjacencyProduct& product, const Components& components,
                               double tolerance, int max_iterations) {
  const auto n = static_cast<std::size_t>(product.size());
  const auto count = static_cast<std::size_t>(components.count);
  const auto label = [&](std::size_t i) { return static_cast<std::size_t>(components.label[i]); };
  const std::vector<double>& degrees = product.degrees();
  std::vector<double> x(n), y(n), ax(n), norm2(count), rayleigh(count);
  for (std::size_t i = 0; i < n; ++i) x[i] = degrees[i] + 1.0;
  ComponentRadii out;
  out.lambda.assign(count, 0.0);
  for (int it = 1; it <= max_iterations; ++it) {
    std::fill(norm2.begin(), norm2.end(), 0.0);
    std::fill(rayleigh.begin(), rayleigh.end(), 0.0);
    product.apply(x, ax);
    for (std::size_t u = 0; u < n; ++u) {
      y[u] = ax[u] + x[u];
      norm2[label(u)] += x[u] * x[u];
      rayleigh[label(u)] += x[u] * ax[u];
    }
    double change = 0.0;
    for (std::size_t c = 0; c < count; ++c) {
      const double estimate = norm2[c] > 0.0 ? rayleigh[c] / norm2[c] : 0.0;
      change = std::max(change,
                        std::abs(estimate - out.lambda[c]) / std::max(std::abs(estimate), 1e-300));
      out.lambda[c] = estimate;
    }
    out.iterations = it;
    if (it > 1 && change <= tolerance) {
      out.converged = true;
      break;
    }
    // Normalise each component's block of y to unit norm.
    std::fill(norm2.begin(), norm2.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) norm2[label(i)] += y[i] * y[i];
    for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / std::sqrt(norm2[label(i)]);
  }
  return out;
}

}  // namespace hmfnet
