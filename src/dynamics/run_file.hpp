#pragma once
// The results file of `hmfnet simulate` (schema in docs/simulation_output.md), and the results
// groups it shares with checkpoints:
//   /points/K, /points/K_over_Kc, /points/h          [points]
//   /points/integrator                               [points] strings
//   /points/R_mean, R_sem, energy_rel_error_max,
//           momentum_drift                           [points x replicas]
//   /points/R_node, /points/omega_node              [points * N x replicas] (node data only)
//   /timeseries/t, /timeseries/K                     [records]
//   /timeseries/R, energy, momentum                  [records x replicas]
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"
#include "io/hdf5_file.hpp"

namespace hmfnet {

void write_results(const Hdf5File& file, const std::vector<PointResult>& points,
                   const TimeSeries& series, int replicas);
void read_results(const Hdf5File& file, std::vector<PointResult>& points, TimeSeries& series,
                  int replicas);

/// What a results file records besides the results and the SimulationParameters.
struct RunMetadata {
  /// The caller's parameters outside SimulationParameters (input file, force, precision): a JSON
  /// object merged into the file's `parameters` (run_parameters).
  std::string inputs_json;
  std::string network_json;     ///< network summary (n, nnz, lambda, Kc, ...)
  std::string provenance_json;  ///< version, commit, command line, ranks, threads, wall time
  double Kc = 0.0;              ///< 0: unknown
};

/// The `parameters` a results file records: to_json(params) (simulation_parameters.hpp) with the
/// keys of `inputs_json` (an object, or empty) added. The CLI's provenance records the same.
nlohmann::json run_parameters(const SimulationParameters& params, const std::string& inputs_json);

/// Upper estimates of the bytes a run writes (its results file; one checkpoint), from the
/// parameters alone, for the free-space check at start-up: 8 bytes per stored double, the
/// per-point, per-node and time-series arrays of the schema above, plus 1 MiB of HDF5 metadata.
std::uintmax_t estimated_run_file_bytes(const SimulationParameters& params, NodeIndex n);
std::uintmax_t estimated_checkpoint_bytes(const SimulationParameters& params, NodeIndex n);

/// Writes to a temporary and renames: an interrupted run leaves no file under `path`.
void write_run_file(const std::string& path, const SimulationResult& result,
                    const SimulationParameters& params, const RunMetadata& meta);

}  // namespace hmfnet
