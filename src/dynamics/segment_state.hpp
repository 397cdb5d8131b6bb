#pragma once
// What a run holds while it integrates one K of its schedule, defined once with one list of its
// fields. The list (`visit_fields`) is walked by every place that must see all of it: the
// checkpoint capture (gather over ranks) and restore (scatter), the checkpoint file's writer and
// reader, and its checksum (checkpoint.cpp). Adding an observable is one member here and one line
// in `visit_fields`; tests/dynamics/test_segment_state.cpp fails when a member is missing from
// the list (it counts the members of both aggregates) or is not restored by a checkpoint.
//
// The field kinds a visitor sees:
//   count(name, int64&)                      equal on every rank
//   real(name, double&)                      equal on every rank
//   replicated(name, vector<double>&)        equal on every rank (per replica)
//   rows(name, vector<double>&, width)       this rank's rows x width (0: the replica count);
//                                            a checkpoint holds all N rows
//   batch_means(name, BatchMeans&)           count and sums, equal on every rank
//   node_statistics(name, NodeStatistics&)   rows x k_row_width, and globals of which the
//                                            first k_shared_globals are equal on every rank and
//                                            the rest add over ranks
#include <cstdint>
#include <vector>

#include "dynamics/node_statistics.hpp"
#include "dynamics/rotor_state.hpp"
#include "dynamics/time_average.hpp"

namespace hmfnet {

/// Accumulators of the segment (the K) being integrated.
struct SegmentState {
  std::int64_t step = 0;  ///< steps done at this K
  BatchMeans R;           ///< eq:timeAverage of eq:globalOrderParam over [T1, T2], per replica
  std::vector<double> energy0, momentum0;  ///< per replica, at the segment's start
  std::vector<double> momentum_scale;      ///< per replica: sum |p_n| at the start (drift scale)
  std::vector<double> energy_err_max;      ///< per replica: max |E - E0| / |E0| so far
  std::vector<double> momentum_drift_max;  ///< per replica: max |P - P0| / momentum_scale so far
  std::vector<double> theta_T1;            ///< rows x replicas at T1 (node_data: Omega_n)
  std::vector<double> R_node_sum;          ///< rows x replicas: sum of R_n samples (node_data)
  NodeStatistics stats;                    ///< node_data only
};

/// Where a run stands in its schedule, and the rotors: with a SegmentState and the results so far,
/// all that a bit-identical resume needs.
struct RunPosition {
  std::int64_t k_index = 0;          ///< the K being integrated
  std::int64_t steps_total = 0;      ///< steps since the run started, all sessions
  std::int64_t evaluations = 0;      ///< force evaluations, all sessions
  double integration_seconds = 0.0;  ///< stepping-loop wall time, all sessions
  std::vector<double> theta, p;      ///< rows x replicas
};

/// The one list of what a checkpoint holds besides the results (see the header comment for the
/// kinds): the position, then the segment's accumulators.
template <class Position, class Segment, class Visitor>
void visit_fields(Position& position, Segment& segment, Visitor& v) {
  v.count("k_index", position.k_index);
  v.count("steps_total", position.steps_total);
  v.count("evaluations", position.evaluations);
  v.real("integration_seconds", position.integration_seconds);
  v.rows("theta", position.theta, 0);
  v.rows("p", position.p, 0);
  v.count("segment_step", segment.step);
  v.batch_means("batch", segment.R);
  v.replicated("energy0", segment.energy0);
  v.replicated("momentum0", segment.momentum0);
  v.replicated("momentum_scale", segment.momentum_scale);
  v.replicated("energy_err_max", segment.energy_err_max);
  v.replicated("momentum_drift_max", segment.momentum_drift_max);
  v.rows("theta_T1", segment.theta_T1, 0);
  v.rows("R_node_sum", segment.R_node_sum, 0);
  v.node_statistics("node", segment.stats);
}

}  // namespace hmfnet
