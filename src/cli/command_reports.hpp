#pragma once
// The work of `spectrum`, `theory` and `simulate` on a network already read, and the networks
// `generate` makes, without the printing: the CLI prints what these return and the Python
// module (src/python) converts it, so both give the same numbers from one code path. Each is
// collective over the MPI ranks; the JSON and the text are complete on rank 0.
#include <chrono>
#include <functional>
#include <string>

#include "cli/command_options.hpp"
#include "dynamics/simulation.hpp"
#include "network/network.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::cli {

/// What a command reports: the object `--json` prints, the table printed without it, and for
/// `theory` the solves that failed (the CLI prints the report, then exits 3 with this message).
struct CommandReport {
  std::string json;  ///< one line, no newline
  std::string text;
  std::string not_converged;  ///< empty when every solve converged
};

CommandReport spectrum_report(const SpectrumFlags& f, const DistributedInput& input);
CommandReport theory_report(const TheoryFlags& f, const DistributedInput& input);

/// `simulate`, in two steps. First what needs no network (run it before reading one): the
/// OpenMP thread count (--threads, or the cores shared by the ranks) and the checks of the
/// output locations and the integrator's name. Then the run: the report and the full result
/// (time series, node data); writes `f.output` when set; a run stopped by a signal throws
/// RunInterrupted.
void prepare_simulate(const SimulateFlags& f);

/// What the caller adds around the run: when it started (the results file's wall_seconds count
/// from there) and what to do once the set-up is done and the integration starts (the CLI
/// installs its interrupt handlers there: a signal during the set-up still ends the process at
/// once, one during the integration ends it at the next record with a checkpoint).
struct SimulateHooks {
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  std::function<void()> before_integration;
};

struct SimulateReport {
  CommandReport report;
  SimulationResult result;
};
SimulateReport simulate_report(const SimulateFlags& f, const DistributedInput& input,
                               const SimulateHooks& hooks = {});

/// The network `generate er|sf|sbm|regular` writes, whole on this rank (as the text formats write
/// it), with the provenance record the file would carry.
struct GeneratedNetwork {
  Network network;
  std::string provenance;
};
GeneratedNetwork generated_network(const ErFlags& f);
GeneratedNetwork generated_network(const SfFlags& f);
GeneratedNetwork generated_network(const SbmFlags& f);
GeneratedNetwork generated_network(const RegularFlags& f);

}  // namespace hmfnet::cli
