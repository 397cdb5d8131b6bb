#pragma once
// Everything a run needs to continue bit-identically: the state, the position in the schedule,
// every accumulator, and the results so far. One HDF5 file written by the root rank through
// write-then-rename (a checkpoint is never half-written); read by every rank. A `fingerprint`
// of the run's parameters guards against resuming another run's checkpoint.
#include <cstdint>
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"

namespace hmfnet {

struct Checkpoint {
  std::string fingerprint;
  int k_index = 0;                  ///< the K being integrated
  std::int64_t segment_step = 0;    ///< steps done at that K
  std::int64_t steps_total = 0;
  std::int64_t evaluations = 0;
  double integration_seconds = 0.0;
  int replicas = 1;
  std::vector<double> theta, p;     ///< N x replicas (whole network)
  std::int64_t batch_count = 0;
  std::vector<double> batch_sums;
  std::vector<double> energy0, momentum0, momentum_scale, energy_err_max, momentum_drift_max;
  std::vector<double> theta_T1, R_node_sum;  ///< N x replicas, node_data only
  std::vector<double> node_rows;     ///< N x 6, node_data only (NodeStatistics::row_state)
  std::vector<double> node_globals;  ///< summed over ranks (NodeStatistics::global_state)
  std::vector<PointResult> points;
  TimeSeries series;
};

void write_checkpoint(const std::string& path, const Checkpoint& c);

/// Throws InputError naming the file for anything missing or inconsistent.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace hmfnet
