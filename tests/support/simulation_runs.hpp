#pragma once
// Shared set-up of the simulation and checkpoint tests: a short three-K schedule, and per-rank-
// count temporary paths (ranks of one mpirun share the file; different rank counts do not).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::test {

inline SimulationParameters short_run() {
  SimulationParameters p;
  p.h = 0.02;
  p.duration = 4.0;
  p.transient = 1.0;
  p.K = {20.0, 60.0, 120.0};
  p.record_stride = 10;
  p.replicas = {{6.0, 1.0, 11}};
  return p;
}

inline std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          (name + "_ranks" + std::to_string(ParallelSession::ranks()) + ".h5"))
      .string();
}

/// Removes `path` on the root rank, every rank waiting before and after (collective).
inline void remove_on_root(const std::string& path) {
  ParallelSession::max(0.0);
  if (ParallelSession::rank() == 0) std::filesystem::remove(path);
  ParallelSession::max(0.0);
}

/// short_run() on `d` stopped after `steps` steps with a checkpoint at `temp_path(name)` (written
/// at every record): the returned parameters resume it (stop_after_steps reset, resume unset).
inline SimulationParameters checkpointed_run(const DistributedNetwork& d,
                                             const std::vector<double>& degrees,
                                             CouplingForce& force, const std::string& name,
                                             std::int64_t steps) {
  SimulationParameters p = short_run();
  p.checkpoint_path = temp_path(name);
  remove_on_root(p.checkpoint_path);
  p.checkpoint_seconds = 0.0;
  p.stop_after_steps = steps;
  simulate(d, degrees, force, p);
  p.stop_after_steps = 0;
  return p;
}

}  // namespace hmfnet::test
