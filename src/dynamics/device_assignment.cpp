#include "dynamics/device_assignment.hpp"

#include "core/error.hpp"

namespace hmfnet {

DeviceAssignment assign_device(int machine_rank, int machine_ranks, int devices) {
  if (devices < 1 || machine_ranks < 1 || machine_rank < 0 || machine_rank >= machine_ranks) {
    throw ParameterError("device assignment: rank " + std::to_string(machine_rank) + " of " +
                         std::to_string(machine_ranks) + " on a machine with " +
                         std::to_string(devices) + " CUDA devices");
  }
  DeviceAssignment a;
  a.device = machine_rank % devices;
  a.shared = machine_ranks > devices;
  if (a.shared) {
    const auto plural = [](int n, const char* one, const char* many) {
      return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    a.note = plural(machine_ranks, "MPI rank", "MPI ranks") + " share " +
             plural(devices, "CUDA device", "CUDA devices") +
             " on this machine (its rank i on device i mod " + std::to_string(devices) + ")";
  }
  return a;
}

}  // namespace hmfnet
