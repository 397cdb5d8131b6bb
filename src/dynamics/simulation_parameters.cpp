#include "dynamics/simulation_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "parallel/network_content_hash.hpp"

namespace hmfnet {

namespace {

std::int64_t steps_for(double time, double h) { return std::llround(time / h); }

// T / h above this is refused before steps_for rounds it: 10^15 steps are years of any machine,
// and the count stays an exact integer in a double (< 2^53) and far inside int64.
constexpr double k_max_steps_per_K = 1e15;

void validate_step_count(double T, double h, const std::string& where) {
  if (T / h <= k_max_steps_per_K) return;
  throw ParameterError(
      "T / h" + where,
      number_text(T) + " / " + number_text(h) + " = " + number_text(T / h) + " steps per K",
      "at most " + number_text(k_max_steps_per_K) + " steps per K");
}

void validate_steps(const SimulationParameters& p) {
  const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!p.steps.empty() && p.steps.size() != p.K.size()) {
    throw ParameterError("steps", std::to_string(p.steps.size()) + " entries",
                         "none, or one per K (" + std::to_string(p.K.size()) + ")");
  }
  for (std::size_t k = 0; k < p.steps.size(); ++k) {
    if (!positive(p.steps[k].h)) {
      throw ParameterError("steps[" + std::to_string(k) + "].h", number_text(p.steps[k].h),
                           "h > 0");
    }
    make_integrator(p.steps[k].integrator);  // unknown names fail here, before any work
  }
  for (std::size_t k = 0; k < std::max<std::size_t>(p.steps.size(), 1); ++k) {
    const double h = step_at(p, k).h;
    validate_step_count(p.duration, h,
                        p.steps.empty() ? "" : " of steps[" + std::to_string(k) + "]");
    const std::int64_t samples = steps_for(p.duration, h) - steps_for(p.transient, h);
    if (samples < p.batches) {
      throw ParameterError("T - transient", number_text(p.duration - p.transient),
                           "at least " + std::to_string(p.batches) +
                               " steps of h = " + number_text(h) + " to average over");
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
  if (!positive(p.h)) throw ParameterError("h", number_text(p.h), "h > 0");
  if (!(p.transient >= 0.0) || !std::isfinite(p.transient)) {
    throw ParameterError("transient", number_text(p.transient), "transient >= 0");
  }
  if (!positive(p.duration) || !(p.duration > p.transient)) {
    throw ParameterError("T", number_text(p.duration), "T > transient >= 0");
  }
  if (p.K.empty()) throw ParameterError("K", "empty schedule", "at least one K >= 0");
  if (p.K.size() > k_max_schedule) {
    throw ParameterError("K", std::to_string(p.K.size()) + " values",
                         "at most " + std::to_string(k_max_schedule) + " K values per run");
  }
  if (p.batches < 2) throw ParameterError("batches", std::to_string(p.batches), ">= 2");
  validate_steps(p);
  for (const double K : p.K) {
    if (!(K >= 0.0) || !std::isfinite(K)) throw ParameterError("K", number_text(K), "K >= 0");
  }
  if (p.replicas.empty() || p.replicas.size() > 64) {
    throw ParameterError("replicas", std::to_string(p.replicas.size()), "1 to 64");
  }
  for (const auto& r : p.replicas) {
    if (!positive(r.sigma0)) throw ParameterError("sigma0", number_text(r.sigma0), "sigma0 > 0");
  }
  if (p.record_stride < 1)
    throw ParameterError("record stride", std::to_string(p.record_stride), ">= 1");
  if (p.phase_bins < 1) throw ParameterError("phase bins", std::to_string(p.phase_bins), ">= 1");
  if (p.rotor_node < 0) throw ParameterError("rotor node", std::to_string(p.rotor_node), ">= 0");
  if (p.threads < 0)
    throw ParameterError("threads", std::to_string(p.threads), ">= 0 (0: default)");
  if (p.device != "cpu" && p.device != "cuda")
    throw ParameterError("device", p.device, "cpu, cuda");
  if (!positive(p.energy_tolerance)) {
    throw ParameterError("energy tolerance", number_text(p.energy_tolerance), "> 0");
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

std::string fingerprint(const SimulationParameters& p, const RunIdentity& identity) {
  nlohmann::json j = to_json(p);
  j.erase("energy_tolerance");
  j["n"] = identity.n;
  j["nnz"] = identity.nnz;
  j["network_hash"] = hash_hex(identity.network_hash);
  j["force"] = identity.force;
  return j.dump();
}

std::string fingerprint_difference(const std::string& checkpoint, const std::string& run) {
  const nlohmann::json a = nlohmann::json::parse(checkpoint, nullptr, false);
  const nlohmann::json b = nlohmann::json::parse(run, nullptr, false);
  if (!a.is_object()) return "fingerprint: unreadable in the checkpoint";
  // The network first: a resume on another network is the mistake that costs most.
  std::vector<std::string> keys{"n", "nnz", "network_hash", "force"};
  for (const auto* j : {&a, &b}) {
    for (const auto& item : j->items()) {
      if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) keys.push_back(item.key());
    }
  }
  std::sort(keys.begin() + 4, keys.end());
  const auto shown = [](const nlohmann::json& j, const std::string& key) {
    if (!j.contains(key)) return std::string("absent");
    std::string text = j.at(key).dump();
    return text.size() > 60 ? text.substr(0, 57) + "..." : text;
  };
  for (const std::string& key : keys) {
    if (a.contains(key) && b.contains(key) && a.at(key) == b.at(key)) continue;
    const std::string name = key == "network_hash" ? "network (hash of its stored entries)" : key;
    return name + ": " + shown(a, key) + " in the checkpoint, " + shown(b, key) + " in this run";
  }
  return "";
}
}  // namespace hmfnet
