#pragma once
// Time steppers for H = sum_n p_n^2/2 + K V(theta) (eq:hamiltonianNetworkCase), behind one
// interface (MFEM's ODE-solver family style). The force is evaluated by a CouplingForce and
// cached between steps: a splitting that ends with a kick at the new phases leaves the force
// there for the next step (first-same-as-last), so leap-frog costs one evaluation per step.
#include <memory>
#include <string>
#include <vector>

#include "dynamics/coupling_force.hpp"

namespace hmfnet {

/// The force at the current phases, with the sums the observables need.
class ForceEvaluation {
 public:
  explicit ForceEvaluation(CouplingForce& force) : m_force(&force) {}
  void update(const RotorState& state) {
    m_force->evaluate(state, m_g, m_sums);
    ++m_count;
  }
  const std::vector<double>& g() const { return m_g; }
  const ForceSums& sums() const { return m_sums; }
  long long count() const { return m_count; }
  CouplingForce& force() { return *m_force; }

 private:
  CouplingForce* m_force;
  std::vector<double> m_g;
  ForceSums m_sums;
  long long m_count = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances `state` by h with coupling K[b] for replica b. On entry `f` holds the force at the
  /// current phases; on exit at the new ones.
  virtual void step(RotorState& state, double h, const std::vector<double>& K,
                    ForceEvaluation& f) const = 0;
  virtual int order() const = 0;
  virtual std::string name() const = 0;
};

/// Kick-drift-kick leap-frog (Stormer-Verlet): second order, symplectic, time-reversible; the
/// paper's integrator (Sec. numericalExperiments, h = 0.01).
class LeapFrog : public Integrator {
 public:
  void step(RotorState& state, double h, const std::vector<double>& K,
            ForceEvaluation& f) const override;
  int order() const override { return 2; }
  std::string name() const override { return "leapfrog"; }
};

/// By name: "leapfrog". Throws ParameterError naming the known integrators otherwise.
std::unique_ptr<Integrator> make_integrator(const std::string& name);

/// p += c K g (the kick), over all rows and replicas.
void kick(RotorState& state, double c, const std::vector<double>& K, const std::vector<double>& g);
/// theta += c p (the drift).
void drift(RotorState& state, double c);

}  // namespace hmfnet
