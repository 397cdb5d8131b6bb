#pragma once
// What the simulation protocol (simulation.cpp) needs of whatever holds the replicas' state and
// steps it: the CPU (host_stepper.hpp) or a CUDA device (device_stepper.hpp). The protocol drives
// a stepper in chunks of steps between its records, so a device stepper runs a whole chunk
// without the host, and hands back per step only what the time average eq:timeAverage needs
// (each replica's sum_n |y_n|), and at a record the sums of the observables. Everything else
// (the batch means, the checkpoints, the record's observers) stays on the host, the same code
// for every stepper: a stepper that reproduces the CPU's sums bit for bit reproduces the run's
// output bit for bit.
#include <cstdint>
#include <string>
#include <vector>

#include "dynamics/integrator.hpp"
#include "dynamics/rotor_state.hpp"

namespace hmfnet {

/// This rank's sums at the current state, per replica, each in OrderedColumnSums' order
/// (ordered_sum.hpp) and not yet reduced over ranks: sum_n |y_n| (eq:globalOrderParam),
/// sum_n Re(e^{-i theta_n} y_n) (the potential, coupling_force.hpp), sum_n p_n^2 / 2,
/// sum_n p_n and sum_n |p_n|.
struct StepperSums {
  std::vector<double> order, coupling, kinetic, momentum, momentum_scale;
};

class EnsembleStepper {
 public:
  virtual ~EnsembleStepper() = default;
  /// Replaces the state, then evaluates the force there (one evaluation).
  virtual void set_state(const RotorState& state) = 0;
  /// The current state (a device copies it to the host first).
  virtual const RotorState& state() = 0;
  /// `steps` steps of `method` with step h and coupling K[b] for replica b. With `order` not
  /// null, each step's sum_n |y_n| per replica (of the force at the step's end) is appended to
  /// it: steps x replicas values.
  virtual void advance(const Integrator& method, double h, const std::vector<double>& K,
                       std::int64_t steps, std::vector<double>* order) = 0;
  /// The sums of a record at the current state.
  virtual StepperSums sums() = 0;
  /// y_n at the current state, rows x replicas x [Re, Im] (CouplingForce::local_fields).
  virtual const std::vector<double>& local_fields() = 0;
  /// Force evaluations so far (set_state and every step's).
  virtual long long evaluations() const = 0;
  /// Where the steps run, in one line ("cpu", or the device's name).
  virtual std::string device() const = 0;
};

}  // namespace hmfnet
