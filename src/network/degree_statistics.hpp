#pragma once
// Degree summaries used by the paper: mean degree ||d|| (node average) and the degree-correlation
// coefficient rho of eq:rhodef.
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

/// ||d|| = (1/N) sum_n d_n.
double mean_degree(const Network& network);

/// eq:rhodef: rho = ||d_n d_m||_e / (||d_n||_e ||d_m||_e), averages over ordered pairs (n, m)
/// weighted by A_nm (each undirected edge counted in both directions), which is
/// rho = (d^T A d)(sum_n d_n) / (sum_n d_n^2)^2. rho = 1 for uncorrelated degrees, > 1 assortative.
double degree_correlation(const Network& network);

}  // namespace hmfnet
