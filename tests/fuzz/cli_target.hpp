#pragma once
// What one fuzz input means for the CLI grammar (src/cli/command_options.cpp), shared by the
// libFuzzer harness (fuzz_cli_arguments.cpp) and the replay CTest (replay_corpus.cpp).
//
// An input is a command line: arguments separated by newlines ("simulate\nnet.mtx\n--K\n1").
// Contract under test: parsing either throws a CLI11 error (a parse error, --help, --version), or
// hmfnet::ParameterError from a check across options, or reaches the subcommand's work with every
// value inside the range its option states. The ranges of the typed requests are their own checks
// (src/app: validate), which the grammar's callbacks run before the work: these checks, written
// apart from them, test them too (simulate: the grammar's part only, see check_simulate). The
// work itself is replaced by those range checks (no network is read and nothing is run). Anything
// else -- another exception, a sanitizer report, a value out of range that reached the work --
// aborts with a message.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/command_options.hpp"
#include "core/error.hpp"

namespace hmfnet::fuzz {

[[noreturn]] inline void grammar_violated(const std::string& command, const std::string& why) {
  std::fprintf(stderr, "CLI contract violated: %s: %s\n", command.c_str(), why.c_str());
  std::abort();
}

// The ranges every add_*_options promises (their --help texts and tests/cli/option_ranges.txt).
class RangeChecks {
 public:
  explicit RangeChecks(std::string command) : command_(std::move(command)) {}
  void require(bool ok, const char* what) const {
    if (!ok) grammar_violated(command_, what);
  }
  void positive(double v, const char* what) const { require(v > 0.0 && std::isfinite(v), what); }
  void non_negative(double v, const char* what) const {
    require(v >= 0.0 && std::isfinite(v), what);
  }
  void read_flags(const cli::ReadFlags& r) const {
    require(r.index_base == 0 || r.index_base == 1, "--index-base outside {0,1}");
    require(r.nodes >= 0, "--nodes < 0");
  }

 private:
  std::string command_;
};

inline void check_er(const app::ErRequest& f, const std::string& line) {
  const RangeChecks c(line);
  c.require(f.n >= 2, "--n < 2");
  c.require(f.q.has_value() != f.mean_degree.has_value(), "not one of --q and --mean-degree");
  c.require((f.q && *f.q > 0.0 && *f.q <= 1.0) ||
                (f.mean_degree && *f.mean_degree > 0.0 && std::isfinite(*f.mean_degree)),
            "neither a probability q > 0 nor a finite mean degree > 0");
}

inline void check_sf(const app::SfRequest& f, const std::string& line) {
  const RangeChecks c(line);
  c.require(f.n >= 2, "--n < 2");
  c.require(f.alpha > 2.0 && std::isfinite(f.alpha), "--alpha not > 2");
  c.require(f.d_min.has_value() != f.mean_degree.has_value(),
            "not one of --dmin and --mean-degree");
  c.require((f.d_min && *f.d_min > 0.0 && std::isfinite(*f.d_min)) ||
                (f.mean_degree && *f.mean_degree > 0.0 && std::isfinite(*f.mean_degree)),
            "neither d_min nor a mean degree > 0");
  c.require(f.cutoff > 0.0, "--cutoff not > 0");
  c.require(f.link == "capped" || f.link == "poisson" || f.link == "odds", "--link unknown");
}

inline void check_complete(const app::CompleteRequest& f, const std::string& line) {
  const RangeChecks c(line);
  c.require(f.n >= 2 && f.n <= 2147483647, "--n outside 2..2^31-1");
}

inline void check_sbm(const app::SbmRequest& f, const std::string& line) {
  const RangeChecks c(line);
  c.require(f.half >= 1 && f.half <= 1073741823, "--half outside 1..2^30-1");
  c.require(f.p_in >= 0.0 && f.p_in <= 1.0, "--p-in not a probability");
  c.require(f.p_out >= 0.0 && f.p_out <= 1.0, "--p-out not a probability");
  c.require(f.p_in > 0.0 || f.p_out > 0.0, "--p-in and --p-out both 0");
}

inline void check_regular(const app::RegularRequest& f, const std::string& line) {
  const RangeChecks c(line);
  c.require(f.n >= 2, "--n < 2");
  c.require(f.degree >= 1, "--degree < 1");
}

// simulate's grammar holds the types, the seed's text, --threads' count and the K options that
// exclude each other, and no more: the ranges of its values are the request's own check
// (app::validate, the command's first step), which needs the library this fuzz build leaves out;
// tests/app/test_simulate_request.cpp refuses each range's edge in the CLI's words instead.
inline void check_simulate(const cli::SimulateFlags& f, const std::string& line) {
  const RangeChecks c(line);
  const app::SimulateRequest& r = f.request;
  c.require(r.threads == 0 || (r.threads >= 1 && r.threads <= 1024), "--threads outside 1..1024");
  c.require(int(!r.K.empty()) + int(!r.K_over_Kc.empty()) + int(!r.sweep.empty()) <= 1,
            "--K, --K-over-Kc and --K-sweep together");
  c.read_flags(f.read);
}

inline void check_theory(const cli::TheoryFlags& f, const std::string& line) {
  const RangeChecks c(line);
  const app::TheoryRequest& r = f.request;
  c.positive(r.sigma0, "--sigma0 not > 0");
  c.require(r.momenta == "gaussian" || r.momenta == "waterbag", "--momenta unknown");
  for (double k : r.K) c.positive(k, "--K not > 0");
  for (double k : r.K_over_Kc) c.positive(k, "--K-over-Kc not > 0");
  c.require(r.K.empty() != r.K_over_Kc.empty(), "not one of --K and --K-over-Kc");
  c.require(r.tolerance >= 1e-14 && r.tolerance <= 1e-2, "--tolerance outside [1e-14, 1e-2]");
  c.read_flags(f.read);
}

inline void check_spectrum(const cli::SpectrumFlags& f, const std::string& line) {
  const RangeChecks c(line);
  const app::SpectrumRequest& r = f.request;
  if (r.sigma0) c.positive(*r.sigma0, "--sigma0 not > 0");
  c.require(r.tolerance >= 1e-15 && r.tolerance <= 1e-2, "--tolerance range");
  c.require(r.lambda2 == "auto" || r.lambda2 == "converged" || r.lambda2 == "bound",
            "--lambda2 unknown");
  c.read_flags(f.read);
}

/// Parses one command line through the real grammar; returns whether it reached a subcommand's
/// work (all of whose values were then checked).
inline bool parse_command_line(std::vector<std::string> args) {
  std::string line = "hmfnet";
  for (const auto& a : args) line += " " + a;
  cli::GenerateFlags generate;
  cli::RewireFlags rewire;
  cli::ConvertFlags convert;
  cli::SpectrumFlags spectrum;
  cli::TheoryFlags theory;
  cli::SimulateFlags simulate;
  cli::DemoFlags demo;
  bool reached = false;
  CLI::App app{"hmfnet (fuzzed grammar)"};
  cli::configure_app(app);
  cli::add_generate_options(app, generate,
                            {[&] { check_er(generate.er, line), reached = true; },
                             [&] { check_sf(generate.sf, line), reached = true; },
                             [&] { check_sbm(generate.sbm, line), reached = true; },
                             [&] { check_complete(generate.complete, line), reached = true; },
                             [&] { check_regular(generate.regular, line), reached = true; }});
  cli::add_rewire_options(app, rewire, [&] {
    const RangeChecks c(line);
    c.positive(rewire.request.target_rho, "--target-rho not > 0");
    c.require(rewire.request.max_attempts >= 0, "--max-attempts < 0");
    c.read_flags(rewire.read);
    reached = true;
  });
  cli::add_convert_options(app, convert, [&] {
    const RangeChecks c(line);
    const app::ConvertRequest& r = convert.request;
    c.require(r.partition >= 0 && r.partition <= 65536, "--partition range");
    c.require(r.order == "original" || r.order == "rcm" || r.order == "degree",
              "--order not a known order");
    c.require(r.partition == 0 || r.order == "original", "--partition with --order");
    c.read_flags(convert.read);
    reached = true;
  });
  cli::add_spectrum_options(app, spectrum, [&] { check_spectrum(spectrum, line), reached = true; });
  cli::add_theory_options(app, theory, [&] { check_theory(theory, line), reached = true; });
  cli::add_simulate_options(app, simulate, [&] { check_simulate(simulate, line), reached = true; });
  cli::add_demo_options(app, demo, [&] {
    RangeChecks(line).require(demo.n >= 100 && demo.n <= 1000000, "--n outside 100..10^6");
    reached = true;
  });
  // CLI11 takes the arguments in reverse order (it pops them from the back).
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::Error&) {
    return false;  // a parse error, --help or --version: main() prints it and exits
  } catch (const hmfnet::ParameterError&) {
    return false;  // a check across options the command makes itself
  }
  return reached;
}

// Token mode: random bytes rarely turn "0.5" into "nan" without breaking the rest of the line,
// and a wrong value takes the same branches as a right one, so coverage does not lead to it. An
// input starting with 0xFF is a list of token indices instead: each later byte picks one whole
// argument from this table (subcommands, every option, boundary values), so one mutated byte
// swaps one argument for another meaningful one.
inline const std::vector<std::string>& argument_tokens() {
  static const std::vector<std::string> tokens = {
      // subcommands and positional files
      "generate", "er", "sf", "rewire", "convert", "spectrum", "theory", "simulate", "demo",
      "net.mtx", "out.h5", "out.mtx", "-o", "--output", "--help", "--version", "--",
      // options
      "--n", "--q", "--mean-degree", "--seed", "--alpha", "--dmin", "--cutoff", "--link",
      "--target-rho", "--max-attempts", "--json", "--sigma0", "--tolerance", "--K", "--K-over-Kc",
      "--K-sweep", "--omega", "--h", "--T", "--transient", "--replicas", "--threads",
      "--checkpoint", "--resume", "--quiet", "--node-data", "--rotor-node", "--phase-bins",
      "--restart-each-K", "--record-stride", "--energy-tolerance", "--integrator", "--force",
      "--symmetrize", "--index-base", "--nodes", "--partition",
      // values: inside, on and outside every stated range
      "nan", "-nan", "inf", "-inf", "-1", "0", "-0", "1e-300", "1e-16", "1e-15", "1e-14", "0.01",
      "0.02", "0.5", "1", "1.5", "2", "2.0000001", "2.5", "3", "10", "64", "65", "99", "100",
      "1000", "1024", "1025", "1000000", "1000001", "2147483647", "2147483648", "1e308", "1e309",
      "18446744073709551615", "18446744073709551616", "-18446744073709551615", "0x10", " 1", "1 ",
      "1,2", "1,nan", ",", "1,,2", "0:10:1", "1:0:1", "0:1:0", "0:1:nan", "a:b:c", ":", "capped",
      "poisson", "odds", "auto", "sparse", "rank-one", "leapfrog", "yoshida4", "blanes_moan", "rk4",
      "", "-", "true", "x",
      // appended (token-mode seeds index the entries above)
      "--precision", "float32", "float64", "--K-across-replicas", "--momenta", "gaussian",
      "waterbag", "--order", "rcm", "degree", "original", "regular", "--degree"};
  return tokens;
}

/// The fuzz input as a command line: one argument per line (a final newline is ignored), or in
/// token mode (first byte 0xFF) one argument_tokens() entry per byte.
inline std::vector<std::string> split_arguments(const std::uint8_t* data, std::size_t size) {
  if (size > 0 && data[0] == 0xFF) {
    const auto& tokens = argument_tokens();
    std::vector<std::string> args;
    for (std::size_t i = 1; i < size; ++i) args.push_back(tokens[data[i] % tokens.size()]);
    return args;
  }
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.emplace_back();
    } else {
      args.back().push_back(static_cast<char>(data[i]));
    }
  }
  if (!args.empty() && args.back().empty()) args.pop_back();
  return args;
}

}  // namespace hmfnet::fuzz
