#pragma once
// The CPU's stepper (ensemble_stepper.hpp): the state in host memory, an Integrator's step and a
// CouplingForce on this rank's rows, the record's sums in OrderedColumnSums' order. Collective
// when the network is distributed (every force evaluation is).
#include <string>
#include <vector>

#include "dynamics/coupling_force.hpp"
#include "dynamics/ensemble_stepper.hpp"
#include "dynamics/integrator.hpp"

namespace hmfnet {

class HostStepper : public EnsembleStepper {
 public:
  explicit HostStepper(CouplingForce& force) : m_force(force), m_f(force) {}
  void set_state(const RotorState& state) override;
  const RotorState& state() override { return m_state; }
  void advance(const Integrator& method, double h, const std::vector<double>& K, std::int64_t steps,
               std::vector<double>* order) override;
  StepperSums sums() override;
  const std::vector<double>& local_fields() override { return m_force.local_fields(); }
  long long evaluations() const override { return m_f.count(); }
  std::string device() const override { return "cpu"; }

 private:
  CouplingForce& m_force;
  ForceEvaluation m_f;  // the force at m_state's phases
  RotorState m_state;
  std::vector<double> m_kinetic_terms, m_abs_p;  // a record's p^2 / 2 and |p|, reused
};

}  // namespace hmfnet
