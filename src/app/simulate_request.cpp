#include "app/simulate_request.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "app/option_checks.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/simulation_parameters.hpp"

namespace hmfnet::app {

std::vector<double> parse_sweep(const std::string& text) {
  const auto refuse = [&text](const char* allowed) {
    throw ParameterError("--K-sweep", "value " + text + " is not allowed", allowed);
  };
  std::vector<double> v;
  // Exactly three parts: getline drops a trailing empty one ("1:2:0.5:" would read as 1:2:0.5).
  if (std::count(text.begin(), text.end(), ':') != 2) refuse("START:STOP:STEP with numbers");
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) {
    std::size_t used = 0;
    try {
      v.push_back(std::stod(part, &used));
    } catch (const std::exception&) {
      used = 0;  // not a number (std::stod throws): refused below with the option's grammar
    }
    if (used == 0 || used != part.size()) {
      refuse("START:STOP:STEP with numbers");
    }
  }
  if (v.size() != 3 || !(v[2] > 0) || !(v[1] >= v[0])) {
    refuse("START:STOP:STEP with STEP > 0 and STOP >= START");
  }
  // The count first: a step far below the range would otherwise fill the memory before any
  // check could see the list (0:1:1e-300 asks for 10^300 values).
  const double count = std::floor((v[1] - v[0]) / v[2] + 0.5) + 1.0;
  if (!(count <= static_cast<double>(k_max_schedule))) {
    throw ParameterError("--K-sweep", text + " gives " + number_text(count) + " K values",
                         "at most " + std::to_string(k_max_schedule) + " K values per run");
  }
  std::vector<double> K;
  // `k <= count` ends the loop where START + k STEP rounds back to START (1e10:1e10:1e-10).
  for (int k = 0; k <= count && v[0] + k * v[2] <= v[1] + 0.5 * v[2]; ++k) {
    K.push_back(v[0] + k * v[2]);
  }
  return K;
}

void validate(const SimulateRequest& r) {
  require_positive("--sigma0", r.sigma0);
  require_finite("--omega", r.omega);
  require_member("--momenta", r.momenta, {"gaussian", "waterbag"});
  for (const double k : r.K) require_non_negative("--K", k);
  for (const double k : r.K_over_Kc) require_non_negative("--K-over-Kc", k);
  const int schedules = int(!r.K.empty()) + int(!r.K_over_Kc.empty()) + int(!r.sweep.empty());
  if (schedules == 0) {
    throw ParameterError("one of --K, --K-over-Kc or --K-sweep is required");
  }
  if (schedules > 1) {
    throw ParameterError("--K, --K-over-Kc and --K-sweep exclude each other: give one of them");
  }
  require_positive("--h", r.h);
  require_positive("--T", r.T);
  require_non_negative("--transient", r.transient);
  require_in_range("--replicas", r.replicas, 1, 64);
  // Replica b draws from seed + b: near 2^64 that would wrap to seed 0 and repeat another run's
  // replicas without a word.
  const auto last_first_seed =
      std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(r.replicas - 1);
  if (r.seed > last_first_seed) {
    throw ParameterError("--seed", "value " + std::to_string(r.seed) + " is not allowed",
                         "<= 2^64 - " + std::to_string(r.replicas) + " = " +
                             std::to_string(last_first_seed) + " with --replicas " +
                             std::to_string(r.replicas) +
                             "; the replicas take seeds seed..seed+B-1");
  }
  if (r.threads != 0) require_in_range("--threads", r.threads, 1, 1024);
  if (r.resume && r.checkpoint.empty()) {
    throw ParameterError("--checkpoint with --resume is required");
  }
  require_non_negative("--rotor-node", static_cast<double>(r.rotor_node));
  require_in_range("--phase-bins", r.phase_bins, 1, 100000);
  require_in_range("--record-stride", r.record_stride, 1, 1000000000);
  require_positive("--energy-tolerance", r.energy_tolerance);
  make_integrator(r.integrator);  // unknown names are refused naming the known ones
  require_member("--force", r.force, {"auto", "sparse", "rank-one"});
  require_member("--precision", r.precision, {"float64", "float32"});
  require_member("--device", r.device, {"cpu", "cuda"});
  // Every range that does not need the network: K_c only scales --K-over-Kc, so 1 stands in.
  validate(simulation_parameters(r, 1.0));
}

SimulationParameters simulation_parameters(const SimulateRequest& r, double Kc) {
  SimulationParameters p;
  p.h = r.h;
  p.duration = r.T;
  p.transient = r.transient;
  if (!r.K.empty()) p.K = r.K;
  for (const double k : r.K_over_Kc) p.K.push_back(k * Kc);
  if (!r.sweep.empty()) p.K = parse_sweep(r.sweep);
  p.continue_state = !(r.restart_each_K || r.K_across_replicas);
  p.K_across_replicas = r.K_across_replicas;
  p.replicas.clear();
  for (int b = 0; b < r.replicas; ++b) {
    p.replicas.push_back({r.omega, r.sigma0, r.seed + static_cast<std::uint64_t>(b),
                          parse_momentum_distribution(r.momenta, "--momenta")});
  }
  p.record_stride = r.record_stride;
  p.energy_tolerance = r.energy_tolerance;
  p.node_data = r.node_data;
  p.integrator = r.integrator;
  p.rotor_node = static_cast<NodeIndex>(r.rotor_node);
  p.phase_bins = r.phase_bins;
  p.checkpoint_path = r.checkpoint;
  p.resume = r.resume;
  p.progress = r.progress;
  p.device = r.device;
  // An explicit count (--threads, or OMP_NUM_THREADS) is the user's; otherwise the work decides.
  if (r.threads > 0) {
    p.threads = r.threads;
  } else if (std::getenv("OMP_NUM_THREADS") != nullptr) {
    p.threads = omp_get_max_threads();
  }
  return p;
}

}  // namespace hmfnet::app
