#pragma once
// What a run returns, declared once: the results of each K of the schedule (PointResult) and the
// records of the time series (TimeSeries), each with one list of its fields. The lists are walked
// by every place that must see all of a result: the results file's writer and reader and the
// checkpoint's checksum (run_file.cpp, checkpoint.cpp), the split of a run across replicas back
// into one point per K (replica_lanes.cpp) and the Python module's arrays. Adding a result is one
// member here and one line in its list; tests/dynamics/test_point_result.cpp fails when a member
// is missing from a list or a consumer loses a listed field.
//
// The lists take one or more objects of the same type (`visit_point_fields(v, a, b)` calls
// `v.per_replica("R_mean", a.R_mean, b.R_mean)`), so a consumer that maps one result onto another
// (the replica split) walks both at once. The field kinds a visitor sees:
//   scalar(name, double&...)               one value per K
//   text(name, std::string&...)            one string per K
//   per_replica(name, vector<double>&...)  one value per replica
//   per_node_replica(name, ...)            N x replicas, row-major (node data only)
//   node_vector(name, ...)                 replica 0's node data: the same length at every K
//   per_record(name, ...)                  one value per record
//   per_record_replica(name, ...)          records x replicas, row-major
// The order of each list is the order of the results file's datasets and of the checksum's bytes.
#include <string>
#include <vector>

namespace hmfnet {

struct PointResult {
  double K = 0.0;
  std::string integrator;                    ///< the method of this K's segment (step_at)
  double h = 0.0;                            ///< the step of this K's segment
  std::vector<double> R_mean, R_sem;         ///< per replica
  std::vector<double> energy_rel_error_max;  ///< per replica, over the whole segment
  std::vector<double> momentum_drift;        ///< per replica: max |P(t) - P(0)| / sum |p_n(0)|
  std::vector<double> R_node;                ///< N x replicas: <R_n>_t (node_data)
  std::vector<double> omega_node;            ///< N x replicas: Omega_n (node_data)
  // node_data, replica 0 (see node_statistics.hpp):
  std::vector<double> r_node;                        ///< r_n of eq:rnDef, N
  std::vector<double> fluctuation;                   ///< Re<z_n e^{-i theta_bar_n}>_t, N
  std::vector<double> synchronised;                  ///< <r_n cos theta_bar_n>_t, N
  std::vector<double> phase_histogram;               ///< psi_n - psi_1 counts over [-pi, pi)
  std::vector<double> rotor_theta_bar, rotor_p_bar;  ///< samples of the chosen rotor
  std::vector<double> psi_frequency;                 ///< N: mean rate of the unwrapped psi_n
  std::vector<double> frame;  ///< {measured frame frequency Omega, phi, P/N} (node_statistics.hpp)
};

struct TimeSeries {
  std::vector<double> t, K;                 ///< per record (t: time since the run started)
  std::vector<double> R, energy, momentum;  ///< records x replicas
};

/// The one list of a PointResult's fields (kinds in the header comment).
template <class Visitor, class... Point>
void visit_point_fields(Visitor& v, Point&... p) {
  v.scalar("K", p.K...);
  v.scalar("h", p.h...);
  v.text("integrator", p.integrator...);
  v.per_replica("R_mean", p.R_mean...);
  v.per_replica("R_sem", p.R_sem...);
  v.per_replica("energy_rel_error_max", p.energy_rel_error_max...);
  v.per_replica("momentum_drift", p.momentum_drift...);
  v.per_node_replica("R_node", p.R_node...);
  v.per_node_replica("omega_node", p.omega_node...);
  v.node_vector("r_node", p.r_node...);
  v.node_vector("fluctuation", p.fluctuation...);
  v.node_vector("synchronised", p.synchronised...);
  v.node_vector("phase_histogram", p.phase_histogram...);
  v.node_vector("rotor_theta_bar", p.rotor_theta_bar...);
  v.node_vector("rotor_p_bar", p.rotor_p_bar...);
  v.node_vector("psi_frequency", p.psi_frequency...);
  v.node_vector("frame", p.frame...);
}

/// The one list of a TimeSeries' fields.
template <class Visitor, class... Series>
void visit_series_fields(Visitor& v, Series&... s) {
  v.per_record("t", s.t...);
  v.per_record("K", s.K...);
  v.per_record_replica("R", s.R...);
  v.per_record_replica("energy", s.energy...);
  v.per_record_replica("momentum", s.momentum...);
}

}  // namespace hmfnet
