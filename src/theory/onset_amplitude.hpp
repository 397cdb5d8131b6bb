#pragma once
// eq:globalOrderRInDeltaK: just above onset R ~ G sqrt((K - K_c)/K_c) with
//   G = (lambda / ||d||) sqrt( 2 ||u^2|| ||u||^2 / (||u^4|| + 4 ||u^2||^2) ),
// ||x|| the node average and u the Perron vector (G does not depend on u's normalisation).
// A regular graph (u constant, lambda = ||d||) gives G = sqrt(2/5).
#include <vector>

namespace hmfnet {

/// Throws ParameterError for an empty or all-zero u, or mean_degree <= 0.
double onset_amplitude(double lambda, double mean_degree, const std::vector<double>& u);

/// The near-onset approximation R = G sqrt((K - K_c)/K_c) for K >= K_c, 0 below.
double onset_order_parameter(double G, double K_over_Kc);

}  // namespace hmfnet
