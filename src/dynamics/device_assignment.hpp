#pragma once
// Which CUDA device each MPI rank of `hmfnet simulate --device cuda` steps on: the ranks of one
// machine take its devices in turn (rank i of the machine on device i mod devices), so one rank
// a GPU where there are as many, and ranks sharing them where there are more; a shared device
// runs the ranks' kernels one after another, the same bits as one rank a device
// (docs/scaling.md: what sharing costs).
#include <string>

namespace hmfnet {

struct DeviceAssignment {
  int device = 0;       ///< the device index this rank steps on
  bool shared = false;  ///< more ranks on this machine than devices
  std::string note;     ///< one line saying how the ranks share the devices, when shared
};

/// The device of rank `machine_rank` of the `machine_ranks` ranks on one machine with `devices`
/// CUDA devices (each at least 1; machine_rank below machine_ranks). Throws ParameterError
/// otherwise.
DeviceAssignment assign_device(int machine_rank, int machine_ranks, int devices);

}  // namespace hmfnet
