#pragma once
// Shared set-up of the simulation and checkpoint tests: a short three-K schedule, and per-rank-
// count temporary paths (ranks of one mpirun share the file; different rank counts do not).
#include <filesystem>
#include <string>

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

}  // namespace hmfnet::test
