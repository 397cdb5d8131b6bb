#pragma once
// The work of `spectrum` and `theory` on a network already read (`simulate`'s is the service
// app/simulate_service.hpp), and the networks
// `generate` makes, without the printing: the CLI prints what these return and the Python
// module (src/python) converts it, so both give the same numbers from one code path. Each is
// collective over the MPI ranks; the JSON and the text are complete on rank 0.
#include <string>

#include "cli/command_options.hpp"
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
