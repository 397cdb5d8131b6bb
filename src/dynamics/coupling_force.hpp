#pragma once
// The coupling force of eq:dMomentum_dT per unit K, and the sums the observables need, from one
// evaluation. With y_n = sum_m A_nm e^{i theta_m} (so R_n = |y_n| / N, eq:localOrderParam):
//   g_n = (1/N) sum_m A_nm sin(theta_m - theta_n) = (cos theta_n Im y_n - sin theta_n Re y_n) / N,
//   p'_n = K g_n,
//   sum_n |y_n|                      -> R = sum_n |y_n| / sum_n d_n       (eq:globalOrderParam)
//   sum_n Re(e^{-i theta_n} y_n)     -> U = -(K / 2N) * that               (potential energy)
// The sums are over this rank's rows and summed in an order that does not depend on the thread
// count; the caller reduces them over ranks.
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/kick_drift_lanes.hpp"
#include "dynamics/rotor_state.hpp"
#include "dynamics/thread_choice.hpp"

namespace hmfnet {

struct ForceSums {
  std::vector<double> order;     ///< per replica: sum_n |y_n|
  std::vector<double> coupling;  ///< per replica: sum_n Re(e^{-i theta_n} y_n)
};

/// What an evaluation forms besides g. The sums are read only where a record is taken (at the
/// end of a segment of steps, or after each step of a sampled one), so the other evaluations (a
/// splitting's inner ones, the steps between records) skip them: the rank-one force then skips
/// |y_n| (a square root a cell) and both ordered sums, the sparse force its rows' terms (a square
/// root a row and replica) and the ordered pass over them. g and the local fields y_n are the same
/// either way, bit for bit (tests/dynamics/test_force_outputs.cpp).
/// start_sums_and_force is for kick_drift_evaluate() only: the sums at the phases the pass
/// starts from (the last evaluation's, which was force_only), formed as its kick forms the force
/// there again, then the force alone at the new phases. A sampled step's sums then cost no pass
/// of their own (Integrator::steps: each step's sums come with the next step's first pass).
enum class ForceOutputs { force_and_sums, force_only, start_sums_and_force };

class CouplingForce {
 public:
  virtual ~CouplingForce() = default;
  /// Sizes g, the sums and this force's own buffers for `state`, outside a step's team
  /// (team.hpp); throws ParameterError for a state it cannot take. evaluate() calls it itself
  /// when it runs outside a team.
  virtual void prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) = 0;
  /// g (rows x replicas, row-major) at the phases of `state`, and the local sums unless
  /// `outputs` is force_only (then `sums` keeps its values). Called by every thread of a step's
  /// team (after prepare) or outside one; collective when the network is distributed. The sums
  /// are complete on the master thread on return, on the others after the next barrier.
  void evaluate(const RotorState& state, std::vector<double>& g, ForceSums& sums,
                ForceOutputs outputs = ForceOutputs::force_and_sums) {
    compute(state, g, sums, outputs);
  }
  /// Whether kick_drift_evaluate() can take `state`: a force that applies the kick-drift pass
  /// and evaluates at the new phases in one pass over the cells (the rank-one force, in whole
  /// groups of replicas, where its last evaluation was at `state`'s phases). Called by every
  /// thread of a team alike; the same answer for every call of one Integrator::steps().
  virtual bool fuses_kick_drift(const RotorState& /*state*/) const { return false; }
  /// The pass `c` (kick_drift_lanes.hpp: p += c_i K_b g, theta += c.drift p) with the force of
  /// the last evaluation, formed again from the force's own data, then evaluate() at the new
  /// phases, in one pass; where fuses_kick_drift(state). The bits of the pass over g, then
  /// evaluate(). After a force_only call g is not formed: it still holds an earlier evaluation's
  /// force (ForceEvaluation::kick_drift_update).
  void kick_drift_evaluate(RotorState& state, const std::vector<double>& K,
                           const KickDriftCoefficients& c, std::vector<double>& g, ForceSums& sums,
                           ForceOutputs outputs) {
    compute_kick_drift(state, K, c, g, sums, outputs);
  }
  /// g and the sums at the phases of the last evaluation, which was at `state` and force_only:
  /// the bits of that evaluation with force_and_sums. By every thread of a team, or outside one.
  /// This default evaluates again; a force that keeps what it needs forms them from that.
  void form_sums(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
    compute_sums(state, g, sums);
  }
  /// Stored entries of A this rank reads per evaluation (for throughput figures).
  virtual EdgeOffset work_per_evaluation() const = 0;
  /// Stored entries gathered per evaluation, for the default thread count (thread_choice.hpp):
  /// those read, unless the force reads none (the rank-one force).
  virtual EdgeOffset gathers_per_evaluation() const { return work_per_evaluation(); }
  /// What one lane's gather costs against one replica's, with `lanes` replica lanes in a pass,
  /// for the default thread count (thread_choice.hpp: wide_lane_gather_cost).
  virtual double lane_gather_cost(int /*lanes*/) const { return 1.0; }
  /// The work of one row and replica besides its gathers, in the thread rule's units
  /// (thread_choice.hpp: k_row_work for a sparse row, k_rank_one_row_work for the rank-one force).
  virtual std::int64_t row_work() const { return k_row_work; }
  /// Column segment counts the evaluations could run in, the same bits in each, where the force's
  /// own rule cannot tell which runs faster on this machine (NetworkForce: trial_segment_width),
  /// the rule's first; empty where there is nothing to try. For the shape of the last prepare and
  /// the team size then. A run times its first steps in each (step_trial.hpp).
  virtual std::vector<int> segment_candidates() const { return {}; }
  /// The evaluations from the next prepare on run in `count` segments, one of
  /// segment_candidates(), or 1: the rule's own choice again (whatever its count).
  virtual void use_segments(int /*count*/) {}
  /// Short name for logs and output files ("sparse", "rank-one").
  virtual const char* name() const = 0;
  /// y_n = sum_m A_nm e^{i theta_m} of the last evaluation, rows x replicas x [Re, Im]
  /// (R_n = |y_n| / N, psi_n = arg y_n: eq:localOrderParam).
  virtual const std::vector<double>& local_fields() const = 0;

 private:
  /// evaluate(), by each force.
  virtual void compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
                       ForceOutputs outputs) = 0;
  /// form_sums(), by each force.
  virtual void compute_sums(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
    compute(state, g, sums, ForceOutputs::force_and_sums);
  }
  /// kick_drift_evaluate(), by a force that fuses them.
  virtual void compute_kick_drift(RotorState& /*state*/, const std::vector<double>& /*K*/,
                                  const KickDriftCoefficients& /*c*/, std::vector<double>& /*g*/,
                                  ForceSums& /*sums*/, ForceOutputs /*outputs*/) {
    throw std::logic_error(std::string(name()) + ": no fused kick-drift pass");
  }
};

}  // namespace hmfnet
