#pragma once
// The CUDA device's stepper (ensemble_stepper.hpp) behind `hmfnet simulate --device cuda`: the
// sparse force on the network's rows (cuda::SparseEnsemble) or the rank-one force of the
// complete graph and of A = a a^T (cuda::RankOneEnsemble), every replica's state on the device,
// the CPU's per-cell arithmetic (kernel_arithmetic.hpp) and summation order, so a run's output
// is the CPU's bit for bit and a checkpoint written by either resumes on the other. The host holds
// the schedule, the batch means and the records; per chunk of steps it reads back only each step's
// order sums. With node data (which read every step's state and fields) the device also keeps
// each cell's y_n, and both are copied back each step.
//
// Over MPI ranks each rank steps its own rows on a device of its machine (device_assignment.hpp),
// the ghosts' [cos, sin] or Z crossing through the host at each evaluation as the CPU's forces
// exchange them (cuda/rank_exchange.hpp): the CPU's bits at the same rank count.
// Not on the device (each refused by make_device_stepper in one line, before any file is
// written): methods that are no kick-drift splitting (rk4).
#include <memory>
#include <string>

#include "dynamics/coupling_force.hpp"
#include "dynamics/ensemble_stepper.hpp"
#include "dynamics/simulation_parameters.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// Empty when this build and this machine can step on a CUDA device; otherwise why, in one line
/// (a build without the CUDA backend, no device, a device that cannot run this build).
std::string cuda_unavailable();

/// What needs no network, checked before it is read: throws ParameterError naming the first
/// option the device does not take (the integrator), then a missing device.
void require_device_for(const SimulationParameters& params);

/// The device's stepper for `params` on this rank's rows with `force` (whose kind and precision
/// it takes; it keeps a reference, for the fields of a blow-up report). Throws ParameterError
/// naming what the device does not take, or the device's own error (memory that does not
/// suffice: the bytes needed and free).
std::unique_ptr<EnsembleStepper> make_device_stepper(const DistributedNetwork& network,
                                                     CouplingForce& force,
                                                     const SimulationParameters& params);

}  // namespace hmfnet
