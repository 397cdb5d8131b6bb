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
// test_rank_one_force.cpp).
#include <optional>
#include <vector>

#include "dynamics/coupling_force.hpp"
#include "dynamics/ordered_sum.hpp"
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
  const RankOneStructure& structure() const { return m_structure; }
  /// Formed from the last evaluation on first call after it (outside a team: not thread-safe).
  const std::vector<double>& local_fields() const override;

 private:
  void compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
               ForceOutputs outputs) override;
  /// The sin/cos, Z and field passes, with (Sums) the order and coupling sums.
  template <bool Sums>
  void evaluate_passes(const RotorState& state, std::vector<double>& g, ForceSums& sums);
  RankOneStructure m_structure;
  NodeIndex m_first_row;
  NodeIndex m_rows;
  double m_inverse_n;
  std::vector<double> m_cs;  // rows x replicas x [cos, sin]: once per evaluation
  std::vector<double> m_z;   // replicas x [Re Z, Im Z]
  OrderedColumnSums m_z_sums;
  mutable std::vector<double> m_y;  // rows x replicas x [Re y, Im y], formed on demand
  mutable bool m_y_current = false;
  std::vector<double> m_term_sums;  // replicas x [sum |y_n|, sum Re(e^{-i theta_n} y_n)]
  OrderedColumnSums m_sums;
};

}  // namespace hmfnet
