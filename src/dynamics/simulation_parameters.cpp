#include "dynamics/simulation_parameters.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dynamics/integrator.hpp"

namespace hmfnet {

namespace {

std::int64_t steps_for(double time, double h) { return std::llround(time / h); }

void validate_steps(const SimulationParameters& p) {
  const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!p.steps.empty() && p.steps.size() != p.K.size()) {
    throw ParameterError("steps", std::to_string(p.steps.size()) + " entries",
                         "none, or one per K (" + std::to_string(p.K.size()) + ")");
  }
  for (std::size_t k = 0; k < p.steps.size(); ++k) {
    if (!positive(p.steps[k].h)) {
      throw ParameterError("steps[" + std::to_string(k) + "].h", std::to_string(p.steps[k].h),
                           "h > 0");
    }
    make_integrator(p.steps[k].integrator);  // unknown names fail here, before any work
  }
  for (std::size_t k = 0; k < std::max<std::size_t>(p.steps.size(), 1); ++k) {
    const double h = step_at(p, k).h;
    const std::int64_t samples = steps_for(p.duration, h) - steps_for(p.transient, h);
    if (samples < p.batches) {
      throw ParameterError("T - transient", std::to_string(p.duration - p.transient),
                           "at least " + std::to_string(p.batches) +
                               " steps of h = " + std::to_string(h) + " to average over");
    }
  }
}

// K_across_replicas runs the schedule as one segment of K.size() x replicas.size() lanes.
void validate_across(const SimulationParameters& p) {
  if (!p.K_across_replicas) return;
  if (p.continue_state) {
    throw ParameterError("K across replicas", "with each K continuing from the previous one",
                         "each K from the initial condition (continue_state = false, "
                         "--restart-each-K): K values run side by side cannot continue each other");
  }
  for (std::size_t k = 1; k < p.steps.size(); ++k) {
    if (p.steps[k].h != p.steps[0].h || p.steps[k].integrator != p.steps[0].integrator) {
      throw ParameterError("K across replicas",
                           "steps[" + std::to_string(k) + "] differs from steps[0]",
                           "one integrator and h for every K (lanes share each step)");
    }
  }
  if (p.node_data) {
    throw ParameterError("K across replicas (--K-across-replicas)", "with node_data (--node-data)",
                         "no per-node statistics (they follow one replica per K): use "
                         "--restart-each-K");
  }
  if (lanes(p) > 64) {
    throw ParameterError(
        "K across replicas",
        std::to_string(p.K.size()) + " K x " + std::to_string(p.replicas.size()) + " replicas",
        "at most 64 lanes per pass");
  }
}

}  // namespace

std::size_t lanes(const SimulationParameters& p) {
  return p.replicas.size() * (p.K_across_replicas ? p.K.size() : 1);
}

StepChoice step_at(const SimulationParameters& p, std::size_t k) {
  return p.steps.empty() ? StepChoice{p.integrator, p.h} : p.steps.at(k);
}

void validate(const SimulationParameters& p) {
  const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!positive(p.h)) throw ParameterError("h", std::to_string(p.h), "h > 0");
  if (!(p.transient >= 0.0) || !std::isfinite(p.transient)) {
    throw ParameterError("transient", std::to_string(p.transient), "transient >= 0");
  }
  if (!positive(p.duration) || !(p.duration > p.transient)) {
    throw ParameterError("T", std::to_string(p.duration), "T > transient >= 0");
  }
  if (p.K.empty()) throw ParameterError("K", "empty schedule", "at least one K >= 0");
  if (p.batches < 2) throw ParameterError("batches", std::to_string(p.batches), ">= 2");
  validate_steps(p);
  for (const double K : p.K) {
    if (!(K >= 0.0) || !std::isfinite(K)) throw ParameterError("K", std::to_string(K), "K >= 0");
  }
  if (p.replicas.empty() || p.replicas.size() > 64) {
    throw ParameterError("replicas", std::to_string(p.replicas.size()), "1 to 64");
  }
  for (const auto& r : p.replicas) {
    if (!positive(r.sigma0)) throw ParameterError("sigma0", std::to_string(r.sigma0), "sigma0 > 0");
  }
  if (p.record_stride < 1)
    throw ParameterError("record stride", std::to_string(p.record_stride), ">= 1");
  if (p.phase_bins < 1) throw ParameterError("phase bins", std::to_string(p.phase_bins), ">= 1");
  if (p.rotor_node < 0) throw ParameterError("rotor node", std::to_string(p.rotor_node), ">= 0");
  if (p.threads < 0)
    throw ParameterError("threads", std::to_string(p.threads), ">= 0 (0: default)");
  if (!positive(p.energy_tolerance)) {
    throw ParameterError("energy tolerance", std::to_string(p.energy_tolerance), "> 0");
  }
  validate_across(p);
}

nlohmann::json to_json(const SimulationParameters& p) {
  nlohmann::json replicas = nlohmann::json::array(), steps = nlohmann::json::array();
  for (const auto& r : p.replicas) {
    replicas.push_back({{"omega", r.omega},
                        {"sigma0", r.sigma0},
                        {"seed", r.seed},
                        {"momenta", name_of(r.momenta)}});
  }
  for (const auto& s : p.steps) steps.push_back({{"integrator", s.integrator}, {"h", s.h}});
  return {{"h", p.h},
          {"T", p.duration},
          {"transient", p.transient},
          {"K", p.K},
          {"continue_state", p.continue_state},
          {"K_across_replicas", p.K_across_replicas},
          {"replicas", replicas},
          {"record_stride", p.record_stride},
          {"batches", p.batches},
          {"energy_tolerance", p.energy_tolerance},
          {"node_data", p.node_data},
          {"rotor_node", p.rotor_node},
          {"phase_bins", p.phase_bins},
          {"integrator", p.integrator},
          {"steps", steps}};
}

std::string fingerprint(const SimulationParameters& p, NodeIndex n, EdgeOffset nnz) {
  nlohmann::json j = to_json(p);
  j.erase("energy_tolerance");
  j["n"] = n;
  j["nnz"] = nnz;
  return j.dump();
}

}  // namespace hmfnet
