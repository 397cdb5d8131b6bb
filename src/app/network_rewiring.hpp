#pragma once
// `rewire`'s work: degree-preserving double-edge swaps until rho (eq:rhodef) reaches a target
// (Fig. PLcorr), the result written with what the swaps did in its provenance.
#include "app/rewire_request.hpp"
#include "network/network.hpp"
#include "network/rewiring.hpp"

namespace hmfnet::app {

/// The request's check and its output's (a known format, a writable place, not the input file):
/// made before the input is read.
void check_rewire(const RewireRequest& r);

/// Checks (check_rewire), rewires `network` and writes r.output on rank 0 (a temporary file, then
/// renamed). Every rank returns the result.
RewiringResult rewire(const RewireRequest& r, const Network& network);

}  // namespace hmfnet::app
