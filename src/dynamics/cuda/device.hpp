#pragma once
// The CUDA device this build runs on: whether it can run this build's code, what it is, and the
// error every backend call throws. A plain C++ interface: no CUDA header reaches the caller.
#include <stdexcept>
#include <string>

namespace hmfnet::cuda {

/// A CUDA call that failed, a device that cannot run this build, or device memory that does not
/// suffice: one line naming it.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// CUDA devices this process sees (0 where there is no driver or no device).
int device_count();

/// Makes device `index` (0 <= index < device_count()) the one every later call of this thread
/// runs on (device 0 until then). Throws DeviceError otherwise.
void use_device(int index);

/// Whether the current CUDA device can run this build's code; if not, `why` says why in one
/// line.
bool device_usable(std::string& why);

/// The current device's name, memory and multiprocessor count, in one line.
std::string device_description();

}  // namespace hmfnet::cuda
