#pragma once
// Dense symmetric eigen-decomposition (Eigen's SelfAdjointEigenSolver) of a small network: the
// independent check of the Anasazi solver in tests, and of lambda_min for bipartite networks.
// O(N^3): refuses N > 4000.
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

struct DenseSpectrum {
  std::vector<double> eigenvalues;  ///< ascending
  std::vector<double> perron;       ///< eigenvector of the largest, unit norm, sum >= 0
};

DenseSpectrum dense_spectrum(const Network& network);

}  // namespace hmfnet
