// `hmfnet generate er|sf|complete`: the paper's two network families (Sec. numericalExperiments)
// and its all-to-all limit K_N, stored in O(1) space.
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli/command_options.hpp"
#include "cli/commands.hpp"
#include "cli/provenance.hpp"
#include "cli/validators.hpp"
#include "core/atomic_file.hpp"
#include "io/network_file.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"

namespace hmfnet::cli {

namespace {

void report(const Network& net, const std::string& path, double seconds) {
  if (!is_root()) return;
  std::cerr << "wrote " << path << ": N = " << net.size() << ", edges = " << net.edges()
            << ", mean degree = " << 2.0 * static_cast<double>(net.edges()) / net.size() << " ("
            << seconds << " s)\n";
}

void check_output(const std::string& path) {
  format_from_extension(path);
  require_writable_destination(path);
}

void run_er(const ErFlags& f) {
  check_output(f.output);
  const auto start = std::chrono::steady_clock::now();
  const double q = f.q >= 0.0 ? f.q : erdos_renyi_probability(f.n, f.mean_degree);
  const Network net = erdos_renyi({f.n, q, f.seed});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (is_root()) {
    write_network(f.output, net,
                  provenance("generate er", {{"n", f.n}, {"q", q}, {"seed", f.seed}}));
  }
  report(net, f.output, seconds);
}

void run_sf(const SfFlags& f) {
  check_output(f.output);
  const auto start = std::chrono::steady_clock::now();
  const double d_min =
      f.d_min > 0.0 ? f.d_min : power_law_d_min_for_mean(f.alpha, f.mean_degree, f.cutoff);
  const PowerLaw law{f.alpha, d_min, f.cutoff};
  const auto link = link_probability_from_name(f.link);
  const Network net = chung_lu(power_law_targets(f.n, law, f.seed), link, f.seed);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (is_root()) {
    nlohmann::json p = {
        {"n", f.n}, {"alpha", f.alpha}, {"d_min", d_min}, {"link", f.link}, {"seed", f.seed}};
    p["cutoff"] = std::isinf(f.cutoff) ? nlohmann::json("none") : nlohmann::json(f.cutoff);
    write_network(f.output, net, provenance("generate sf", p));
  }
  report(net, f.output, seconds);
}

void run_complete(const CompleteFlags& f) {
  const CompleteGraph graph = CompleteGraph::make(f.n, f.self_loops);
  require_complete_graph_format(f.output);
  require_writable_destination(f.output);
  if (is_root()) {
    write_complete_graph(
        f.output, graph,
        provenance("generate complete", {{"n", f.n}, {"self_loops", f.self_loops}}));
    std::cerr << "wrote " << f.output << ": the complete graph, N = " << graph.n
              << ", edges = " << graph.edges() << " (stored implicitly)\n";
  }
}

}  // namespace

void add_generate_command(CLI::App& app) {
  static ErFlags er;
  static SfFlags sf;
  static CompleteFlags complete;
  add_generate_options(
      app, er, sf, complete, [] { run_er(er); }, [] { run_sf(sf); },
      [] { run_complete(complete); });
}

}  // namespace hmfnet::cli
