#pragma once
// What `simulate` is asked to do: the CLI's options and Python's keyword arguments are both
// turned into this one typed request, checked by one function (validate) and run by one service
// (simulate_service.hpp). Defaults are the CLI's. Plain data: the CLI grammar binds to it
// without the library behind it (the fuzz build).
#include <cstdint>
#include <string>
#include <vector>

namespace hmfnet {
struct SimulationParameters;  // dynamics/simulation_parameters.hpp
}

namespace hmfnet::app {

struct SimulateRequest {
  /// The network's file: recorded in the results and compared with the outputs (empty for a
  /// network made in memory).
  std::string input;
  double sigma0 = 0.35;
  double omega = 6.0;
  std::string momenta = "gaussian";
  std::vector<double> K, K_over_Kc;
  std::string sweep;  ///< START:STOP:STEP
  double h = 0.01, T = 1000.0, transient = 500.0;
  std::uint64_t seed = 0;
  int replicas = 1;
  int threads = 0;  ///< 0: the thread rule (dynamics/thread_choice.hpp) or OMP_NUM_THREADS
  std::string output, checkpoint;
  std::string force = "auto", integrator = "leapfrog", precision = "float64";
  std::string device = "cpu";  ///< cpu, or cuda (dynamics/device_stepper.hpp)
  bool resume = false, node_data = false, restart_each_K = false, K_across_replicas = false;
  int record_stride = 100;
  double energy_tolerance = 1e-2;
  int rotor_node = 0;
  int phase_bins = 72;
  bool progress = false;  ///< a progress line on stderr (root rank)
};

/// Throws ParameterError naming the first value out of range, in the CLI's words
/// (app/option_checks.hpp); also every range of the parameters that needs no network
/// (dynamics/simulation_parameters.hpp: validate).
void validate(const SimulateRequest& r);

/// The run's parameters: K_over_Kc scaled by Kc, the sweep expanded, one initial condition per
/// replica (seeds seed .. seed + replicas - 1).
SimulationParameters simulation_parameters(const SimulateRequest& r, double Kc);

/// "START:STOP:STEP" -> START, START+STEP, ... <= STOP (+ half a step of slack for round-off);
/// at most k_max_schedule values.
std::vector<double> parse_sweep(const std::string& text);

}  // namespace hmfnet::app
