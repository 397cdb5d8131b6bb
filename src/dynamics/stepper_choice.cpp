#include "dynamics/stepper_choice.hpp"

#include "dynamics/device_stepper.hpp"
#include "dynamics/host_stepper.hpp"

namespace hmfnet {

std::unique_ptr<EnsembleStepper> make_stepper(const DistributedNetwork& network,
                                              CouplingForce& force,
                                              const SimulationParameters& params) {
  if (params.device == "cuda") return make_device_stepper(network, force, params);
  return std::make_unique<HostStepper>(force);
}

}  // namespace hmfnet
