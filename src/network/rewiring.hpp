#pragma once
// Degree-preserving rewiring towards a target degree correlation rho (eq:rhodef), as used for
// the paper's Fig. PLcorr, following Restrepo, Ott & Hunt, Phys. Rev. E 76, 056119 (2007):
// repeated double-edge swaps {a,b},{c,d} -> {a,c},{b,d} or {a,d},{b,c}. Of the two pairings,
// the one that moves sum_edges d_u d_v towards the target is proposed (to raise rho, the two
// highest-degree endpoints are joined, as in Xulvi-Brunet & Sokolov 2004), and kept only if it
// moves rho towards the target and creates neither a self-loop nor a repeated edge.
//
// Each swap removes one edge end from and adds one to each of a, b, c, d, so every degree is
// unchanged (tested on every run by rewire_to_correlation's final check).
#include <cstdint>

#include "network/network.hpp"

namespace hmfnet {

/// Rewiring is a serial Markov chain on the whole network (one rank; every rank of an MPI run
/// repeats it): inputs with more stored entries than this are refused rather than left running
/// for hours: measured ~2 10^6 attempts per second here (ER N = 10^5, degree 100), so the
/// default budget of 200 attempts per edge is ~17 minutes at the limit.
inline constexpr std::int64_t k_max_rewiring_entries = 20'000'000;

struct RewiringParameters {
  double target_rho = 1.0;  ///< stop when rho crosses this value
  std::uint64_t seed = 0;
  std::int64_t max_attempts = 0;  ///< 0: 200 x edges
};

struct RewiringResult {
  Network network;
  double initial_rho = 0.0;
  double final_rho = 0.0;
  std::int64_t attempts = 0;
  std::int64_t swaps = 0;
};

/// Needs a simple unweighted network (no self-loops, no weights) of at most
/// k_max_rewiring_entries stored entries: throws ParameterError otherwise.
/// Throws ConvergenceError, with the rho reached, when the target is not reached within
/// max_attempts (the swaps saturate below the largest rho the degree sequence allows).
RewiringResult rewire_to_correlation(const Network& network, const RewiringParameters& params);

}  // namespace hmfnet
