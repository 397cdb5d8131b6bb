#pragma once
// O(N) coupling force for rank-one networks A = a a^T (the disordered HMF of Restrepo & Meiss
// 2014; a = 1 is the all-to-all HMF of Antoni & Ruffo 1995), optionally without the diagonal
// (the complete graph without self-loops, A = a a^T - diag(a^2)). Then
//   y_n = sum_m A_nm e^{i theta_m} = a_n Z - [no diagonal] a_n^2 e^{i theta_n},
//   Z = sum_m a_m e^{i theta_m}  (one global sum, reduced over ranks),
// and g, |y_n| and the coupling term follow as in the sparse kernel. Chosen automatically when
// detect_rank_one finds the structure, and checked against the sparse path in tests. Two passes
// over the rows after the sin/cos, each summing as it goes (Z; then g with the order and
// coupling sums), the same bits as storing the terms and summing them (tests/dynamics/
// test_rank_one_force.cpp). Inside a splitting's steps, whole groups of 8 replicas take the
// kick, the drift, the sin/cos and Z in one pass instead, where the groups share out over the
// threads (kick_drift_evaluate, fuses_kick_drift; rank_one_fused.hpp), the field pass following
// only where the sums are read and no later pass forms them (ForceOutputs::start_sums_and_force:
// a sampled step's sums come with the next step's kick).
#include <optional>
#include <vector>

#include "dynamics/coupling_force.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/rank_one_fused.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/complete_graph.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct RankOneStructure {
  std::vector<double> a;  ///< the whole vector (every rank)
  bool diagonal = true;   ///< A_nn = a_n^2 stored; false: no self-loops
};

/// The rank-one structure of `network`, if it has one: every row full (N entries with the
/// diagonal, N-1 without), and every stored A_nm = a_n a_m to 1e-12 relative. Weighted networks
/// without a diagonal are not recognised (a is then not determined by the diagonal), nor are
/// networks with N < 3. Collective; O(1) unless nnz = N (N - 1) or N^2, then O(nnz / ranks).
std::optional<RankOneStructure> detect_rank_one(const DistributedNetwork& network);

/// K_N's structure, known without looking at rows (it has none): a = 1, the diagonal present
/// exactly when the graph has self-loops.
RankOneStructure complete_graph_structure(const CompleteGraph& graph);

class RankOneForce : public CouplingForce {
 public:
  RankOneForce(RankOneStructure structure, NodeIndex first_row, NodeIndex rows);
  void prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) override;
  EdgeOffset work_per_evaluation() const override { return m_rows; }
  EdgeOffset gathers_per_evaluation() const override { return 0; }  // rows only: thread_choice
  std::int64_t row_work() const override { return k_rank_one_row_work; }
  const char* name() const override { return "rank-one"; }
  /// Whole groups of k_fused_group replicas (rank_one_fused.hpp: a tail would pad a vector of
  /// sin/cos per cell), with the work items (blocks of the ordered sums x groups) shared evenly
  /// enough over the team (the separate passes share the sin/cos and the kick-drift cell by
  /// cell), and the last evaluation at `state`'s phases. Called by every thread of the team.
  bool fuses_kick_drift(const RotorState& state) const override;
  const RankOneStructure& structure() const { return m_structure; }
  /// Formed from the last evaluation on first call after it (outside a team: not thread-safe).
  const std::vector<double>& local_fields() const override;

 private:
  void compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
               ForceOutputs outputs) override;
  /// One pass over the cells (rank_one_fused_groups, a thread's items of a block in one call): the
  /// field at the last evaluation's [cos, sin] and Z, the kicks and the drift, the new sin/cos and
  /// Z; then, with the sums, the field pass.
  void compute_kick_drift(RotorState& state, const std::vector<double>& K,
                          const KickDriftCoefficients& c, std::vector<double>& g, ForceSums& sums,
                          ForceOutputs outputs) override;
  /// g and the sums at the last evaluation's phases: the field pass alone where they are
  /// `state`'s (a fused force_only pass), else an evaluation.
  void compute_sums(const RotorState& state, std::vector<double>& g, ForceSums& sums) override;
  /// The blocks' sums (m_sums) added in order into `sums`, w replicas. Master thread.
  void collect_sums(std::size_t w, ForceSums& sums);
  /// The sin/cos, Z and field passes, with (Sums) the order and coupling sums.
  template <bool Sums>
  void evaluate_passes(const RotorState& state, std::vector<double>& g, ForceSums& sums);
  /// Z from the blocks' partial sums, over ranks, as the phases of `state`'s, whose g this
  /// evaluation forms into `g_formed` (nullptr: it does not); a barrier after it.
  void reduce_z(const RotorState& state, const double* g_formed);
  /// g at the current [cos, sin] and Z, with (Sums) the order and coupling sums.
  template <bool Sums>
  void field_pass(const RotorState& state, std::vector<double>& g, ForceSums& sums);
  RankOneStructure m_structure;
  NodeIndex m_first_row;
  NodeIndex m_rows;
  double m_inverse_n;
  bool m_unit_a;  // every a_n of this rank's rows is 1 (rank_one_fused.hpp: RankOneFusedCells)
  std::vector<double> m_cs;                   // rows x replicas x [cos, sin]: once per evaluation
  std::vector<double> m_z;                    // replicas x [Re Z, Im Z]
  const double* m_evaluated_theta = nullptr;  // the phases m_cs and m_z belong to
  const double* m_formed_g = nullptr;         // where their g was formed, if it was
  OrderedColumnSums m_z_sums;
  mutable std::vector<double> m_y;  // rows x replicas x [Re y, Im y], formed on demand
  mutable bool m_y_current = false;
  std::vector<double> m_term_sums;  // replicas x [sum |y_n|, sum Re(e^{-i theta_n} y_n)]
  OrderedColumnSums m_sums;
};

}  // namespace hmfnet
