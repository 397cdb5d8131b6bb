#pragma once
// Per-node time averages over [T1, T2] of replica 0, for the figures that test the paper's
// assumptions about the synchronised state (Sec. synchronizedState).
//
// The rotating frame. eq:rnDef writes the common rotation as Omega t + phi. Taking Omega = P/N
// (the conserved mean momentum) is exact only for an infinite network: on N rotors the locked
// cluster turns at P/N + O(sigma / sqrt(N)) (the drifting rotors carry the rest of P), and over a
// window of 400 time units an offset of 0.02 turns the frame by 8 rad and averages every
// frame-dependent mean to ~0. So the frame is measured, not assumed: its phase at each sample is
// Psi(t) = arg sum_n y_n, the phase of the global order parameter, which is Omega t + phi of
// eq:rnDef up to its own O(N^-1/2) fluctuation; Omega is reported as the mean rate of the
// unwrapped Psi, beside P/N.
//  - r_n e^{i phi} = <R_n e^{i(psi_n - Psi)}>_t (eq:rnDef; phi = arg sum_n r_n e^{i phi} = 0 in
//    this frame, kept as a check);
//  - the fluctuation term of eq:timeAveragedHV2: Re<z_n e^{-i theta_bar_n}>_t against the
//    synchronised term <r_n cos theta_bar_n>_t (Fig. Assumptions1(b)), from the online sums
//      A_n = <(y_n / N) e^{-i theta_n}>, B_n = <e^{-i(theta_n - Psi)}>, C_n = r_n e^{i phi}:
//      <z_n e^{-i theta_bar_n}> = A_n - C_n B_n,  <e^{-i theta_bar_n}> = e^{i phi} B_n
//    (theta_bar_n = theta_n - Psi - phi, eq:thetaPBar);
//  - Omega_n of Fig. Assumptions1(a): the mean rate of the unwrapped local phase psi_n (the
//    frequency of the local order parameter, which Assumption 1 says is common);
//  - a histogram of psi_n - psi_1 over all n, sampled once per time unit (Fig.
//    histPsinMinusPsi1; psi_1 is node 0 here);
//  - samples of one rotor's (theta_bar, p_bar = p - P/N) every record (Fig. ergodicityAssumption).
// All state is additive over ranks or per row, so checkpoints gather and restore it exactly.
#include <cstdint>
#include <vector>

#include "dynamics/rotor_state.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct NodeStatisticsResult {
  std::vector<double> r;                ///< r_n, N
  double phi = 0.0;                     ///< global phase of eq:rnDef (0 in the measured frame)
  double omega = 0.0;                   ///< measured frame frequency: mean rate of Psi(t)
  double omega_momentum = 0.0;          ///< P/N
  std::vector<double> psi_frequency;    ///< mean rate of the unwrapped psi_n, N
  std::vector<double> fluctuation;      ///< Re<z_n e^{-i theta_bar_n}>_t, N
  std::vector<double> synchronised;     ///< <r_n cos theta_bar_n>_t, N
  std::vector<double> phase_histogram;  ///< counts of psi_n - psi_1 in bins over [-pi, pi)
  std::vector<double> rotor_theta_bar, rotor_p_bar;  ///< samples of the chosen rotor
};

class NodeStatistics {
 public:
  NodeStatistics() = default;
  /// `rows`: this rank's rows; `rotor`: global index of the sampled rotor; `rotor_samples`:
  /// how many record steps fall in [T1, T2]; `bins`: histogram bins.
  NodeStatistics(NodeIndex first_row, NodeIndex rows, NodeIndex rotor, std::int64_t rotor_samples,
                 int bins, double omega);

  /// One sample at time t since the start of the segment (collective: the global field is summed
  /// over ranks). `y`: local fields (rows x replicas x 2, replica 0 used), `n`: N.
  void add(const RotorState& state, const std::vector<double>& y, double t, double n);
  /// Phase histogram sample (collective: psi_1 travels from its owner).
  void add_phase_sample(const std::vector<double>& y, int replicas);
  /// Rotor sample (theta - Psi, p - P/N) of the chosen rotor, if owned here; Psi of the last add().
  void add_rotor_sample(const RotorState& state, double t);

  /// Collective: the whole-network result on every rank.
  NodeStatisticsResult finish(const DistributedNetwork& network) const;

  // Checkpoint state: per-row sums (rows x k_row_width) and globals: the first k_shared_globals
  // are equal on every rank, the rest are additive over ranks.
  static constexpr int k_row_width = 8;
  static constexpr std::size_t k_shared_globals = 7;
  std::vector<double> row_state() const { return m_rows_sums; }
  std::vector<double> global_state() const;
  void restore(std::vector<double> row_state, const std::vector<double>& global_state,
               bool owner_of_globals);

 private:
  NodeIndex m_first_row = 0;
  NodeIndex m_rows = 0;
  NodeIndex m_rotor = 0;
  double m_omega = 0.0;
  std::int64_t m_count = 0;
  // rows x [A re, A im, B re, B im, C re, C im, unwrapped psi_n increments, last psi_n]
  std::vector<double> m_rows_sums;
  double m_frame_turned = 0.0;  // unwrapped increments of Psi since the first sample
  double m_frame_last = 0.0;    // Psi at the last sample
  double m_t_first = 0.0, m_t_last = 0.0;
  std::vector<double> m_histogram;               // local counts
  std::vector<double> m_rotor_theta, m_rotor_p;  // preallocated, filled by the owner
  std::int64_t m_rotor_count = 0;
};

}  // namespace hmfnet
