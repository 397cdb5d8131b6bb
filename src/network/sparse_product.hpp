#pragma once
// The sparse product y = A x with the network's adjacency matrix: y_i = sum_j A_ij x_j (weights
// 1.0 in a 0/1 network). The theory's maps (eq:rSigmaBesselMain's sum_m A_nm v_m), the power
// iterations and rho (d^T A d, eq:rhodef) all need it.
//
// Each y_i is summed by one thread over row i in storage order (ascending j), so the result is
// bit-identical to a plain row-wise CSR loop whatever the number of OpenMP threads.
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

/// y = A x. x holds N entries and must not be y; y is resized to N.
void multiply(const Network& network, const std::vector<double>& x, std::vector<double>& y);

}  // namespace hmfnet
