#pragma once
// Phase-space state of B replicas of the rotor network on this rank's rows
// (eq:hamiltonianNetworkCase: unit moments of inertia). Arrays are row-major [row][replica], so
// one pass over a row's neighbours serves every replica (the index array is read once per step).
// Phases are not reduced modulo 2 pi: node frequencies Omega_n need the unwrapped angle.
#include <cstdint>
#include <vector>

#include "network/network.hpp"
#include "theory/momentum_distribution.hpp"

namespace hmfnet {

struct RotorState {
  int replicas = 1;
  NodeIndex rows = 0;         ///< rows owned by this rank
  NodeIndex first_row = 0;    ///< global index of the first owned row
  std::vector<double> theta;  ///< rows * replicas
  std::vector<double> p;      ///< rows * replicas

  std::size_t at(NodeIndex row, int replica) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(replicas) +
           static_cast<std::size_t>(replica);
  }
};

/// Initial condition of one replica (paper, Sec. numericalExperiments): theta_n uniform in
/// [0, 2 pi), p_n ~ Gaussian(omega, sigma0), or uniform on [omega - D, omega + D) with
/// D = sqrt(3) sigma0 for the water-bag (momentum_distribution.hpp): mean omega and standard
/// deviation sigma0 either way.
struct InitialCondition {
  double omega = 6.0;
  double sigma0 = 0.35;
  std::uint64_t seed = 0;
  MomentumDistribution momenta = MomentumDistribution::gaussian;
};

/// Node n of a replica draws from random stream n of that replica's seed, so the state does not
/// depend on how rows are split over ranks. Throws ParameterError for sigma0 < 0 or non-finite
/// values.
RotorState initial_state(NodeIndex first_row, NodeIndex rows,
                         const std::vector<InitialCondition>& replicas);

}  // namespace hmfnet
