#pragma once
// Time steppers for H = sum_n p_n^2/2 + K V(theta) (eq:hamiltonianNetworkCase), behind one
// interface (MFEM's ODE-solver family style). The force is evaluated by a CouplingForce and
// cached between steps: a splitting that ends with a kick at the new phases leaves the force
// there for the next step (first-same-as-last), so leap-frog costs one evaluation per step;
// over several steps (steps()) that closing kick also shares the next step's first pass over the
// cells.
//
// The family, with force evaluations per step (what a work-precision chart charges):
//   leapfrog     order 2, symplectic, 1 evaluation
//   yoshida4     order 4, symplectic, 3 evaluations (Yoshida 1990 triple jump)
//   blanes_moan  order 4, symplectic, 6 evaluations (Blanes & Moan 2002, SRKN_6^b)
//   rk4          order 4, not symplectic, 4 evaluations (the contrast: secular energy drift)
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/coupling_force.hpp"
#include "dynamics/team.hpp"

namespace hmfnet {

/// The force at the current phases, with the sums the observables need.
class ForceEvaluation {
 public:
  explicit ForceEvaluation(CouplingForce& force) : m_force(&force) {}
  /// Sizes the buffers for `state`: outside a step's team, before it opens (team.hpp).
  void prepare(const RotorState& state) { m_force->prepare(state, m_g, m_sums); }
  /// The force at `state`, by every thread of a step's team or outside one; the sums too unless
  /// `outputs` is force_only (coupling_force.hpp: for an evaluation no record reads).
  void update(const RotorState& state, ForceOutputs outputs = ForceOutputs::force_and_sums) {
    if (outside_team()) prepare(state);
    m_force->evaluate(state, m_g, m_sums, outputs);
#pragma omp master
    {
      ++m_count;
      m_sums_current = outputs == ForceOutputs::force_and_sums;
    }
  }
  /// The kick-drift pass `c` over the cells with g(), then update() at the new phases; where the
  /// force fuses them (CouplingForce::fuses_kick_drift: its last evaluation was at `state`'s
  /// phases), one pass that forms g() again from the force's own data, the same bits. After a
  /// fused force_only call g() is not the new force: the next call forms it again, and a
  /// force_and_sums call forms it (a splitting's last step always does).
  /// With start_sums_and_force, sums() are then those at the phases the pass started from.
  void kick_drift_update(RotorState& state, const std::vector<double>& K,
                         const KickDriftCoefficients& c, ForceOutputs outputs);
  /// g() and sums() at `state`'s phases, where the last update was there and force_only (the
  /// bits of that update with force_and_sums; CouplingForce::form_sums). Every thread of a team.
  void form_sums(const RotorState& state) {
    m_force->form_sums(state, m_g, m_sums);
#pragma omp master
    m_sums_current = true;
  }
  const std::vector<double>& g() const { return m_g; }
  /// The sums of the last update; valid where sums_current() (an integrator forms them at a
  /// step's last evaluation when after_step reads them, and at the last step's always).
  const ForceSums& sums() const { return m_sums; }
  bool sums_current() const { return m_sums_current; }
  long long count() const { return m_count; }
  CouplingForce& force() { return *m_force; }

 private:
  CouplingForce* m_force;
  std::vector<double> m_g;
  ForceSums m_sums;
  long long m_count = 0;
  bool m_sums_current = false;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances `state` by h with coupling K[b] for replica b. On entry `f` holds the force at the
  /// current phases; on exit at the new ones. One parallel region for the whole step
  /// (team.hpp): the buffers are sized first, then every thread runs advance().
  void step(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f) const;
  /// `n` steps, with the bits of `n` calls of step(), in one parallel region. after_step (may be
  /// empty) runs on the master thread after each step's last force evaluation and may read
  /// f.sums() (that step's) and nothing of `state`: a splitting applies a step's closing kick in
  /// one pass with the next step's opening kick and drift, so the momenta are complete only when
  /// steps() returns. After a failed exchange in the team (on_master, team.hpp) the remaining
  /// steps run on without it and in_team rethrows at the end: their results are never used.
  void steps(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f,
             std::int64_t n, const std::function<void()>& after_step) const;
  /// Global order p: the state error after a fixed time is O(h^p).
  virtual int order() const = 0;
  virtual std::string name() const = 0;
  /// Calls of f.update() per step (the cost unit of work-precision comparisons).
  virtual int evaluations_per_step() const = 0;
  /// Linear stability bound c: on a harmonic oscillator of frequency omega the step is stable
  /// for h omega < c (and the blow-up guard quotes it with omega_max = sqrt(K max_n R_n)).
  virtual double stability_limit() const = 0;

 private:
  /// Sizes this method's scratch for `state`, before the team opens (none by default).
  virtual void prepare(const RotorState& state) const { static_cast<void>(state); }
  /// The step, run by every thread of the step's team (or by the caller alone).
  virtual void advance(RotorState& state, double h, const std::vector<double>& K,
                       ForceEvaluation& f) const = 0;
  /// steps() inside the team: advance() n times by default.
  virtual void advance_steps(RotorState& state, double h, const std::vector<double>& K,
                             ForceEvaluation& f, std::int64_t n,
                             const std::function<void()>& after_step) const;
};

/// Kick-drift-kick leap-frog (Stormer-Verlet): second order, symplectic, time-reversible; the
/// paper's integrator (Sec. numericalExperiments, h = 0.01).
class LeapFrog : public Integrator {
 public:
  int order() const override { return 2; }
  std::string name() const override { return "leapfrog"; }
  int evaluations_per_step() const override { return 1; }
  /// |trace| of the one-step map [[1 - x^2/2, x], [-x (1 - x^2/4), 1 - x^2/2]] < 2 for x < 2.
  double stability_limit() const override { return 2.0; }

 private:
  void advance(RotorState& state, double h, const std::vector<double>& K,
               ForceEvaluation& f) const override;
  void advance_steps(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f,
                     std::int64_t n, const std::function<void()>& after_step) const override;
};

/// A kick-drift-...-kick splitting
///   e^{b_0 h B} e^{a_0 h A} e^{b_1 h B} ... e^{a_{s-1} h A} e^{b_s h B},
/// B the kick p += c K g(theta), A the drift theta += c p. Each composition of leap-frog
/// (Yoshida) and each BAB partitioned method (Blanes & Moan) is of this form. The last kick of
/// a step uses the force at the new phases, which stays cached for the first kick of the next
/// (first-same-as-last), so a step costs s evaluations. Symmetric coefficients
/// (a_i = a_{s-1-i}, b_i = b_{s-i}) make the map time-reversible; every such map is symplectic
/// and conserves total momentum (each kick adds antisymmetric pair forces).
class KickDriftSplitting : public Integrator {
 public:
  /// `kicks` has one more entry than `drifts`; sum(kicks) = sum(drifts) = 1 for consistency.
  /// Throws ParameterError otherwise.
  KickDriftSplitting(std::string name, int order, std::vector<double> kicks,
                     std::vector<double> drifts);
  int order() const override { return m_order; }
  std::string name() const override { return m_name; }
  int evaluations_per_step() const override { return static_cast<int>(m_drifts.size()); }
  /// The first h omega where |trace| of the one-step map of q'' = -omega^2 q reaches 2,
  /// computed from the coefficients (splitting_stability_limit).
  double stability_limit() const override { return m_stability_limit; }

 private:
  void advance(RotorState& state, double h, const std::vector<double>& K,
               ForceEvaluation& f) const override;
  void advance_steps(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f,
                     std::int64_t n, const std::function<void()>& after_step) const override;
  std::string m_name;
  int m_order;
  std::vector<double> m_kicks;
  std::vector<double> m_drifts;
  double m_stability_limit;
};

/// The linear stability bound of a kick-drift splitting: the smallest x = h omega > 0 at which the
/// one-step map of the harmonic oscillator (a product of kick [[1, 0], [-b x, 1]] and drift
/// [[1, a x], [0, 1]] matrices, determinant 1) stops being stable, |trace| >= 2. Scanned on a grid
/// of 1e-3 up to x = 8, then bisected to 1e-12; 8 if stable on the whole scan.
double splitting_stability_limit(const std::vector<double>& kicks,
                                 const std::vector<double>& drifts);

/// Yoshida's fourth-order triple jump (H. Yoshida, Phys. Lett. A 150, 262 (1990); E. Forest &
/// R. D. Ruth, Physica D 43, 105 (1990)): leap-frog substeps of w1 h, w0 h, w1 h with
/// w1 = 1 / (2 - 2^(1/3)), w0 = -2^(1/3) / (2 - 2^(1/3)), merged kicks: 3 evaluations.
KickDriftSplitting yoshida4();

/// Blanes & Moan, J. Comput. Appl. Math. 142, 313 (2002), Table 3, SRKN_6^b: the optimised
/// fourth-order Runge-Kutta-Nystrom splitting for H = p^2/2 + V(q), 7 kicks and 6 drifts
/// (6 evaluations). Chosen over the same paper's PRK S_6 (Table 2) because our H has the RKN
/// form: on the test network of test_integrator_family.cpp its state error is 11 times below
/// S_6's at the same step and cost, and ~300 times below Yoshida's at equal work.
KickDriftSplitting blanes_moan4();

/// Classical fourth-order Runge-Kutta on (theta' = p, p' = K g(theta)): not symplectic, so the
/// energy drifts secularly (Hairer, Lubich & Wanner, Geometric Numerical Integration, Ch. IX).
/// Stage 1 reuses the cached force; stages 2-4 need the force at intermediate phases (3
/// evaluations); the new phases are not a stage, so one more evaluation leaves `f` at the new
/// state: 4 evaluations per step. Holds scratch arrays (hence `mutable`): one instance must not
/// step two states concurrently.
class RungeKutta4 : public Integrator {
 public:
  int order() const override { return 4; }
  std::string name() const override { return "rk4"; }
  int evaluations_per_step() const override { return 4; }
  /// |R(i x)| <= 1 for the RK4 stability polynomial R on the imaginary axis iff x <= 2 sqrt 2.
  double stability_limit() const override { return 2.0 * std::sqrt(2.0); }

 private:
  void advance(RotorState& state, double h, const std::vector<double>& K,
               ForceEvaluation& f) const override;
  void advance_steps(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f,
                     std::int64_t n, const std::function<void()>& after_step) const override;
  /// One step whose closing evaluation forms `last` (coupling_force.hpp: ForceOutputs).
  void advance_one(RotorState& state, double h, const std::vector<double>& K, ForceEvaluation& f,
                   ForceOutputs last) const;
  void prepare(const RotorState& state) const override;
  mutable RotorState m_stage;
  mutable std::vector<double> m_theta_rate;  // p1 + 2 p2 + 2 p3 + p4
  mutable std::vector<double> m_force_sum;   // g1 + 2 g2 + 2 g3 + g4
};

/// The names make_integrator accepts, comma separated (for messages and --help).
std::string integrator_names();
/// By name: "leapfrog", "yoshida4", "blanes_moan", "rk4". Throws ParameterError naming the
/// known integrators otherwise.
std::unique_ptr<Integrator> make_integrator(const std::string& name);

// The loops of a step, shared out over the step's team (team.hpp) or run by the caller alone.
/// p += c K g (the kick), over all rows and replicas.
void kick(RotorState& state, double c, const std::vector<double>& K, const std::vector<double>& g);
/// A kick by c_kick (p += c_kick K g) then a drift by c_drift (theta += c_drift p), fused per
/// rotor: one pass and one barrier instead of two.
void kick_drift(RotorState& state, double c_kick, const std::vector<double>& K,
                const std::vector<double>& g, double c_drift);

}  // namespace hmfnet
