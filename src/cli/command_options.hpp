#pragma once
// The command-line grammar of `hmfnet`: every subcommand's options, their ranges and the checks
// that involve several options, with no work attached. Each add_*_options registers a subcommand
// whose callback, once its options parse, calls `run` with the flags filled in. The commands
// (cli/*_command.cpp) pass their work; the CLI argument fuzzer (tests/fuzz/fuzz_cli_arguments)
// passes nothing, so the grammar is tested without MPI, Trilinos or a network. The ranges of a
// typed request's values are its own check (src/app: validate), run by the subcommand's callback
// before its work, so the command line and Python refuse a value with the same words; a refusal
// there is a command-line error like any the grammar finds ("(see --help)", exit code 2).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/convert_request.hpp"
#include "app/generate_requests.hpp"
#include "app/rewire_request.hpp"
#include "app/simulate_request.hpp"
#include "app/spectrum_request.hpp"
#include "app/theory_request.hpp"
#include "cli/cli_app_fwd.hpp"
#include "cli/read_flags.hpp"
#include "core/error.hpp"

namespace hmfnet::cli {

using Run = std::function<void()>;

/// `rewire`: the typed request (app/rewire_request.hpp) and how to read its input.
struct RewireFlags {
  app::RewireRequest request;
  ReadFlags read;
};

/// `convert`: the typed request (app/convert_request.hpp) and how to read its input.
struct ConvertFlags {
  app::ConvertRequest request;
  ReadFlags read;
};

/// `spectrum`: the typed request (app/spectrum_request.hpp) and what only the command line has.
struct SpectrumFlags {
  app::SpectrumRequest request;
  bool json = false;
  ReadFlags read;
};

/// `theory`: the typed request (app/theory_request.hpp) and what only the command line has.
struct TheoryFlags {
  app::TheoryRequest request;
  bool json = false;
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

/// Throws the error main() reports as a command-line error: one line ending in "(see --help)",
/// exit code 2 (CLI11's ValidationError, so that the commands need not include CLI11).
[[noreturn]] void throw_command_line_error(const std::string& message);

/// Runs `work`; a value it refuses (ParameterError) is a command-line error like any the grammar
/// finds (throw_command_line_error), in the request's own words.
template <class Work>
void as_command_line_error(Work&& work) {
  try {
    work();
  } catch (const ParameterError& e) {
    throw_command_line_error(e.what());
  }
}

/// `generate er|sf|sbm|complete|regular`: the typed requests (app/generate_requests.hpp).
struct GenerateFlags {
  app::ErRequest er;
  app::SfRequest sf;
  app::SbmRequest sbm;
  app::CompleteRequest complete;
  app::RegularRequest regular;
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
