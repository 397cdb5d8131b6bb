#pragma once
// The largest eigenvalue lambda_c of A restricted to each connected component. On a
// disconnected network the theory's threshold is per component (a component synchronizes iff
// K lambda_c / (2 N mu) > 1, with the variance mu shared through eq:rSigmaBesselMain's second
// line), so the self-consistent solver needs them to start only the components that can be
// coherent (theory/self_consistent.cpp). No Trilinos: in hmfnet_core, below hmfnet_theory.
//
// Method: power iteration on A + I (the shift makes a bipartite component's -lambda_c smaller
// in magnitude than lambda_c + 1), all components at once with one norm each, from the positive
// start d_n + 1 (which overlaps every component's Perron vector); lambda_c is the Rayleigh
// quotient, a lower bound that converges at twice the vector's rate. Stops when no estimate
// moved by more than `tolerance` relative in one iteration, or after max_iterations.
#include <vector>

#include "network/adjacency_product.hpp"
#include "network/network.hpp"
#include "network/structure.hpp"

namespace hmfnet {

struct ComponentRadii {
  std::vector<double> lambda;  ///< per component label (0 for an isolated node)
  int iterations = 0;
  bool converged = false;
};

ComponentRadii component_radii(const AdjacencyProduct& product, const Components& components,
                               double tolerance = 1e-12, int max_iterations = 20000);
ComponentRadii component_radii(const Network& network, const Components& components,
                               double tolerance = 1e-12, int max_iterations = 20000);

}  // namespace hmfnet
