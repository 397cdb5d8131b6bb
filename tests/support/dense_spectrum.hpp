#pragma once
// Dense symmetric eigen-decomposition (Eigen's SelfAdjointEigenSolver) of a small network: the
// independent check of the Anasazi solver and the power iterations in tests, and of lambda_min
// for bipartite networks. Test support only (hmfnet_test_support), not part of the library.
// O(N^3): refuses N > 4000.
#include <vector>

#include "network/network.hpp"

namespace hmfnet::test {

struct DenseSpectrum {
  std::vector<double> eigenvalues;  ///< ascending
  std::vector<double> perron;       ///< eigenvector of the largest, unit norm, sum >= 0
};

DenseSpectrum dense_spectrum(const Network& network);

}  // namespace hmfnet::test
