#pragma once
// Which stepper (ensemble_stepper.hpp) runs a simulation: SimulationParameters::device, "cpu"
// (host_stepper.hpp) or "cuda" (device_stepper.hpp). One choice for the CLI, Python and the
// drivers.
#include <memory>

#include "dynamics/coupling_force.hpp"
#include "dynamics/ensemble_stepper.hpp"
#include "dynamics/simulation_parameters.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// The stepper of params.device for this rank's rows with `force` (kept by reference). Throws
/// ParameterError when the device cannot take the run (device_stepper.hpp).
std::unique_ptr<EnsembleStepper> make_stepper(const DistributedNetwork& network,
                                              CouplingForce& force,
                                              const SimulationParameters& params);

}  // namespace hmfnet
