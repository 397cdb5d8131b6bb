// `hmfnet generate er|sf`: the paper's two network families (Sec. numericalExperiments).
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/provenance.hpp"
#include "cli/validators.hpp"
#include "core/atomic_file.hpp"
#include "io/network_file.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"

namespace hmfnet::cli {

namespace {

struct ErFlags {
  int n = 0;
  double q = -1.0;
  double mean_degree = -1.0;
  std::uint64_t seed = 0;
  std::string output;
};

struct SfFlags {
  int n = 0;
  double alpha = 0.0;
  double d_min = -1.0;
  double mean_degree = -1.0;
  double cutoff = std::numeric_limits<double>::infinity();
  std::string link = "capped";
  std::uint64_t seed = 0;
  std::string output;
};

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

}  // namespace

void add_generate_command(CLI::App& app) {
  auto* gen = app.add_subcommand("generate", "Generate a random network (er | sf)");
  gen->require_subcommand(1);

  static ErFlags er;
  auto* e = gen->add_subcommand("er", "Erdos-Renyi G(N, q): each pair linked with probability q");
  e->add_option("--n", er.n, "Number of nodes")->required()->check(CLI::Range(1, 2147483647));
  auto* q = e->add_option("--q", er.q, "Link probability")->check(k_probability);
  auto* d =
      e->add_option("--mean-degree", er.mean_degree, "Mean degree (N-1) q")->check(k_non_negative);
  q->excludes(d);
  e->add_option("--seed", er.seed, "Random seed")->required()->check(k_seed);
  e->add_option("-o,--output", er.output, "Output file (.mtx, .h5 or edge list .txt)")->required();
  e->callback([q, d] {
    if (q->count() == 0 && d->count() == 0) {
      throw CLI::RequiredError("one of --q or --mean-degree");
    }
    run_er(er);
  });

  static SfFlags sf;
  auto* s = gen->add_subcommand(
      "sf", "Scale-free Chung-Lu network with power-law targets P(d) ~ d^-alpha, d > d_min");
  s->add_option("--n", sf.n, "Number of nodes")->required()->check(CLI::Range(1, 2147483647));
  s->add_option("--alpha", sf.alpha, "Power-law exponent (> 2)")
      ->required()
      ->check(greater_than(2.0));
  auto* dm =
      s->add_option("--dmin", sf.d_min, "Smallest target degree d_min (> 0)")->check(k_positive);
  auto* md = s->add_option("--mean-degree", sf.mean_degree,
                           "Target mean degree: d_min solved from the continuum mean")
                 ->check(k_positive);
  dm->excludes(md);
  s->add_option("--cutoff", sf.cutoff, "Largest target degree (default: none)")
      ->check(k_positive_or_inf);
  s->add_option("--link", sf.link,
                "Link probability of x = w_n w_m / S: capped min(1,x) "
                "(default), poisson 1-exp(-x), odds x/(1+x)")
      ->check(CLI::IsMember({"capped", "poisson", "odds"}));
  s->add_option("--seed", sf.seed, "Random seed")->required()->check(k_seed);
  s->add_option("-o,--output", sf.output, "Output file (.mtx, .h5 or edge list .txt)")->required();
  s->callback([dm, md] {
    if (dm->count() == 0 && md->count() == 0) {
      throw CLI::RequiredError("one of --dmin or --mean-degree");
    }
    run_sf(sf);
  });
}

}  // namespace hmfnet::cli
