#pragma once
// The command-line grammar of `hmfnet`: every subcommand's options, their ranges and the checks
// that involve several options, with no work attached. Each add_*_options registers a subcommand
// whose callback, once its options parse, calls `run` with the flags filled in. The commands
// (cli/*_command.cpp) pass their work; the CLI argument fuzzer (tests/fuzz/fuzz_cli_arguments)
// passes nothing, so the grammar is tested without MPI, Trilinos or a network.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "app/simulate_request.hpp"
#include "cli/read_flags.hpp"

namespace hmfnet::cli {

using Run = std::function<void()>;

struct ErFlags {
  int n = 0;
  double q = -1.0;
  double mean_degree = -1.0;
  std::uint64_t seed = 0;
  std::string output;
};

struct CompleteFlags {
  std::int64_t n = 0;
  bool self_loops = false;
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

struct SbmFlags {
  int half = 0;
  double p_in = 0.0;
  double p_out = 0.0;
  std::uint64_t seed = 0;
  std::string output;
};

struct RegularFlags {
  int n = 0;
  int degree = 0;
  std::uint64_t seed = 0;
  std::string output;
};

struct RewireFlags {
  std::string input;
  double target_rho = 0.0;
  std::uint64_t seed = 0;
  std::int64_t max_attempts = 0;
  std::string output;
  ReadFlags read;
};

struct ConvertFlags {
  std::string input;
  std::string output;
  int partition = 0;
  std::uint64_t seed = 1;
  std::string order = "original";
  ReadFlags read;
};

struct SpectrumFlags {
  std::string input;
  bool json = false;
  double sigma0 = 0.0;
  double tolerance = 1e-10;
  std::string lambda2 = "auto";
  ReadFlags read;
};

struct TheoryFlags {
  std::string input;
  double sigma0 = 0.0;
  std::string momenta = "gaussian";
  std::vector<double> K;
  std::vector<double> K_over_Kc;
  bool json = false;
  double tolerance = 1e-10;
  ReadFlags read;
};

/// `simulate`: the typed request (app/simulate_request.hpp) and what only the command line has
/// (how to read the file, how to print).
struct SimulateFlags {
  app::SimulateRequest request;
  bool json = false, quiet = false;
  ReadFlags read;
};

struct DemoFlags {
  int n = 10000;
  std::uint64_t seed = 1;
};

/// The top-level app: version flag, one subcommand required, one-line errors.
void configure_app(CLI::App& app);

struct GenerateFlags {
  ErFlags er;
  SfFlags sf;
  SbmFlags sbm;
  CompleteFlags complete;
  RegularFlags regular;
};
struct GenerateRuns {
  Run er, sf, sbm, complete, regular;
};
void add_generate_options(CLI::App& app, GenerateFlags& flags, const GenerateRuns& runs);
void add_rewire_options(CLI::App& app, RewireFlags& f, const Run& run);
void add_convert_options(CLI::App& app, ConvertFlags& f, const Run& run);
void add_spectrum_options(CLI::App& app, SpectrumFlags& f, const Run& run);
void add_theory_options(CLI::App& app, TheoryFlags& f, const Run& run);
void add_simulate_options(CLI::App& app, SimulateFlags& f, const Run& run);
void add_demo_options(CLI::App& app, DemoFlags& f, const Run& run);

}  // namespace hmfnet::cli
