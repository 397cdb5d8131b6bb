#pragma once
// A schedule run across replicas (SimulationParameters::K_across_replicas): the K values of a
// --restart-each-K sweep become replicas of one pass, so the network's index stream and each
// gathered neighbour serve every K at once (network_force.cpp: B replicas in one pass equal B
// separate passes bit for bit). Lane m R + r is replica r at K_m, so the lanes of one K are
// adjacent and the split back into one point per K is a slice.
//
// Everything a lane does is what the same replica does in its own segment: the same initial
// condition (each K restarts from it), the same step, its own energy, momentum and batch means.
// split_lanes rebuilds the result the sequential run returns, its time axis included
// (t = (m S + s) h, S the steps of one K, as that run counts them), so the two are equal bit for
// bit; only the work counts differ (steps and force evaluations: S, not K.size() x S).
#include <vector>

#include "dynamics/simulation.hpp"

namespace hmfnet {

/// The one-segment run that carries `params` (K_across_replicas): replicas repeated per K in
/// lane order, K reduced to its first value (each lane's own K is lane_couplings).
SimulationParameters lane_parameters(const SimulationParameters& params);

/// K of every lane: K_m for lanes m R .. m R + R - 1.
std::vector<double> lane_couplings(const SimulationParameters& params);

/// The result of the sequential schedule from the result of its lane run.
SimulationResult split_lanes(SimulationResult run, const SimulationParameters& params);

}  // namespace hmfnet
