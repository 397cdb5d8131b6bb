#include "cli/command_options.hpp"

#include <CLI/CLI.hpp>

#include "app/read_request.hpp"
#include "cli/number_list.hpp"
#include "cli/seed_check.hpp"
#include "core/error.hpp"
#include "core/version.hpp"

namespace hmfnet::cli {

void configure_app(CLI::App& app) {
  app.set_version_flag("--version", std::string(version()) + " (" + git_commit() + ")");
  app.require_subcommand(1);
  // One line, like every other error: "hmfnet: error: CAUSE (see --help)".
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "hmfnet: error: " + std::string(e.what()) + " (see --help)\n";
  });
}

void throw_command_line_error(const std::string& message) { throw CLI::ValidationError(message); }

namespace {

// The requests' own checks, a refusal a command-line error (main.cpp: exit code 2).
template <class... Requests>
void validate_on_command_line(const Requests&... requests) {
  as_command_line_error([&] { (app::validate(requests), ...); });
}

// `name` as a list of numbers read into `target` (cli/number_list.hpp), its refusal a
// command-line error.
CLI::Option* add_number_list(CLI::App* command, const std::string& name,
                             std::vector<double>& target, const std::string& description) {
  const auto read = [name, &target](const std::vector<std::string>& values) {
    as_command_line_error([&] { target = parse_number_list(name, values); });
  };
  // One value an occurrence (`--K 1,2` or `--K 1 --K 2`): with extra arguments allowed, CLI11
  // would read `--K '[1,,2]'` as a list of its own and drop the empty item before `read` sees it.
  return command->add_option_function<std::vector<std::string>>(name, read, description)
      ->allow_extra_args(false)
      ->type_name("FLOAT,...");
}

// The subcommand's callback: the requests' checks, then the work.
template <class... Requests>
std::function<void()> checked(const Run& run, const Requests&... requests) {
  return [run, &requests...] {
    validate_on_command_line(requests...);
    run();
  };
}

}  // namespace

void ReadFlags::add_to(CLI::App* command) {
  command->add_flag("--symmetrize", symmetrize,
                    "Matrix Market 'general' input that is not symmetric: use (A+A^T)/2 "
                    "(with a warning) instead of rejecting it");
  command->add_option("--index-base", index_base, "Edge lists: first node index (0 or 1)");
  command->add_option("--nodes", nodes, "Edge lists: number of nodes (default: largest index+1)");
}

// The generators' ranges and the options that set one quantity two ways ("one of --q or
// --mean-degree") are the requests' checks (app/generate_requests.hpp); the grammar keeps the
// seed's text (a uint64 would silently wrap "-1") and the exclusions that --help shows.
void add_generate_options(CLI::App& app, GenerateFlags& flags, const GenerateRuns& runs) {
  auto* gen =
      app.add_subcommand("generate", "Generate a network (er | sf | sbm | complete | regular)");
  gen->require_subcommand(1);

  app::ErRequest& er = flags.er;
  auto* e = gen->add_subcommand("er", "Erdos-Renyi G(N, q): each pair linked with probability q");
  e->add_option("--n", er.n, "Number of nodes")->required();
  auto* q = e->add_option("--q", er.q, "Link probability");
  auto* d = e->add_option("--mean-degree", er.mean_degree, "Mean degree (N-1) q");
  q->excludes(d);
  e->add_option("--seed", er.seed, "Random seed")->required()->check(k_seed);
  e->add_option("-o,--output", er.output, "Output file (.mtx, .h5 or edge list .txt)")->required();
  e->callback(checked(runs.er, er));

  app::SfRequest& sf = flags.sf;
  auto* s = gen->add_subcommand(
      "sf", "Scale-free Chung-Lu network with power-law targets P(d) ~ d^-alpha, d > d_min");
  s->add_option("--n", sf.n, "Number of nodes")->required();
  s->add_option("--alpha", sf.alpha, "Power-law exponent (> 2)")->required();
  auto* dm = s->add_option("--dmin", sf.d_min, "Smallest target degree d_min (> 0)");
  auto* md = s->add_option("--mean-degree", sf.mean_degree,
                           "Target mean degree: d_min solved from the continuum mean");
  dm->excludes(md);
  s->add_option("--cutoff", sf.cutoff, "Largest target degree (default: none)");
  s->add_option("--link", sf.link,
                "Link probability of x = w_n w_m / S: capped min(1,x) "
                "(default), poisson 1-exp(-x), odds x/(1+x)");
  s->add_option("--seed", sf.seed, "Random seed")->required()->check(k_seed);
  s->add_option("-o,--output", sf.output, "Output file (.mtx, .h5 or edge list .txt)")->required();
  s->callback(checked(runs.sf, sf));

  app::SbmRequest& sbm = flags.sbm;
  auto* b = gen->add_subcommand(
      "sbm", "Two-block stochastic block model: 2 half nodes, p_in inside a block, p_out between");
  b->add_option("--half", sbm.half, "Nodes per block")->required();
  b->add_option("--p-in", sbm.p_in, "Link probability inside a block")->required();
  b->add_option("--p-out", sbm.p_out, "Link probability between the blocks")->required();
  b->add_option("--seed", sbm.seed, "Random seed")->required()->check(k_seed);
  b->add_option("-o,--output", sbm.output, "Output file (.mtx, .h5 or edge list .txt)")->required();
  b->callback(checked(runs.sbm, sbm));

  app::CompleteRequest& complete = flags.complete;
  auto* c = gen->add_subcommand(
      "complete", "The complete graph K_N (all-to-all HMF), stored in O(1) space (.h5 only)");
  c->add_option("--n", complete.n, "Number of nodes")->required();
  c->add_flag("--self-loops", complete.self_loops, "Also A_nn = 1 (A = 1 1^T, lambda = N)");
  c->add_option("-o,--output", complete.output, "Output file (.h5)")->required();
  c->callback(checked(runs.complete, complete));

  app::RegularRequest& regular = flags.regular;
  auto* r = gen->add_subcommand(
      "regular", "Random d-regular graph: every node has exactly d neighbours (pairing model)");
  r->add_option("--n", regular.n, "Number of nodes")->required();
  r->add_option("--degree", regular.degree, "Degree d of every node (1 <= d <= n - 1, n d even)")
      ->required();
  r->add_option("--seed", regular.seed, "Random seed")->required()->check(k_seed);
  r->add_option("-o,--output", regular.output, "Output file (.mtx, .h5 or edge list .txt)")
      ->required();
  r->callback(checked(runs.regular, regular));
}

void add_rewire_options(CLI::App& app, RewireFlags& f, const Run& run) {
  app::RewireRequest& r = f.request;
  auto* c = app.add_subcommand("rewire",
                               "Degree-preserving double-edge swaps until the degree correlation "
                               "rho (paper eq. (17)) reaches a "
                               "target");
  c->add_option("input", r.input, "Network file (.mtx, .h5, edge list)")->required();
  c->add_option("--target-rho", r.target_rho, "Target degree correlation rho (> 0)")->required();
  c->add_option("--seed", r.seed, "Random seed")->required()->check(k_seed);
  c->add_option("--max-attempts", r.max_attempts,
                "Swap attempts before giving up (0: 200 x edges)");
  c->add_option("-o,--output", r.output, "Output file")->required();
  f.read.add_to(c);
  c->callback(checked(run, r, f.read));
}

void add_convert_options(CLI::App& app, ConvertFlags& f, const Run& run) {
  app::ConvertRequest& r = f.request;
  auto* c = app.add_subcommand(
      "convert", "Convert a network file to hmfnet HDF5, in parallel (each rank parses its part)");
  c->add_option("input", r.input, "Network file (.mtx, .h5, edge list)")->required();
  c->add_option("-o,--output", r.output, "Output file (.h5)")->required();
  auto* partition = c->add_option(
      "--partition", r.partition,
      "Renumber the nodes so that each of P parts found by Zoltan2 (Zoltan PHG "
      "hypergraph partitioning, parts of equal stored entries) is contiguous: P row blocks "
      "then import fewer ghosts per step (0: keep the order; at most 65536)");
  c->add_option("--seed", r.seed, "Seed of the partitioner's random choices (with --partition)")
      ->check(k_seed);
  c->add_option("--order", r.order,
                "Renumber the nodes for the force kernel's cache: rcm (reverse Cuthill-McKee, "
                "one rank; narrows the band of networks with locality) or degree (hubs first; "
                "scale-free networks); default original")
      ->excludes(partition);
  f.read.add_to(c);
  c->callback(checked(run, r, f.read));
}

void add_spectrum_options(CLI::App& app, SpectrumFlags& f, const Run& run) {
  app::SpectrumRequest& r = f.request;
  auto* c = app.add_subcommand(
      "spectrum", "Largest eigenvalue (Anasazi, distributed over MPI ranks), rho, G, structure");
  c->add_option("input", r.input, "Network file (.mtx, .h5, edge list)")->required();
  c->add_flag("--json", f.json, "One JSON object on stdout");
  c->add_option("--sigma0", r.sigma0, "Momentum spread: also report K_c = 2 sigma0^2 N / lambda");
  c->add_option("--tolerance", r.tolerance, "Relative eigen-residual tolerance (default 1e-10)");
  c->add_option("--lambda2", r.lambda2,
                "lambda_2: converged (to 1e-6), bound (Lanczos bounds that settle "
                "lambda / lambda_2 > 1.1, converged only if they do not), or auto (converged up "
                "to 4 10^6 stored entries; default)");
  f.read.add_to(c);
  c->callback(checked(run, r, f.read));
}

void add_theory_options(CLI::App& app, TheoryFlags& f, const Run& run) {
  app::TheoryRequest& r = f.request;
  auto* c = app.add_subcommand(
      "theory", "K_c, G, growth rate, synchronized state R(K) and its K -> infinity limit");
  c->add_option("input", r.input, "Network file (.mtx, .h5, edge list)")->required();
  c->add_option("--sigma0", r.sigma0, "Standard deviation of the initial momenta")->required();
  c->add_option("--momenta", r.momenta,
                "Initial momenta: gaussian or waterbag; K_c and gamma are that distribution's "
                "linear threshold and growth rate");
  auto* k = add_number_list(c, "--K", r.K, "Couplings K (comma-separated list)");
  auto* kappa =
      add_number_list(c, "--K-over-Kc", r.K_over_Kc, "Couplings as K/K_c (comma-separated)");
  k->excludes(kappa);
  c->add_flag("--json", f.json, "One JSON object on stdout");
  c->add_option("--tolerance", r.tolerance,
                "Relative residual of the self-consistent solves (default 1e-10)");
  f.read.add_to(c);
  c->callback(checked(run, r, f.read));
}

// The grammar only: the values' ranges are the request's own check (app::validate, the first
// thing the command does), so the command line and Python refuse a value with the same words.
void add_simulate_options(CLI::App& app, SimulateFlags& f, const Run& run) {
  app::SimulateRequest& r = f.request;
  auto* c = app.add_subcommand("simulate",
                               "Integrate the HMF rotors on a network over a schedule of K "
                               "(the paper's protocol: each K continues from the current state)");
  c->add_option("input", r.input, "Network file (.mtx, .h5, edge list)")->required();
  c->add_option("--sigma0", r.sigma0, "Standard deviation of the initial momenta (default 0.35)");
  c->add_option("--omega", r.omega, "Mean of the initial momenta (default 6)");
  c->add_option("--momenta", r.momenta,
                "Initial momenta: gaussian (the paper) or waterbag (uniform on omega +- "
                "sqrt(3) sigma0); K_c is that distribution's linear threshold");
  auto* k = add_number_list(c, "--K", r.K, "Couplings, comma separated");
  auto* kr = add_number_list(c, "--K-over-Kc", r.K_over_Kc,
                             "Couplings as multiples of K_c = 2 sigma0^2 N / lambda (Gaussian), "
                             "6 sigma0^2 N / lambda (water-bag)");
  auto* ks = c->add_option("--K-sweep", r.sweep, "START:STOP:STEP (the paper's sweep)");
  k->excludes(kr)->excludes(ks);
  kr->excludes(ks);
  c->add_option("--h", r.h, "Time step (default 0.01)");
  c->add_option("--T", r.T, "Time per K, T2 (default 1000)");
  c->add_option("--transient", r.transient, "Discarded start of each K, T1 (default 500)");
  c->add_option("--seed", r.seed, "Random seed of the initial state")->required()->check(k_seed);
  c->add_option("--replicas", r.replicas, "Independent replicas (seeds seed..seed+B-1, B <= 64)");
  // The request's 0 means "the thread rule's count"; on the command line that is the option left
  // out, so a typed 0 is refused here.
  c->add_option("--threads", r.threads,
                "OpenMP threads per rank (default: as the work per step pays for, at most the "
                "cores shared by the ranks; on a long enough run, the count whose first steps ran "
                "fastest)")
      ->check(CLI::Range(1, 1024));
  c->add_option("-o,--output", r.output, "Results file (HDF5)");
  c->add_option("--checkpoint", r.checkpoint, "Checkpoint file, written every few seconds");
  c->add_flag("--resume", r.resume, "Continue from --checkpoint if it exists");
  c->add_flag("--json", f.json, "One JSON object on stdout");
  c->add_flag("--quiet", f.quiet, "No progress line");
  c->add_flag("--node-data", r.node_data,
              "Per node and K: <R_n>_t, Omega_n, r_n, the fluctuation terms, the psi_n - psi_1 "
              "histogram and one rotor's (theta_bar, p_bar) samples (docs/simulation_output.md)");
  c->add_option("--rotor-node", r.rotor_node, "--node-data: the rotor sampled (default 0)");
  c->add_option("--phase-bins", r.phase_bins, "--node-data: histogram bins (default 72)");
  c->add_flag("--restart-each-K", r.restart_each_K, "Each K starts from the initial state");
  c->add_flag("--K-across-replicas", r.K_across_replicas,
              "Run every K at once as replicas of one pass (implies --restart-each-K; same "
              "results, one pass over the network per step for all K; K values x replicas <= 64)");
  c->add_option("--record-stride", r.record_stride, "Steps between time-series records");
  c->add_option("--energy-tolerance", r.energy_tolerance,
                "Stop when the relative energy error exceeds this (default 1e-2)");
  c->add_option("--integrator", r.integrator,
                "leapfrog (default; the paper's), yoshida4, blanes_moan (4th-order symplectic), "
                "rk4 (non-symplectic contrast)");
  c->add_option("--force", r.force, "auto (rank-one fast path when A = a a^T), sparse, rank-one");
  c->add_option("--precision", r.precision,
                "Sparse force kernel: float64 (default) or float32 (storage and accumulation of "
                "the gathered cos/sin; docs/choosing_a_method.md)");
  c->add_option("--device", r.device,
                "cpu (default) or cuda: every step on one CUDA GPU, the same bits as the CPU "
                "(sparse networks on one rank; docs/gpu.md)");
  f.read.add_to(c);
  c->callback(checked(run, f.read));
}

void add_demo_options(CLI::App& app, DemoFlags& f, const Run& run) {
  auto* c = app.add_subcommand("demo", "Built-in default job: the paper's Tables I-II networks");
  c->add_option("--n", f.n, "Nodes per network")->check(CLI::Range(100, 1000000));
  c->add_option("--seed", f.seed, "Random seed")->check(k_seed);
  c->callback(run);
}

}  // namespace hmfnet::cli
